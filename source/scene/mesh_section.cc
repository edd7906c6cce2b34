// Body <name>/Mesh: the generator and its dimensions.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/mesh/mesh_factory.h>
#include <glissade/scene/section_reader.h>

#include <string>

namespace glissade
{
  using namespace dealii;

  void
  MeshDescription::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry(
      "Type",
      "rectangle",
      Patterns::Selection(MeshFactory::names_as_pattern()),
      "The mesh generator. " + MeshFactory::documentation() +
        " Must be set: it is how a body's subsection is known to exist.",
      true);
    // The shapes' entries (Corner 1, Center, Inner radius, ...) belong to
    // the mesh types (MeshFactory::types()).
    MeshFactory::declare_parameters(prm);
    prm.declare_entry(
      "Subdivisions",
      "1, 1",
      Patterns::List(Patterns::Integer(1), 2, 2, ","),
      "Elements along and across: (x, y) for rectangles and squares, "
      "(circumference, thickness) for rings.");
    prm.declare_entry(
      "Grading",
      "1, 1",
      Patterns::List(Patterns::Double(0.), 2, 2, ","),
      "For each count of Subdivisions, the ratio of the last interval to "
      "the first, the sizes in geometric progression: 1, 1 for equal "
      "intervals; 20 makes them grow twentyfold from the low end of x (or "
      "xi), 0.05 shrink twentyfold towards its high end. rectangle, square "
      "and nurbs patch (each element of the file graded alike); a contact "
      "zone meshed finely without a mesh file.");
    prm.declare_entry("File",
                      "",
                      Patterns::Anything(),
                      "gmsh: path of the .msh file (relative paths are "
                      "taken from the .prm file's folder).");
    prm.declare_entry(
      "Boundary parts",
      "",
      Patterns::Anything(),
      "Parts of the mesh's named boundaries under names of their own, for "
      "a contact area or a support on part of a boundary: 'name: boundary: "
      "condition; ...', the faces of that boundary whose centre (reference "
      "coordinates x, y) makes the condition nonzero, as 'inner_top: inner: "
      "y > 0'. Parts are taken in turn, each from what the earlier ones "
      "left; a boundary left without faces loses its name.");
    prm.declare_entry(
      "Distortion",
      "0",
      Patterns::Double(0., 0.4),
      "Random displacement of interior vertices, as a fraction of the "
      "local cell size (deterministic). For patch tests.");
    prm.leave_subsection();
  }



  void
  MeshDescription::parse_parameters(SectionReader     &prm,
                                    const std::string &where)
  {
    prm.enter_subsection("Mesh");
    type = prm.get("Type");
    for (const auto &n :
         Utilities::split_string_list(prm.get("Subdivisions"), ','))
      subdivisions.push_back(Utilities::string_to_int(n));
    {
      const auto ratios = Utilities::split_string_list(prm.get("Grading"), ',');
      for (unsigned int d = 0; d < 2; ++d)
        {
          grading[d] = Utilities::string_to_double(ratios[d]);
          if (!(grading[d] >= 1e-4 && grading[d] <= 1e4))
            throw InputError(where + "/Mesh/Grading",
                             "each ratio must lie between 1e-4 and 1e4 (is " +
                               ratios[d] + ")");
        }
    }
    file       = prm.get("File");
    distortion = prm.get_double("Distortion");
    {
      const std::string entry = where + "/Mesh/Boundary parts";
      for (const auto &fields : entry_format::items(
             prm.get("Boundary parts"), 3, entry, "name: boundary: condition"))
        {
          BoundaryPart part{text::trim(fields[0]),
                            text::trim(fields[1]),
                            text::trim(fields[2])};
          if (part.name.empty() || part.boundary.empty())
            throw InputError(entry,
                             "a part needs a name and the boundary it is "
                             "taken from ('name: boundary: condition')");
          entry_format::check_expressions({part.condition}, entry);
          boundary_parts.push_back(part);
        }
    }
    shape = MeshFactory::type(type).parse_parameters(prm.handler(), where);
    prm.leave_subsection();

    MeshFactory::type(type).check(*this, where);
    {
      // A generated mesh is allocated before anything else happens: a
      // typing slip (100000, 100000) would take every byte of memory.
      double cells = 1.;
      for (const int n : subdivisions)
        {
          if (n < 1)
            throw InputError(where + "/Mesh/Subdivisions",
                             "every count must be at least 1");
          cells *= n;
        }
      if (!MeshFactory::type(type).from_file && cells > 4e6)
        throw InputError(where + "/Mesh/Subdivisions",
                         "asks for " + std::to_string(cells) +
                           " cells; more than 4 million (about 8 million "
                           "dofs and 10 GB for one body) is refused as a "
                           "probable slip");
    }
  }
} // namespace glissade
