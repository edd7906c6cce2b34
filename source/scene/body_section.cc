// Body <name>: its Mesh (mesh_section.cc), Element, Material
// (material_section.cc) and Boundary conditions.

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/mesh/mesh_factory.h>
#include <glissade/scene/section_reader.h>

#include <string>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    void
    declare_boundary_conditions(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry(
          "Fixed",
          "",
          Patterns::Anything(),
          "Zero displacement: 'location: components; ...', location a "
          "boundary name or point(x, y) (a mesh vertex), components x, y or "
          "xy, or all: xy and every derivative dof of Hermite elements (the "
          "paper's fully clamped nodes; by default a fixed Hermite boundary "
          "fixes values and tangential derivatives); or n (t): zero "
          "displacement normal (tangential) to the boundary at each node, "
          "along the reference configuration's normal there (a roller on a "
          "curved boundary; q1 bodies); or symmetry: a symmetry line (a "
          "straight boundary along x or y): its normal displacement zero, "
          "and on Hermite elements its tangential displacement's normal "
          "derivative too, which a mirror image continuous in slope needs "
          "(x or y alone leaves it free: a roller). Example: 'left: xy; "
          "point(0, 0): y; outer: n; axis: symmetry'.");
        prm.declare_entry(
          "Prescribed displacement",
          "",
          Patterns::Anything(),
          "'location: components: expressions; ...', one muParser "
          "expression per component in x, y (reference position) and t. "
          "Example: 'top: y: -0.01*t'.");
        prm.declare_entry(
          "Prescribed rotation",
          "",
          Patterns::Anything(),
          "Rigid rotation of a boundary about a point: 'location: cx, cy: "
          "angle(t)' with the angle in radians. Example: 'inner: 0, 0: "
          "pi*max(t-1, 0)'.");
        prm.declare_entry(
          "Point loads",
          "",
          Patterns::Anything(),
          "Nodal forces in N, on the whole thickness (added as given): "
          "'point(x, y): fx, fy; ...' with fx, fy expressions in t.");
        prm.declare_entry(
          "Nodal loads",
          "",
          Patterns::Anything(),
          "The same force on every node of a boundary: 'boundary: fx, fy; "
          "...' with expressions in x, y (the node's reference position) "
          "and t, e.g. radial forces 'outer: -10*x/sqrt(x^2+y^2)*t, "
          "-10*y/sqrt(x^2+y^2)*t'.");
        prm.declare_entry(
          "Tractions",
          "",
          Patterns::Anything(),
          "Dead tractions, force per unit reference area (integrated along "
          "the reference boundary times the material's Thickness): "
          "'boundary: tx, ty; ...' (expressions in x, y, t).");
        prm.declare_entry(
          "Gravity",
          "",
          Patterns::Anything(),
          "An acceleration field acting on the body's mass (Material/"
          "Density), a force per unit volume rho g: 'gx, gy' (expressions "
          "in x, y, t), e.g. '0, -9.81'. Empty: none.");
        prm.declare_entry(
          "Elastic foundation",
          "0",
          Patterns::Double(0.),
          "Springs of this stiffness per unit reference volume (force per "
          "unit volume and unit displacement, times the Thickness) holding "
          "every point of the body to where it started: a force -k u. It "
          "holds a free body before contact does, so that a quasi-static "
          "scene has one answer (GetFEM's multi-body demo adds the same "
          "term as a 'mass brick'); its work is counted with the loads'. "
          "0: none.");
        prm.declare_entry(
          "Pressure",
          "",
          Patterns::Anything(),
          "Follower pressure on the deformed boundary, positive into the "
          "body, force per unit area (times the Thickness): 'boundary: p; "
          "...' (expression in x, y, t).");
      }
      prm.leave_subsection();
    }



    void
    parse_components(const std::string    &components,
                     DirichletDescription &item,
                     const std::string    &where)
    {
      const std::string c = text::trim(components);
      if (c == "symmetry" && item.kind == DirichletDescription::Kind::fixed)
        {
          item.symmetry        = true;
          item.x_component     = false;
          item.y_component     = false;
          item.all_derivatives = false;
          return;
        }
      if ((c == "n" || c == "t") &&
          item.kind == DirichletDescription::Kind::fixed)
        {
          item.direction       = c == "n" ?
                                   DirichletDescription::Direction::normal :
                                   DirichletDescription::Direction::tangential;
          item.x_component     = false;
          item.y_component     = false;
          item.all_derivatives = false;
          return;
        }
      if (c != "x" && c != "y" && c != "xy" && c != "all")
        throw InputError(where,
                         "components must be x, y, xy or all" +
                           std::string(item.kind ==
                                           DirichletDescription::Kind::fixed ?
                                         ", or n or t (normal, tangential), "
                                         "or symmetry" :
                                         "") +
                           ", not '" + c + "'");
      item.all_derivatives = (c == "all");
      item.x_component =
        item.all_derivatives || (c.find('x') != std::string::npos);
      item.y_component =
        item.all_derivatives || (c.find('y') != std::string::npos);
    }



    /** Fixed: 'location: components; ...'. */
    void
    parse_fixed_supports(SectionReader     &prm,
                         const std::string &where,
                         BodyDescription   &body)
    {
      for (const auto &f : entry_format::items(
             prm.get("Fixed"), 2, where + "Fixed", "location: components"))
        {
          DirichletDescription item;
          item.kind     = DirichletDescription::Kind::fixed;
          item.location = f[0];
          item.entry    = where + "Fixed";
          parse_components(f[1], item, item.entry);
          body.dirichlet.push_back(item);
        }
    }



    /**
     * Prescribed displacement: 'location: components: expressions; ...',
     * one expression per component.
     */
    void
    parse_prescribed_displacements(SectionReader     &prm,
                                   const std::string &where,
                                   BodyDescription   &body)
    {
      for (const auto &f :
           entry_format::items(prm.get("Prescribed displacement"),
                               3,
                               where + "Prescribed displacement",
                               "location: components: expressions"))
        {
          DirichletDescription item;
          item.kind     = DirichletDescription::Kind::displacement;
          item.location = f[0];
          item.entry    = where + "Prescribed displacement";
          parse_components(f[1], item, item.entry);
          item.expressions = text::split_top_level(f[2], ',');
          const unsigned int n_expected =
            (item.x_component ? 1 : 0) + (item.y_component ? 1 : 0);
          if (item.expressions.size() != n_expected)
            throw InputError(item.entry,
                             "'" + f[2] +
                               "' must give one expression per "
                               "component");
          entry_format::check_expressions(item.expressions, item.entry);
          body.dirichlet.push_back(item);
        }
    }



    /** Prescribed rotation: 'location: cx, cy: angle; ...'. */
    void
    parse_prescribed_rotations(SectionReader     &prm,
                               const std::string &where,
                               BodyDescription   &body)
    {
      for (const auto &f : entry_format::items(prm.get("Prescribed rotation"),
                                               3,
                                               where + "Prescribed rotation",
                                               "location: cx, cy: angle"))
        {
          DirichletDescription item;
          item.kind             = DirichletDescription::Kind::rotation;
          item.location         = f[0];
          item.entry            = where + "Prescribed rotation";
          item.rotation_center  = entry_format::coordinates(f[1], item.entry);
          item.angle_expression = f[2];
          entry_format::check_expressions({f[2]}, item.entry);
          body.dirichlet.push_back(item);
        }
    }



    /**
     * Two Dirichlet data on one location and component contradict each
     * other (which wins would depend on the order of application): the
     * second is refused.
     */
    void
    check_one_datum_per_component(const BodyDescription &body)
    {
      // A rotation, a normal or a tangential support involves both
      // Cartesian components.
      const auto both_x = [](const DirichletDescription &d) {
        return d.kind == DirichletDescription::Kind::rotation ||
               d.direction != DirichletDescription::Direction::cartesian ||
               d.x_component;
      };
      const auto both_y = [](const DirichletDescription &d) {
        return d.kind == DirichletDescription::Kind::rotation ||
               d.direction != DirichletDescription::Direction::cartesian ||
               d.y_component;
      };
      for (unsigned int i = 0; i < body.dirichlet.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            const DirichletDescription &a = body.dirichlet[j],
                                       &b = body.dirichlet[i];
            if (text::trim(a.location) == text::trim(b.location) &&
                ((both_x(a) && both_x(b)) || (both_y(a) && both_y(b))))
              throw InputError(b.entry,
                               "'" + text::trim(b.location) +
                                 "' is already constrained in the same "
                                 "component by " +
                                 a.entry +
                                 ": give each component of a boundary one "
                                 "Dirichlet datum");
          }
    }



    /**
     * One entry of loads ('location: expressions; ...', n_expressions of
     * them): point loads act on points, the others on boundaries.
     */
    void
    parse_neumann_entry(SectionReader                 &prm,
                        const std::string             &where,
                        const std::string             &entry,
                        const NeumannDescription::Kind kind,
                        const unsigned int             n_expressions,
                        const std::string             &syntax,
                        BodyDescription               &body)
    {
      for (const auto &f :
           entry_format::items(prm.get(entry), 2, where + entry, syntax))
        {
          NeumannDescription item;
          item.kind        = kind;
          item.location    = f[0];
          item.entry       = where + entry;
          item.expressions = text::split_top_level(f[1], ',');
          if (item.expressions.size() != n_expressions)
            throw InputError(item.entry,
                             "'" + f[1] + "': expected '" + syntax + "'");
          entry_format::check_expressions(item.expressions, item.entry);
          double     x, y;
          const bool is_point = text::parse_point_location(item.location, x, y);
          if (kind == NeumannDescription::Kind::point_load && !is_point)
            throw InputError(item.entry,
                             "point loads act on 'point(x, y)', not on '" +
                               item.location + "'");
          if (kind != NeumannDescription::Kind::point_load && is_point)
            throw InputError(item.entry,
                             "tractions and pressures act on a boundary, "
                             "not on a point");
          body.neumann.push_back(item);
        }
    }



    void
    parse_boundary_conditions(SectionReader     &prm,
                              BodyDescription   &body,
                              const std::string &where_body)
    {
      prm.enter_subsection("Boundary conditions");
      const std::string where = where_body + "/Boundary conditions/";

      parse_fixed_supports(prm, where, body);
      parse_prescribed_displacements(prm, where, body);
      parse_prescribed_rotations(prm, where, body);
      check_one_datum_per_component(body);

      parse_neumann_entry(prm,
                          where,
                          "Point loads",
                          NeumannDescription::Kind::point_load,
                          2,
                          "point(x, y): fx, fy",
                          body);
      parse_neumann_entry(prm,
                          where,
                          "Nodal loads",
                          NeumannDescription::Kind::nodal_loads,
                          2,
                          "boundary: fx, fy",
                          body);
      parse_neumann_entry(prm,
                          where,
                          "Tractions",
                          NeumannDescription::Kind::traction,
                          2,
                          "boundary: tx, ty",
                          body);
      parse_neumann_entry(prm,
                          where,
                          "Pressure",
                          NeumannDescription::Kind::pressure,
                          1,
                          "boundary: p",
                          body);
      if (const std::string g = text::trim(prm.get("Gravity")); !g.empty())
        {
          body.gravity = text::split_top_level(g, ',');
          if (body.gravity.size() != 2)
            throw InputError(where + "Gravity",
                             "'" + g + "': expected 'gx, gy'");
          entry_format::check_expressions(body.gravity, where + "Gravity");
        }
      body.elastic_foundation = prm.get_double("Elastic foundation");
      prm.leave_subsection();
    }
  } // namespace



  void
  BodyDescription::declare_parameters(ParameterHandler               &prm,
                                      const std::vector<std::string> &regions)
  {
    MeshDescription::declare_parameters(prm);

    prm.enter_subsection("Element");
    prm.declare_entry(
      "Space",
      "q1",
      Patterns::Selection(ElementSpaceRegistry::names_as_pattern()),
      "The element space by name: " + ElementSpaceRegistry::documentation());
    prm.declare_entry("Degree",
                      "2",
                      Patterns::Integer(2, 4),
                      "nurbs: the polynomial degree of the patch in each "
                      "direction (2 to 4; the Lagrange and serendipity "
                      "spaces are named by theirs).");
    prm.leave_subsection();

    MaterialDescription::declare_parameters(prm, regions);
    declare_boundary_conditions(prm);
    TurningFrameDescription::declare_parameters(prm);
    prm.declare_entry("Initial velocity",
                      "0, 0",
                      Patterns::Anything(),
                      "The velocity at t = 0 of a dynamic scheme (Time "
                      "integration): 'vx, vy', expressions in x, y (the "
                      "reference position), e.g. '0, -1' or a rotation "
                      "'-2*y, 2*x'.");
  }



  void
  BodyDescription::parse_parameters(SectionReader &prm)
  {
    const std::string where = prm.file() + ": Body " + name;
    // The mesh, the material and the boundary conditions are checked
    // apart: a mistake in one does not hide those of the others.
    prm.check([&]() { mesh.parse_parameters(prm, where); });
    prm.enter_subsection("Element");
    element_space  = prm.get("Space");
    element_degree = prm.get_integer("Degree");
    if (element_degree != 2 && element_space != "nurbs")
      prm.check([&]() {
        throw InputError(where + "/Element/Degree",
                         "applies to Space = nurbs only (this body's space, " +
                           element_space + ", is named by its degree)");
      });
    prm.leave_subsection();
    prm.check([&]() { material.parse_parameters(prm, where); });
    prm.check([&]() { parse_boundary_conditions(prm, *this, where); });
    prm.check([&]() { turning_frame.parse_parameters(prm, where); });
    prm.check([&]() {
      initial_velocity =
        text::split_top_level(text::trim(prm.get("Initial velocity")), ',');
      if (initial_velocity.size() != 2)
        throw InputError(where + "/Initial velocity",
                         "'" + prm.get("Initial velocity") +
                           "': expected 'vx, vy'");
      entry_format::check_expressions(initial_velocity,
                                      where + "/Initial velocity");
    });
    if (MeshFactory::type(mesh.type).from_file)
      mesh.file = text::path_beside(prm.file(), mesh.file);
  }
} // namespace glissade
