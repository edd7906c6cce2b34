// Body <name>/Mesh: the generator and its dimensions.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
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
    prm.declare_entry("Corner 1",
                      "0, 0",
                      Patterns::Anything(),
                      "rectangle: lower left corner 'x, y'.");
    prm.declare_entry("Corner 2",
                      "1, 1",
                      Patterns::Anything(),
                      "rectangle: upper right corner 'x, y'.");
    prm.declare_entry("Center",
                      "0, 0",
                      Patterns::Anything(),
                      "square, rings: centre 'x, y'.");
    prm.declare_entry("Side",
                      "1",
                      Patterns::Double(0.),
                      "square: side length.");
    prm.declare_entry("Inner radius",
                      "0.5",
                      Patterns::Double(0.),
                      "rings: inner radius.");
    prm.declare_entry("Outer radius",
                      "1",
                      Patterns::Double(0.),
                      "rings: outer radius.");
    prm.declare_entry("Start angle",
                      "0",
                      Patterns::Double(),
                      "half ring: angle of the 'start' end, in degrees.");
    prm.declare_entry("End angle",
                      "180",
                      Patterns::Double(),
                      "half ring: angle of the 'end' end, in degrees.");
    prm.declare_entry(
      "Subdivisions",
      "1, 1",
      Patterns::List(Patterns::Integer(1), 2, 2, ","),
      "Elements along and across: (x, y) for rectangles and squares, "
      "(circumference, thickness) for rings.");
    prm.declare_entry("File",
                      "",
                      Patterns::Anything(),
                      "gmsh: path of the .msh file (relative paths are "
                      "taken from the .prm file's folder).");
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
    corner_1 =
      entry_format::coordinates(prm.get("Corner 1"), where + "/Mesh/Corner 1");
    corner_2 =
      entry_format::coordinates(prm.get("Corner 2"), where + "/Mesh/Corner 2");
    center =
      entry_format::coordinates(prm.get("Center"), where + "/Mesh/Center");
    side         = prm.get_double("Side");
    inner_radius = prm.get_double("Inner radius");
    outer_radius = prm.get_double("Outer radius");
    start_angle  = prm.get_double("Start angle");
    end_angle    = prm.get_double("End angle");
    for (const auto &n :
         Utilities::split_string_list(prm.get("Subdivisions"), ','))
      subdivisions.push_back(Utilities::string_to_int(n));
    file       = prm.get("File");
    distortion = prm.get_double("Distortion");
    prm.leave_subsection();

    if (type != "half ring" && (start_angle != 0. || end_angle != 180.))
      throw InputError(where + "/Mesh/" +
                         (start_angle != 0. ? "Start angle" : "End angle"),
                       "applies to Type = half ring only (this mesh is a " +
                         type +
                         "); to turn a body, use Boundary conditions/"
                         "Prescribed rotation");
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
