#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/scene/scene_reader.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace glissade
{
  namespace
  {
    /**
     * deal.II's exception text carries the library's source location and a
     * stack trace; the user needs only the "Additional information" part,
     * which names the line and the entry of the .prm file.
     */
    std::string
    essential_message(const std::exception &e)
    {
      std::string       message = e.what();
      const std::string marker  = "Additional information:";
      const auto        begin   = message.find(marker);
      if (begin != std::string::npos)
        message = message.substr(begin + marker.size());
      const auto end = message.find("Stacktrace:");
      if (end != std::string::npos)
        message = message.substr(0, end);
      std::string compact;
      bool        space = false;
      for (const char c : message)
        if (c == '\n' || c == ' ' || c == '\t')
          space = true;
        else
          {
            if (space && !compact.empty())
              compact += ' ';
            compact += c;
            space = false;
          }
      return compact;
    }

    /** Compiles an expression once so that typos are caught while reading. */
    void
    check_expressions(const std::vector<std::string> &expressions,
                      const std::string              &where)
    {
      try
        {
          FunctionParser<2> function(expressions.size());
          function.initialize("x,y,t",
                              expressions,
                              {{"pi", numbers::PI}},
                              true);
          Vector<double> values(expressions.size());
          function.vector_value(Point<2>(), values);
        }
      catch (const std::exception &e)
        {
          std::string list;
          for (const auto &s : expressions)
            list += (list.empty() ? "" : ", ") + s;
          throw InputError(where,
                           "cannot evaluate the expression(s) '" + list +
                             "' (variables are x, y, t; constant pi): " +
                             essential_message(e));
        }
    }

    Point<2>
    parse_coordinates(const std::string &text_value, const std::string &where)
    {
      const auto parts = text::split_top_level(text_value, ',');
      if (parts.size() != 2)
        throw InputError(where,
                         "expected two coordinates 'x, y', got '" +
                           text_value + "'");
      try
        {
          return Point<2>(std::stod(parts[0]), std::stod(parts[1]));
        }
      catch (...)
        {
          throw InputError(where,
                           "cannot read coordinates '" + text_value + "'");
        }
    }

    void
    parse_components(const std::string    &components,
                     DirichletDescription &item,
                     const std::string    &where)
    {
      const std::string c = text::trim(components);
      if (c != "x" && c != "y" && c != "xy" && c != "all")
        throw InputError(where,
                         "components must be x, y, xy or all, not '" + c +
                           "'");
      item.all_derivatives = (c == "all");
      item.x_component = item.all_derivatives || (c.find('x') != std::string::npos);
      item.y_component = item.all_derivatives || (c.find('y') != std::string::npos);
    }

    /** Splits "a: b: c; d: e" into items and fields, checking the count. */
    std::vector<std::vector<std::string>>
    split_items(const std::string &value,
                const unsigned int n_fields,
                const std::string &where,
                const std::string &syntax)
    {
      std::vector<std::vector<std::string>> items;
      for (const auto &item : text::split_top_level(value, ';'))
        {
          if (item.empty())
            continue;
          const auto fields = text::split_top_level(item, ':');
          if (fields.size() != n_fields)
            throw InputError(where,
                             "cannot read '" + item + "': expected '" +
                               syntax + "'");
          items.push_back(fields);
        }
      return items;
    }

    void
    declare_body(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      {
        prm.declare_entry(
          "Type",
          "rectangle",
          Patterns::Selection("rectangle|square|half ring|ring|gmsh"),
          "The mesh generator. rectangle: from Corner 1 to Corner 2, "
          "boundaries left, right, bottom, top. square: centred at Center with "
          "side Side, same boundary names. half ring / ring: centred at "
          "Center between Inner radius and Outer radius, boundaries inner, "
          "outer and (half ring) start, end at the Start/End angle. gmsh: "
          "the .msh file File, whose named physical lines become boundaries. "
          "Must be set: it is how a body's subsection is known to exist.",
          true);
        prm.declare_entry("Corner 1", "0, 0", Patterns::Anything(),
                          "rectangle: lower left corner 'x, y'.");
        prm.declare_entry("Corner 2", "1, 1", Patterns::Anything(),
                          "rectangle: upper right corner 'x, y'.");
        prm.declare_entry("Center", "0, 0", Patterns::Anything(),
                          "square, rings: centre 'x, y'.");
        prm.declare_entry("Side", "1", Patterns::Double(0.),
                          "square: side length.");
        prm.declare_entry("Inner radius", "0.5", Patterns::Double(0.),
                          "rings: inner radius.");
        prm.declare_entry("Outer radius", "1", Patterns::Double(0.),
                          "rings: outer radius.");
        prm.declare_entry("Start angle", "0", Patterns::Double(),
                          "half ring: angle of the 'start' end, in degrees.");
        prm.declare_entry("End angle", "180", Patterns::Double(),
                          "half ring: angle of the 'end' end, in degrees.");
        prm.declare_entry(
          "Subdivisions",
          "1, 1",
          Patterns::List(Patterns::Integer(1), 2, 2, ","),
          "Elements along and across: (x, y) for rectangles and squares, "
          "(circumference, thickness) for rings.");
        prm.declare_entry("File", "", Patterns::Anything(),
                          "gmsh: path of the .msh file (relative paths are "
                          "taken from the .prm file's folder).");
        prm.declare_entry(
          "Distortion",
          "0",
          Patterns::Double(0., 0.4),
          "Random displacement of interior vertices, as a fraction of the "
          "local cell size (deterministic). For patch tests.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Element");
      prm.declare_entry("Space",
                        "q1",
                        Patterns::Selection(
                          ElementSpaceRegistry::names_as_pattern()),
                        "The element space by name: " +
                          ElementSpaceRegistry::documentation());
      prm.leave_subsection();

      prm.enter_subsection("Material");
      {
        prm.declare_entry("Law",
                          "neo-Hookean",
                          Patterns::Selection(
                            "neo-Hookean|Saint Venant-Kirchhoff"),
                          "Hyperelastic law (total Lagrangian).");
        prm.declare_entry("Young modulus", "1", Patterns::Double(),
                          "E in Pa, > 0.");
        prm.declare_entry("Poisson ratio", "0.3", Patterns::Double(),
                          "nu, in (-1, 0.5).");
        prm.declare_entry("Hypothesis",
                          "plane strain",
                          Patterns::Selection("plane strain|plane stress"),
                          "Planar hypothesis.");
        prm.declare_entry("Thickness", "1", Patterns::Double(),
                          "Out-of-plane thickness (m), > 0: forces are per "
                          "this thickness.");
      }
      prm.leave_subsection();

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
          "fixes values and tangential derivatives). Example: 'left: xy; "
          "point(0, 0): y'.");
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
          "Nodal forces (N per thickness): 'point(x, y): fx, fy; ...' with "
          "fx, fy expressions in t.");
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
          "Dead tractions per unit reference length: 'boundary: tx, ty; ...' "
          "(expressions in x, y, t).");
        prm.declare_entry(
          "Pressure",
          "",
          Patterns::Anything(),
          "Follower pressure on the deformed boundary, positive into the "
          "body: 'boundary: p; ...' (expression in x, y, t).");
      }
      prm.leave_subsection();
    }

    void
    declare_contact(ParameterHandler &prm)
    {
      prm.declare_entry("Slave body", "", Patterns::Anything(),
                        "The body whose boundary nodes are the slave nodes.");
      prm.declare_entry("Slave boundary", "", Patterns::Anything(),
                        "The declared contact area on the slave body.");
      prm.declare_entry("Master body", "rigid", Patterns::Anything(),
                        "The body that carries the master surface, or "
                        "'rigid' for an analytic obstacle (subsection "
                        "Obstacle).");
      prm.declare_entry("Master boundary", "", Patterns::Anything(),
                        "The declared contact area on the master body.");
      prm.declare_entry(
        "Surface",
        "faceted",
        Patterns::Selection("faceted|bspline|hermite"),
        "Representation of the master surface: faceted (the element edges, "
        "the paper's Q4), bspline (cubic uniform interpolating B-spline "
        "through the master nodes, closed if the boundary is), hermite (the "
        "C1 edges of a Hermite master body).");
      prm.declare_entry(
        "Force transfer",
        "segment",
        Patterns::Selection("segment|spline"),
        "How a B-spline master receives the reaction: segment hands it to "
        "the two nodes of the underlying straight segment (the paper); "
        "spline uses the spline's own weights (consistent, symmetric W).");
      prm.declare_entry("Alert distance", "0", Patterns::Double(0.),
                        "Slave nodes farther than this from the master at the "
                        "start of an increment are left out of the condensed "
                        "problem.");
      prm.declare_entry(
        "Frame update",
        "iteration",
        Patterns::Selection("iteration|increment"),
        "iteration: re-project the active nodes at every Newton iteration "
        "(frame, gap, weights). increment: project them at the start of the "
        "increment only and follow the gap linearly within it. The frame's "
        "change is not part of the tangent, so with a very compliant master "
        "surface (Hermite edges, whose tangents turn under a point force) "
        "re-projecting can make the iteration diverge; freezing the frame "
        "over small increments converges, at an error of the order of the "
        "increment.");
      prm.declare_entry("Friction coefficient", "0", Patterns::Double(0.),
                        "Coulomb's mu (0: frictionless).");
      prm.declare_entry("Beta", "1", Patterns::Double(0.),
                        "Bi-potential parameter in (0, 2): rho_k = beta / "
                        "W_kk(nn).");
      prm.declare_entry("Tolerance", "1e-10", Patterns::Double(0.),
                        "Relative tolerance of the local solver.");
      prm.declare_entry("Maximum sweeps", "10000", Patterns::Integer(1),
                        "Gauss-Seidel sweeps of the local solver.");
      prm.enter_subsection("Obstacle");
      prm.declare_entry("Type", "line", Patterns::Selection("line|disk|hole"),
                        "line: the half-plane behind a line; disk: a solid "
                        "disk; hole: the outside of a circular hole.");
      prm.declare_entry("Point", "0, 0", Patterns::Anything(),
                        "line: a point on it; disk, hole: the centre.");
      prm.declare_entry("Normal", "0, 1", Patterns::Anything(),
                        "line: the normal pointing out of the obstacle.");
      prm.declare_entry("Radius", "1", Patterns::Double(0.), "disk, hole.");
      prm.declare_entry("Motion", "0, 0", Patterns::Anything(),
                        "Translation of the obstacle as expressions of t.");
      prm.leave_subsection();
    }

    ContactDescription
    parse_contact(ParameterHandler               &prm,
                  const std::string              &name,
                  const std::vector<std::string> &body_names,
                  const std::string              &source)
    {
      ContactDescription c;
      c.name  = name;
      c.entry = source + ": Contact " + name;
      c.slave_body      = prm.get("Slave body");
      c.slave_boundary  = prm.get("Slave boundary");
      c.master_body     = prm.get("Master body");
      c.master_boundary = prm.get("Master boundary");
      c.surface         = prm.get("Surface");
      c.force_transfer  = prm.get("Force transfer");
      c.alert_distance  = prm.get_double("Alert distance");
      c.frame_update    = prm.get("Frame update");
      c.friction        = prm.get_double("Friction coefficient");
      c.beta            = prm.get_double("Beta");
      c.tolerance       = prm.get_double("Tolerance");
      c.max_sweeps      = prm.get_integer("Maximum sweeps");
      prm.enter_subsection("Obstacle");
      c.obstacle       = prm.get("Type");
      c.obstacle_point = parse_coordinates(prm.get("Point"),
                                           c.entry + "/Obstacle/Point");
      const Point<2> normal =
        parse_coordinates(prm.get("Normal"), c.entry + "/Obstacle/Normal");
      c.obstacle_normal = normal;
      c.obstacle_radius = prm.get_double("Radius");
      c.obstacle_motion = text::split_top_level(prm.get("Motion"), ',');
      prm.leave_subsection();

      const auto known = [&](const std::string &b) {
        return std::find(body_names.begin(), body_names.end(), b) !=
               body_names.end();
      };
      if (!known(c.slave_body))
        throw InputError(c.entry + "/Slave body",
                         "there is no body '" + c.slave_body + "'");
      if (c.master_body != "rigid" && !known(c.master_body))
        throw InputError(c.entry + "/Master body",
                         "there is no body '" + c.master_body +
                           "' (or use 'rigid')");
      if (c.master_body == c.slave_body)
        throw InputError(c.entry + "/Master body",
                         "a body cannot be its own master");
      if (c.slave_boundary.empty())
        throw InputError(c.entry + "/Slave boundary", "must be given");
      if (c.master_body != "rigid" && c.master_boundary.empty())
        throw InputError(c.entry + "/Master boundary", "must be given");
      if (!(c.beta > 0. && c.beta < 2.))
        throw InputError(c.entry + "/Beta", "must lie in (0, 2)");
      if (c.obstacle_motion.size() != 2)
        throw InputError(c.entry + "/Obstacle/Motion",
                         "expected two expressions 'x(t), y(t)'");
      check_expressions(c.obstacle_motion, c.entry + "/Obstacle/Motion");
      if (c.master_body == "rigid" && c.obstacle == "line" &&
          normal.norm() == 0.)
        throw InputError(c.entry + "/Obstacle/Normal", "must not be zero");
      return c;
    }

    MeshDescription
    parse_mesh(ParameterHandler &prm, const std::string &where)
    {
      MeshDescription mesh;
      prm.enter_subsection("Mesh");
      mesh.type         = prm.get("Type");
      mesh.corner_1     = parse_coordinates(prm.get("Corner 1"),
                                        where + "/Mesh/Corner 1");
      mesh.corner_2     = parse_coordinates(prm.get("Corner 2"),
                                        where + "/Mesh/Corner 2");
      mesh.center       = parse_coordinates(prm.get("Center"),
                                      where + "/Mesh/Center");
      mesh.side         = prm.get_double("Side");
      mesh.inner_radius = prm.get_double("Inner radius");
      mesh.outer_radius = prm.get_double("Outer radius");
      mesh.start_angle  = prm.get_double("Start angle");
      mesh.end_angle    = prm.get_double("End angle");
      for (const auto &n :
           Utilities::split_string_list(prm.get("Subdivisions"), ','))
        mesh.subdivisions.push_back(Utilities::string_to_int(n));
      mesh.file       = prm.get("File");
      mesh.distortion = prm.get_double("Distortion");
      prm.leave_subsection();

      if (mesh.type == "rectangle" && !(mesh.corner_2[0] > mesh.corner_1[0] &&
                                        mesh.corner_2[1] > mesh.corner_1[1]))
        throw InputError(where + "/Mesh/Corner 2",
                         "must lie above and to the right of Corner 1");
      if ((mesh.type == "ring" || mesh.type == "half ring") &&
          !(mesh.outer_radius > mesh.inner_radius && mesh.inner_radius > 0))
        throw InputError(where + "/Mesh/Outer radius",
                         "rings need 0 < Inner radius < Outer radius");
      if (mesh.type == "half ring" && !(mesh.end_angle > mesh.start_angle &&
                                        mesh.end_angle - mesh.start_angle <
                                          360.))
        throw InputError(where + "/Mesh/End angle",
                         "must be larger than Start angle, by less than 360");
      if (mesh.type == "ring" && mesh.subdivisions[0] < 3)
        throw InputError(where + "/Mesh/Subdivisions",
                         "a ring needs at least 3 elements around");
      if (mesh.type == "gmsh" && mesh.file.empty())
        throw InputError(where + "/Mesh/File", "gmsh meshes need a File");
      return mesh;
    }

    MaterialDescription
    parse_material(ParameterHandler &prm, const std::string &where)
    {
      MaterialDescription material;
      prm.enter_subsection("Material");
      material.law           = prm.get("Law");
      material.young_modulus = prm.get_double("Young modulus");
      material.poisson_ratio = prm.get_double("Poisson ratio");
      material.hypothesis    = prm.get("Hypothesis");
      material.thickness     = prm.get_double("Thickness");
      prm.leave_subsection();
      if (!(material.young_modulus > 0.))
        throw InputError(where + "/Material/Young modulus", "must be > 0");
      if (!(material.poisson_ratio > -1. && material.poisson_ratio < 0.5))
        throw InputError(where + "/Material/Poisson ratio",
                         "must lie in (-1, 0.5)");
      if (!(material.thickness > 0.))
        throw InputError(where + "/Material/Thickness", "must be > 0");
      return material;
    }

    void
    parse_boundary_conditions(ParameterHandler  &prm,
                              BodyDescription   &body,
                              const std::string &where_body)
    {
      prm.enter_subsection("Boundary conditions");
      const std::string where = where_body + "/Boundary conditions/";

      for (const auto &f :
           split_items(prm.get("Fixed"), 2, where + "Fixed",
                       "location: components"))
        {
          DirichletDescription item;
          item.kind     = DirichletDescription::Kind::fixed;
          item.location = f[0];
          item.entry    = where + "Fixed";
          parse_components(f[1], item, item.entry);
          body.dirichlet.push_back(item);
        }

      for (const auto &f :
           split_items(prm.get("Prescribed displacement"), 3,
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
                             "'" + f[2] + "' must give one expression per "
                             "component");
          check_expressions(item.expressions, item.entry);
          body.dirichlet.push_back(item);
        }

      for (const auto &f :
           split_items(prm.get("Prescribed rotation"), 3,
                       where + "Prescribed rotation",
                       "location: cx, cy: angle"))
        {
          DirichletDescription item;
          item.kind             = DirichletDescription::Kind::rotation;
          item.location         = f[0];
          item.entry            = where + "Prescribed rotation";
          item.rotation_center  = parse_coordinates(f[1], item.entry);
          item.angle_expression = f[2];
          check_expressions({f[2]}, item.entry);
          body.dirichlet.push_back(item);
        }

      const auto add_neumann = [&](const std::string              &entry,
                                   const NeumannDescription::Kind kind,
                                   const unsigned int n_expressions,
                                   const std::string &syntax) {
        for (const auto &f :
             split_items(prm.get(entry), 2, where + entry, syntax))
          {
            NeumannDescription item;
            item.kind        = kind;
            item.location    = f[0];
            item.entry       = where + entry;
            item.expressions = text::split_top_level(f[1], ',');
            if (item.expressions.size() != n_expressions)
              throw InputError(item.entry,
                               "'" + f[1] + "': expected '" + syntax + "'");
            check_expressions(item.expressions, item.entry);
            double x, y;
            const bool is_point =
              text::parse_point_location(item.location, x, y);
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
      };
      add_neumann("Point loads",
                  NeumannDescription::Kind::point_load,
                  2,
                  "point(x, y): fx, fy");
      add_neumann("Nodal loads",
                  NeumannDescription::Kind::nodal_loads,
                  2,
                  "boundary: fx, fy");
      add_neumann("Tractions",
                  NeumannDescription::Kind::traction,
                  2,
                  "boundary: tx, ty");
      add_neumann("Pressure",
                  NeumannDescription::Kind::pressure,
                  1,
                  "boundary: p");
      prm.leave_subsection();
    }

    /** Applies one "A/B/Entry=value" override. */
    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      if (equal == std::string::npos)
        throw InputError("--set " + assignment,
                         "expected 'Subsection/Entry=value'");
      const auto path =
        Utilities::split_string_list(assignment.substr(0, equal), '/');
      const std::string value = text::trim(assignment.substr(equal + 1));
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.enter_subsection(path[i]);
      try
        {
          prm.set(path.back(), value);
        }
      catch (const std::exception &e)
        {
          throw InputError("--set " + assignment, essential_message(e));
        }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }

    std::vector<std::string>
    read_body_names(const std::string &text_value, const std::string &source)
    {
      const auto names = Utilities::split_string_list(text_value, ',');
      if (names.empty())
        throw InputError(source + ": Scene/Bodies",
                         "the scene needs at least one body");
      for (unsigned int i = 0; i < names.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          if (names[i] == names[j])
            throw InputError(source + ": Scene/Bodies",
                             "body '" + names[i] + "' is named twice");
      return names;
    }

  } // namespace



  void
  SceneReader::declare_parameters(ParameterHandler               &prm,
                                  const std::vector<std::string> &body_names,
                                  const std::vector<std::string> &contact_names)
  {
    prm.declare_entry("Study",
                      "simulation",
                      Patterns::Selection("simulation|geometric|case1|case2|case3"),
                      "simulation: run the scene below. geometric: the "
                      "geometric study of the paper's section 3.3 (see "
                      "prm/geometric_study.prm); case1, case2: the beam on a "
                      "half ring and the square between two half rings "
                      "(sections 4.1, 4.2; prm/case1_study.prm, "
                      "prm/case2_study.prm); case3: the concentric rings "
                      "of section 4.3 in several variants (see "
                      "prm/case3_default.prm). A study's own entries replace "
                      "these.");
    prm.enter_subsection("Scene");
    prm.declare_entry("Bodies",
                      "body",
                      Patterns::Anything(),
                      "Comma-separated names of the bodies; each has a "
                      "subsection 'Body <name>'.");
    prm.declare_entry("Contact pairs",
                      "",
                      Patterns::Anything(),
                      "Comma-separated names of the contact pairs; each has a "
                      "subsection 'Contact <name>'.");
    prm.leave_subsection();

    for (const auto &name : contact_names)
      {
        prm.enter_subsection("Contact " + name);
        declare_contact(prm);
        prm.leave_subsection();
      }

    for (const auto &name : body_names)
      {
        prm.enter_subsection("Body " + name);
        declare_body(prm);
        prm.leave_subsection();
      }

    prm.enter_subsection("Load program");
    prm.declare_entry("Stage end times",
                      "1",
                      Patterns::List(Patterns::Double(), 1),
                      "Time t at the end of each stage (increasing). Loads "
                      "and motions are expressions in t.");
    prm.declare_entry("Stage increments",
                      "1",
                      Patterns::List(Patterns::Integer(1), 1),
                      "Number of equal increments of each stage.");
    prm.declare_entry("Maximum cut-back depth",
                      "6",
                      Patterns::Integer(0, 30),
                      "How many times an increment that does not converge "
                      "may be bisected before the run stops.");
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations", "25", Patterns::Integer(1),
                      "Newton iterations per increment before a cut-back.");
    prm.declare_entry("Residual tolerance", "1e-9", Patterns::Double(0.),
                      "Converged when |R| <= tol * max(|F_int|, |F_ext|) on "
                      "the free dofs...");
    prm.declare_entry("Displacement tolerance", "1e-9", Patterns::Double(0.),
                      "...and |du| <= tol * max(|u|, size of the body).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Patterns::Anything(),
                      "Where VTU/PVD, history.csv and summary.txt go "
                      "(relative paths: from the working directory).");
    prm.declare_entry("VTU interval", "1", Patterns::Integer(0),
                      "Write a VTU every this many increments (0: only the "
                      "final state).");
    prm.declare_entry("Contact table interval", "0", Patterns::Integer(0),
                      "Write contact-<pair>-<increment>.csv (every slave "
                      "node's gap, reaction, status) every this many "
                      "increments; 0: with the VTU files.");
    prm.declare_entry(
      "History",
      "",
      Patterns::Anything(),
      "Columns of history.csv, ';'-separated: displacement(body, point(x, "
      "y)), max_displacement(body), reaction(body, boundary), "
      "contact_force(pair) (total force on the slave and active nodes), "
      "contact_node(pair, point(x, y)) (r_n, r_t, |f|, gap of the slave node "
      "at that reference position).");
    prm.declare_entry("Progress", "true", Patterns::Bool(),
                      "Print one line per increment.");
    prm.leave_subsection();
  }



  SceneDescription
  SceneReader::parse_parameters(ParameterHandler               &prm,
                                const std::vector<std::string> &body_names,
                                const std::vector<std::string> &contact_names,
                                const std::string              &source)
  {
    SceneDescription scene;
    scene.source = source;
    for (const auto &name : contact_names)
      {
        prm.enter_subsection("Contact " + name);
        scene.contacts.push_back(parse_contact(prm, name, body_names, source));
        prm.leave_subsection();
      }
    for (const auto &name : body_names)
      {
        const std::string where = source + ": Body " + name;
        prm.enter_subsection("Body " + name);
        BodyDescription body;
        body.name     = name;
        body.mesh     = parse_mesh(prm, where);
        prm.enter_subsection("Element");
        body.element_space = prm.get("Space");
        prm.leave_subsection();
        body.material = parse_material(prm, where);
        parse_boundary_conditions(prm, body, where);
        prm.leave_subsection();
        if (body.mesh.type == "gmsh" && !body.mesh.file.empty() &&
            body.mesh.file[0] != '/')
          {
            const auto slash = source.find_last_of('/');
            if (slash != std::string::npos)
              body.mesh.file = source.substr(0, slash + 1) + body.mesh.file;
          }
        scene.bodies.push_back(body);
      }

    prm.enter_subsection("Load program");
    scene.load_program.stage_end_times.clear();
    for (const auto &t :
         Utilities::split_string_list(prm.get("Stage end times"), ','))
      scene.load_program.stage_end_times.push_back(std::stod(t));
    scene.load_program.stage_increments.clear();
    for (const auto &n :
         Utilities::split_string_list(prm.get("Stage increments"), ','))
      scene.load_program.stage_increments.push_back(
        Utilities::string_to_int(n));
    scene.load_program.max_cut_back_depth =
      prm.get_integer("Maximum cut-back depth");
    prm.leave_subsection();
    const auto &times = scene.load_program.stage_end_times;
    if (times.size() != scene.load_program.stage_increments.size())
      throw InputError(source + ": Load program/Stage increments",
                       "needs one value per stage end time");
    for (unsigned int i = 0; i < times.size(); ++i)
      if (!(times[i] > (i == 0 ? 0. : times[i - 1])))
        throw InputError(source + ": Load program/Stage end times",
                         "must be positive and increasing");

    prm.enter_subsection("Newton");
    scene.newton.max_iterations = prm.get_integer("Maximum iterations");
    scene.newton.residual_tolerance = prm.get_double("Residual tolerance");
    scene.newton.displacement_tolerance =
      prm.get_double("Displacement tolerance");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    scene.output.directory    = prm.get("Directory");
    scene.output.vtu_interval = prm.get_integer("VTU interval");
    scene.output.contact_table_interval =
      prm.get_integer("Contact table interval");
    for (const auto &item : text::split_top_level(prm.get("History"), ';'))
      if (!item.empty())
        scene.output.history.push_back(item);
    scene.output.progress = prm.get_bool("Progress");
    prm.leave_subsection();
    return scene;
  }



  SceneDescription
  SceneReader::read_string(const std::string              &text_value,
                           const std::string              &source,
                           const std::vector<std::string> &overrides)
  {
    // Pass 1: the body and contact pair names only.
    std::vector<std::string> body_names, contact_names;
    {
      ParameterHandler prm;
      prm.enter_subsection("Scene");
      prm.declare_entry("Bodies", "body", Patterns::Anything());
      prm.declare_entry("Contact pairs", "", Patterns::Anything());
      prm.leave_subsection();
      try
        {
          prm.parse_input_from_string(text_value, "", true);
          for (const auto &o : overrides)
            if (o.rfind("Scene/", 0) == 0)
              apply_override(prm, o);
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::exception &e)
        {
          throw InputError(source, essential_message(e));
        }
      prm.enter_subsection("Scene");
      body_names = read_body_names(prm.get("Bodies"), source);
      contact_names =
        Utilities::split_string_list(prm.get("Contact pairs"), ',');
      prm.leave_subsection();
    }

    // Pass 2: everything, strictly: an undeclared entry is an error.
    ParameterHandler prm;
    declare_parameters(prm, body_names, contact_names);
    try
      {
        prm.parse_input_from_string(text_value, "", false);
        for (const auto &o : overrides)
          apply_override(prm, o);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw InputError(source, essential_message(e));
      }
    // ParameterHandler reports paths with special characters mangled as
    // "_XX" (hex); undo that before looking for the body's name.
    const auto demangle = [](const std::string &mangled) {
      std::string plain;
      for (unsigned int i = 0; i < mangled.size(); ++i)
        if (mangled[i] == '_' && i + 2 < mangled.size() &&
            std::isxdigit(mangled[i + 1]) && std::isxdigit(mangled[i + 2]))
          {
            plain += static_cast<char>(
              std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          plain += mangled[i];
      return plain;
    };
    for (const auto &name : body_names)
      for (const auto &missing : prm.get_entries_wrongly_not_set())
        if (demangle(missing).find("Body " + name) != std::string::npos)
          throw InputError(source + ": Body " + name + "/Mesh/Type",
                           "is not set: every body of Scene/Bodies needs a "
                           "'subsection Body " +
                             name + "' with at least its Mesh/Type");
    return parse_parameters(prm, body_names, contact_names, source);
  }



  SceneDescription
  SceneReader::read_file(const std::string              &filename,
                         const std::vector<std::string> &overrides)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(filename, "cannot open the parameter file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return read_string(buffer.str(), filename, overrides);
  }



  void
  SceneReader::parse_study(ParameterHandler               &prm,
                           const std::string              &filename,
                           const std::vector<std::string> &overrides)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(filename, "cannot open the parameter file");
    try
      {
        prm.parse_input(in, filename);
        for (const auto &o : overrides)
          apply_override(prm, o);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw InputError(filename, essential_message(e));
      }
  }



  std::string
  SceneReader::study_type(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(filename, "cannot open the parameter file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    ParameterHandler prm;
    prm.declare_entry("Study", "simulation", Patterns::Anything());
    try
      {
        prm.parse_input_from_string(buffer.str(), "", true);
      }
    catch (const std::exception &e)
      {
        throw InputError(filename, essential_message(e));
      }
    return prm.get("Study");
  }



  void
  SceneReader::print_parameters(std::ostream &out)
  {
    ParameterHandler prm;
    declare_parameters(prm, {"body"}, {"pair"});
    prm.print_parameters(out,
                         ParameterHandler::PRM |
                           ParameterHandler::KeepDeclarationOrder);
  }
} // namespace glissade
