// The second half of reading a scene: turning the values of a parsed
// ParameterHandler into a SceneDescription, checking each value as it goes.
// The mistakes of independent parts (each body, each contact pair, the load
// program) are collected and reported together.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/material/material.h>
#include <glissade/scene/scene_reader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The ParameterHandler seen by the parsing functions, which counts the
     * subsections it has entered: when a check throws from inside a
     * subsection, the collector of mistakes unwinds to where it started and
     * goes on with the next body or contact pair.
     */
    class TrackedParameters
    {
    public:
      explicit TrackedParameters(ParameterHandler &prm)
        : prm(prm)
      {}

      void
      enter_subsection(const std::string &name)
      {
        prm.enter_subsection(name);
        ++depth;
      }

      void
      leave_subsection()
      {
        prm.leave_subsection();
        --depth;
      }

      /** Leaves subsections until `level` are open. */
      void
      unwind_to(const unsigned int level)
      {
        while (depth > level)
          leave_subsection();
      }

      unsigned int
      level() const
      {
        return depth;
      }

      std::string
      get(const std::string &entry) const
      {
        return prm.get(entry);
      }

      long int
      get_integer(const std::string &entry) const
      {
        return prm.get_integer(entry);
      }

      double
      get_double(const std::string &entry) const
      {
        return prm.get_double(entry);
      }

      bool
      get_bool(const std::string &entry) const
      {
        return prm.get_bool(entry);
      }

    private:
      ParameterHandler &prm;
      unsigned int      depth = 0;
    };

    /** Compiles an expression once so that typos are caught while reading. */
    void
    check_expressions(const std::vector<std::string> &expressions,
                      const std::string              &where)
    {
      // muParser accepts an assignment ("t=5" sets t and yields 5) and
      // rand(): neither belongs in a boundary datum, and both ran silently.
      for (const auto &e : expressions)
        {
          for (std::size_t i = 0; i < e.size(); ++i)
            if (e[i] == '=' &&
                (i == 0 ||
                 std::string("<>!=").find(e[i - 1]) == std::string::npos) &&
                (i + 1 == e.size() || e[i + 1] != '='))
              throw InputError(where,
                               "'" + e +
                                 "' assigns with '=': an expression "
                                 "gives a value (compare with '==')");
          if (e.find("rand") != std::string::npos)
            throw InputError(where,
                             "'" + e +
                               "' uses rand(): boundary data must be "
                               "the same in every run");
        }
      // deal.II's parser prints muparser's diagnosis to std::cerr before it
      // throws; the user gets it once, in the InputError below.
      std::ostringstream diagnosis;
      std::streambuf    *standard_error = std::cerr.rdbuf(diagnosis.rdbuf());
      struct Restore
      {
        std::streambuf *buffer;
        ~Restore()
        {
          std::cerr.rdbuf(buffer);
        }
      } restore{standard_error};
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
                             text::essential_message(e));
        }
    }

    Point<2>
    parse_coordinates(const std::string &text_value, const std::string &where)
    {
      const auto parts = text::split_top_level(text_value, ',');
      if (parts.size() != 2)
        throw InputError(where,
                         "expected two coordinates 'x, y', got '" + text_value +
                           "'");
      // Every character must belong to the number ("0.5abc" and "0.5*t"
      // were read as 0.5), and the number must be finite and small enough
      // that squared distances do not overflow.
      double x[2];
      for (unsigned int i = 0; i < 2; ++i)
        {
          const std::string part = text::trim(parts[i]);
          char             *end  = nullptr;
          x[i]                   = std::strtod(part.c_str(), &end);
          if (part.empty() || *end != '\0')
            throw InputError(where,
                             "cannot read coordinates '" + text_value + "': '" +
                               part + "' is not a number");
          if (!std::isfinite(x[i]) || std::abs(x[i]) > 1e100)
            throw InputError(where,
                             "coordinates '" + text_value +
                               "': each must be finite and below 1e100 in "
                               "magnitude");
        }
      return Point<2>(x[0], x[1]);
    }

    void
    parse_components(const std::string    &components,
                     DirichletDescription &item,
                     const std::string    &where)
    {
      const std::string c = text::trim(components);
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
                                         ", or n or t (normal, tangential)" :
                                         "") +
                           ", not '" + c + "'");
      item.all_derivatives = (c == "all");
      item.x_component =
        item.all_derivatives || (c.find('x') != std::string::npos);
      item.y_component =
        item.all_derivatives || (c.find('y') != std::string::npos);
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
                             "cannot read '" + item + "': expected '" + syntax +
                               "'");
          items.push_back(fields);
        }
      return items;
    }

    /**
     * An entry that may be left empty to inherit a value (a material
     * region's moduli, a pair's old Contact solver entries): `inherited`
     * if empty, else the number it holds; anything else is an input error
     * naming `where`/entry, with `hint` after the complaint.
     */
    double
    number_or_inherited(TrackedParameters &prm,
                        const std::string &entry,
                        const double       inherited,
                        const std::string &where,
                        const std::string &hint = "")
    {
      const std::string value = text::trim(prm.get(entry));
      if (value.empty())
        return inherited;
      try
        {
          std::size_t  used   = 0;
          const double result = std::stod(value, &used);
          if (used == value.size() && std::isfinite(result))
            return result;
        }
      catch (const std::exception &)
        {}
      throw InputError(where + "/" + entry,
                       "'" + value + "' is not a number" + hint);
    }

    ContactDescription
    parse_contact(TrackedParameters              &prm,
                  const std::string              &name,
                  const std::vector<std::string> &body_names,
                  const ContactSolverSettings    &solver,
                  const std::string              &source)
    {
      ContactDescription c;
      c.name            = name;
      c.entry           = source + ": Contact " + name;
      c.slave_body      = prm.get("Slave body");
      c.slave_boundary  = prm.get("Slave boundary");
      c.master_body     = prm.get("Master body");
      c.master_boundary = prm.get("Master boundary");
      c.surface         = prm.get("Surface");
      c.force_transfer  = prm.get("Force transfer") == "spline" ?
                            ContactDescription::ForceTransfer::spline :
                            ContactDescription::ForceTransfer::segment;
      {
        const std::string rule = prm.get("Faceted vertex rule");
        c.vertex_rule          = rule == "closest point" ?
                                   ContactDescription::VertexRule::closest_point :
                                 rule == "vertex normal" ?
                                   ContactDescription::VertexRule::vertex_normal :
                                   ContactDescription::VertexRule::kept_segment;
      }
      c.alert_distance = prm.get_double("Alert distance");
      if (prm.get("Frame update") == "increment")
        throw InputError(
          c.entry + "/Frame update",
          "'increment' (the contact frame frozen over an increment) was "
          "removed: the tangent now holds the contact's own terms, so the "
          "frame is updated at every Newton iteration and converges "
          "quadratically in the true frame (doc/contact.md); delete this "
          "line");
      c.friction = prm.get_double("Friction coefficient");
      // A pair's own value of a Contact solver entry (old scenes)
      // replaces the section's.
      const auto solver_entry = [&](const std::string &entry,
                                    const double       section_value) {
        return number_or_inherited(prm,
                                   entry,
                                   section_value,
                                   c.entry,
                                   " (this entry is kept for old scenes: set "
                                   "Contact solver/" +
                                     entry + " instead, once for all pairs)");
      };
      c.beta              = solver_entry("Beta", solver.beta);
      c.tolerance         = solver_entry("Tolerance", solver.tolerance);
      const double sweeps = solver_entry("Maximum sweeps", solver.max_sweeps);
      if (!(sweeps >= 1. && sweeps <= 1e9 && sweeps == std::floor(sweeps)))
        throw InputError(c.entry + "/Maximum sweeps",
                         "must be a whole number of at least 1");
      c.max_sweeps = static_cast<unsigned int>(sweeps);
      if (!(c.tolerance > 0.))
        throw InputError(c.entry + "/Tolerance",
                         "must be > 0: the local solver's residual is never "
                         "exactly zero (1e-10 is the default)");
      if (c.friction > 100.)
        throw InputError(c.entry + "/Friction coefficient",
                         "is " + std::to_string(c.friction) +
                           ": above 100 the local solver's cone is too "
                           "sharp to converge in double precision; such "
                           "a contact sticks for any load, so use 100");
      prm.enter_subsection("Obstacle");
      c.obstacle = prm.get("Type");
      c.obstacle_point =
        parse_coordinates(prm.get("Point"), c.entry + "/Obstacle/Point");
      const Point<2> normal =
        parse_coordinates(prm.get("Normal"), c.entry + "/Obstacle/Normal");
      c.obstacle_normal = normal;
      c.obstacle_radius = prm.get_double("Radius");
      c.obstacle_motion = text::split_top_level(prm.get("Motion"), ',');
      prm.leave_subsection();
      if (!(c.obstacle_radius <= 1e100))
        throw InputError(c.entry + "/Obstacle/Radius",
                         "must be finite and below 1e100 (squared distances "
                         "would overflow)");

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
    parse_mesh(TrackedParameters &prm, const std::string &where)
    {
      MeshDescription mesh;
      prm.enter_subsection("Mesh");
      mesh.type = prm.get("Type");
      mesh.corner_1 =
        parse_coordinates(prm.get("Corner 1"), where + "/Mesh/Corner 1");
      mesh.corner_2 =
        parse_coordinates(prm.get("Corner 2"), where + "/Mesh/Corner 2");
      mesh.center =
        parse_coordinates(prm.get("Center"), where + "/Mesh/Center");
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
      if (mesh.type == "half ring" &&
          !(mesh.end_angle > mesh.start_angle &&
            mesh.end_angle - mesh.start_angle < 360.))
        throw InputError(where + "/Mesh/End angle",
                         "must be larger than Start angle, by less than 360");
      if (mesh.type != "half ring" &&
          (mesh.start_angle != 0. || mesh.end_angle != 180.))
        throw InputError(where + "/Mesh/" +
                           (mesh.start_angle != 0. ? "Start angle" :
                                                     "End angle"),
                         "applies to Type = half ring only (this mesh is a " +
                           mesh.type +
                           "); to turn a body, use Boundary conditions/"
                           "Prescribed rotation");
      {
        // A generated mesh is allocated before anything else happens: a
        // typing slip (100000, 100000) would take every byte of memory.
        double cells = 1.;
        for (const int n : mesh.subdivisions)
          {
            if (n < 1)
              throw InputError(where + "/Mesh/Subdivisions",
                               "every count must be at least 1");
            cells *= n;
          }
        if (mesh.type != "gmsh" && cells > 4e6)
          throw InputError(where + "/Mesh/Subdivisions",
                           "asks for " + std::to_string(cells) +
                             " cells; more than 4 million (about 8 million "
                             "dofs and 10 GB for one body) is refused as a "
                             "probable slip");
      }
      if (mesh.type == "ring" && mesh.subdivisions[0] < 3)
        throw InputError(where + "/Mesh/Subdivisions",
                         "a ring needs at least 3 elements around");
      if (mesh.type == "gmsh" && mesh.file.empty())
        throw InputError(where + "/Mesh/File", "gmsh meshes need a File");
      return mesh;
    }

    MaterialDescription
    parse_material(TrackedParameters &prm, const std::string &where)
    {
      MaterialDescription material;
      prm.enter_subsection("Material");
      material.law           = prm.get("Law");
      material.young_modulus = prm.get_double("Young modulus");
      material.poisson_ratio = prm.get_double("Poisson ratio");
      material.hypothesis    = prm.get("Hypothesis") == "plane stress" ?
                                 PlaneHypothesis::plane_stress :
                                 PlaneHypothesis::plane_strain;
      material.thickness     = prm.get_double("Thickness");
      const std::vector<std::string> regions =
        Utilities::split_string_list(prm.get("Regions"), ',');
      prm.leave_subsection();
      const auto check_moduli = [&where](const double       young_modulus,
                                         const double       poisson_ratio,
                                         const std::string &subsection) {
        if (!(young_modulus > 0.))
          throw InputError(where + "/" + subsection + "/Young modulus",
                           "must be > 0");
        if (!(poisson_ratio > -1. && poisson_ratio < 0.5))
          throw InputError(where + "/" + subsection + "/Poisson ratio",
                           "must lie in (-1, 0.5)");
      };
      check_moduli(material.young_modulus, material.poisson_ratio, "Material");
      if (!(material.thickness > 0.))
        throw InputError(where + "/Material/Thickness", "must be > 0");

      // Each region: its own entries, the body's where it sets none.
      for (const std::string &name : regions)
        {
          const std::string         subsection = "Material " + name;
          MaterialRegionDescription region;
          region.name = name;
          prm.enter_subsection(subsection);
          region.law           = text::trim(prm.get("Law"));
          region.young_modulus = number_or_inherited(prm,
                                                     "Young modulus",
                                                     material.young_modulus,
                                                     where + "/" + subsection);
          region.poisson_ratio = number_or_inherited(prm,
                                                     "Poisson ratio",
                                                     material.poisson_ratio,
                                                     where + "/" + subsection);
          prm.leave_subsection();
          if (region.law.empty())
            region.law = material.law;
          const auto &laws = Material::law_names();
          if (std::find(laws.begin(), laws.end(), region.law) == laws.end())
            throw InputError(where + "/" + subsection + "/Law",
                             "'" + region.law + "' is not a law (" +
                               text::joined(laws, ", ") + ")");
          check_moduli(region.young_modulus, region.poisson_ratio, subsection);
          material.regions.push_back(region);
        }
      return material;
    }

    void
    parse_boundary_conditions(TrackedParameters &prm,
                              BodyDescription   &body,
                              const std::string &where_body)
    {
      prm.enter_subsection("Boundary conditions");
      const std::string where = where_body + "/Boundary conditions/";

      for (const auto &f : split_items(
             prm.get("Fixed"), 2, where + "Fixed", "location: components"))
        {
          DirichletDescription item;
          item.kind     = DirichletDescription::Kind::fixed;
          item.location = f[0];
          item.entry    = where + "Fixed";
          parse_components(f[1], item, item.entry);
          body.dirichlet.push_back(item);
        }

      for (const auto &f : split_items(prm.get("Prescribed displacement"),
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
          check_expressions(item.expressions, item.entry);
          body.dirichlet.push_back(item);
        }

      for (const auto &f : split_items(prm.get("Prescribed rotation"),
                                       3,
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

      // Two Dirichlet data on one location and component contradict each
      // other (which wins would depend on the order of application).
      for (unsigned int i = 0; i < body.dirichlet.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            const DirichletDescription &a = body.dirichlet[j],
                                       &b = body.dirichlet[i];
            // A rotation, a normal or a tangential support involves both
            // Cartesian components.
            const auto both_x = [](const DirichletDescription &d) {
              return d.kind == DirichletDescription::Kind::rotation ||
                     d.direction !=
                       DirichletDescription::Direction::cartesian ||
                     d.x_component;
            };
            const auto both_y = [](const DirichletDescription &d) {
              return d.kind == DirichletDescription::Kind::rotation ||
                     d.direction !=
                       DirichletDescription::Direction::cartesian ||
                     d.y_component;
            };
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

      const auto add_neumann = [&](const std::string             &entry,
                                   const NeumannDescription::Kind kind,
                                   const unsigned int             n_expressions,
                                   const std::string             &syntax) {
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
            double     x, y;
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



    /**
     * A 64-bit FNV-1a hash of every value of the scene except the
     * Checkpoint section (a run stopped half-way and its restart differ
     * only there): a restart refuses a checkpoint of another scene.
     */
    std::string
    fingerprint(ParameterHandler &prm, const std::vector<std::string> &files)
    {
      prm.enter_subsection("Checkpoint");
      const std::string interval = prm.get("Interval");
      const std::string stop     = prm.get("Stop after increment");
      prm.set("Interval", "0");
      prm.set("Stop after increment", "0");
      prm.leave_subsection();
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      prm.enter_subsection("Checkpoint");
      prm.set("Interval", interval);
      prm.set("Stop after increment", stop);
      prm.leave_subsection();
      // The content of the files the scene reads (meshes): a restart after a
      // mesh file changed would otherwise continue a different problem.
      for (const auto &file : files)
        {
          // Only what the mesh reader will accept (it refuses the rest with
          // a message): a device such as /dev/zero never ends.
          if (!text::is_regular_file_of_at_most(file, 1ull << 31))
            continue;
          std::ifstream in(file, std::ios::binary);
          text << "\nfile " << file << '\n' << in.rdbuf();
        }

      std::uint64_t hash = 14695981039346656037ull;
      for (const char c : text.str())
        {
          hash ^= static_cast<unsigned char>(c);
          hash *= 1099511628211ull;
        }
      std::ostringstream hex;
      hex << std::hex << std::setw(16) << std::setfill('0') << hash;
      return hex.str();
    }
  } // namespace



  SceneDescription
  SceneReader::parse_parameters(ParameterHandler               &handler,
                                const std::vector<std::string> &body_names,
                                const std::vector<std::string> &contact_names,
                                const std::string              &source)
  {
    SceneDescription  scene;
    TrackedParameters prm(handler);
    InputErrorList    mistakes;
    scene.source = source;

    // Each part is checked even when an earlier one has a mistake: the user
    // reads every mistake of the file in one message.
    const auto check_part = [&](const auto &parse_part) {
      const unsigned int level = prm.level();
      mistakes.collect([&]() {
        try
          {
            parse_part();
          }
        catch (...)
          {
            prm.unwind_to(level);
            throw;
          }
      });
    };

    check_part([&]() {
      prm.enter_subsection("Contact solver");
      scene.contact_solver.beta       = prm.get_double("Beta");
      scene.contact_solver.tolerance  = prm.get_double("Tolerance");
      scene.contact_solver.max_sweeps = prm.get_integer("Maximum sweeps");
      prm.leave_subsection();
      if (!(scene.contact_solver.beta > 0. && scene.contact_solver.beta < 2.))
        throw InputError(source + ": Contact solver/Beta",
                         "must lie in (0, 2)");
      if (!(scene.contact_solver.tolerance > 0.))
        throw InputError(source + ": Contact solver/Tolerance",
                         "must be > 0: the local solver's residual is never "
                         "exactly zero (1e-10 is the default)");
    });
    for (const auto &name : contact_names)
      check_part([&]() {
        prm.enter_subsection("Contact " + name);
        scene.contacts.push_back(
          parse_contact(prm, name, body_names, scene.contact_solver, source));
        prm.leave_subsection();
      });
    for (const auto &name : body_names)
      {
        const std::string where = source + ": Body " + name;
        BodyDescription   body;
        body.name = name;
        prm.enter_subsection("Body " + name);
        check_part([&]() { body.mesh = parse_mesh(prm, where); });
        prm.enter_subsection("Element");
        body.element_space = prm.get("Space");
        prm.leave_subsection();
        check_part([&]() { body.material = parse_material(prm, where); });
        check_part([&]() { parse_boundary_conditions(prm, body, where); });
        prm.leave_subsection();
        if (body.mesh.type == "gmsh")
          body.mesh.file = text::path_beside(source, body.mesh.file);
        // A body that nothing holds (no Dirichlet datum, no contact pair)
        // has a singular tangent: its rigid-body motions are free. The
        // factorisation would not always say so (round-off pivots), and the
        // run would end on an inverted element far from the cause.
        bool in_contact = false;
        for (const auto &c : scene.contacts)
          in_contact =
            in_contact || c.slave_body == name || c.master_body == name;
        if (body.dirichlet.empty() && !in_contact)
          check_part([&]() {
            throw InputError(where + "/Boundary conditions",
                             "body '" + name +
                               "' has no support: no Fixed, Prescribed "
                               "displacement or rotation, and no contact "
                               "pair, so its rigid-body motions (two "
                               "translations and a rotation) are free");
          });
        scene.bodies.push_back(body);
      }

    prm.enter_subsection("Load program");
    scene.load_program.stage_end_times.clear();
    for (const auto &t :
         Utilities::split_string_list(prm.get("Stage end times"), ','))
      try
        {
          scene.load_program.stage_end_times.push_back(std::stod(t));
        }
      catch (const std::exception &)
        {
          throw InputError(source + ": Load program/Stage end times",
                           "'" + t +
                             "' is not a double-precision number "
                             "(out of range?)");
        }
    scene.load_program.stage_increments.clear();
    for (const auto &n :
         Utilities::split_string_list(prm.get("Stage increments"), ','))
      {
        const long value = std::strtol(n.c_str(), nullptr, 10);
        if (value < 1 || value > 100000000)
          throw InputError(source + ": Load program/Stage increments",
                           "'" + n +
                             "' is not a number of increments "
                             "between 1 and 1e8");
        scene.load_program.stage_increments.push_back(value);
      }
    scene.load_program.max_cut_back_depth =
      prm.get_integer("Maximum cut-back depth");
    prm.leave_subsection();
    const auto &times = scene.load_program.stage_end_times;
    check_part([&]() {
      if (times.size() != scene.load_program.stage_increments.size())
        throw InputError(source + ": Load program/Stage increments",
                         "needs one value per stage end time");
    });
    check_part([&]() {
      for (unsigned int i = 0; i < times.size(); ++i)
        if (!(times[i] > (i == 0 ? 0. : times[i - 1])))
          throw InputError(source + ": Load program/Stage end times",
                           "must be positive and increasing");
    });

    prm.enter_subsection("Newton");
    scene.newton.max_iterations     = prm.get_integer("Maximum iterations");
    scene.newton.residual_tolerance = prm.get_double("Residual tolerance");
    scene.newton.displacement_tolerance =
      prm.get_double("Displacement tolerance");
    prm.leave_subsection();
    check_part([&]() {
      if (!(scene.newton.residual_tolerance > 0.))
        throw InputError(source + ": Newton/Residual tolerance",
                         "must be > 0: a residual is never exactly zero in "
                         "floating point (1e-9 to 1e-12 is usual)");
      if (!(scene.newton.displacement_tolerance > 0.))
        throw InputError(source + ": Newton/Displacement tolerance",
                         "must be > 0 (1e-6 to 1e-10 is usual)");
    });

    prm.enter_subsection("Output");
    scene.output.directory    = prm.get("Directory");
    scene.output.vtu_interval = prm.get_integer("VTU interval");
    {
      using Compression            = OutputSettings::Compression;
      const std::string level      = prm.get("VTU compression");
      scene.output.vtu_compression = level == "small" ? Compression::small :
                                     level == "none"  ? Compression::none :
                                                        Compression::fast;
    }
    scene.output.initial_state = prm.get_bool("Initial state");
    scene.output.contact_table_interval =
      prm.get_integer("Contact table interval");
    for (const auto &item : text::split_top_level(prm.get("History"), ';'))
      if (!item.empty())
        scene.output.history.push_back(item);
    scene.output.progress    = prm.get_bool("Progress");
    scene.output.plots       = prm.get_bool("Plots");
    const std::string curves = prm.get("Plot curves");
    prm.leave_subsection();
    check_part([&]() {
      for (const auto &item : text::split_top_level(curves, ';'))
        {
          if (text::trim(item).empty())
            continue;
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
            throw InputError(source + ": Output/Plot curves",
                             "'" + text::trim(item) +
                               "' is not 'x column: y column' (names of "
                               "history.csv, e.g. 'pad_uy_0_10: "
                               "pad_Ry_top')");
          scene.output.plot_curves.emplace_back(parts[0], parts[1]);
        }
    });

    prm.enter_subsection("Checkpoint");
    scene.checkpoint.interval   = prm.get_integer("Interval");
    scene.checkpoint.stop_after = prm.get_integer("Stop after increment");
    prm.leave_subsection();
    unsigned int n_increments = 0;
    for (const unsigned int n : scene.load_program.stage_increments)
      n_increments += n;
    check_part([&]() {
      if (scene.checkpoint.stop_after > n_increments)
        throw InputError(source + ": Checkpoint/Stop after increment",
                         "is " + std::to_string(scene.checkpoint.stop_after) +
                           ", beyond the last increment of the load program (" +
                           std::to_string(n_increments) + ")");
    });

    mistakes.throw_if_any();
    std::vector<std::string> files_read;
    for (const auto &body : scene.bodies)
      if (!body.mesh.file.empty())
        files_read.push_back(body.mesh.file);
    scene.fingerprint = fingerprint(handler, files_read);
    return scene;
  }
} // namespace glissade
