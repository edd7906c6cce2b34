#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/contact/surface_registry.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/material/material.h>
#include <glissade/scene/parameter_file.h>
#include <glissade/scene/scene_reader.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The entries a material region may set; unset ones are the body's. */
    void
    declare_region_material(ParameterHandler &prm)
    {
      prm.declare_entry("Law",
                        "",
                        Patterns::Anything(),
                        "As Material/Law; empty: the body's.");
      prm.declare_entry("Young modulus",
                        "",
                        Patterns::Anything(),
                        "As Material/Young modulus; empty: the body's.");
      prm.declare_entry("Poisson ratio",
                        "",
                        Patterns::Anything(),
                        "As Material/Poisson ratio; empty: the body's.");
    }

    void
    declare_body(ParameterHandler &prm, const std::vector<std::string> &regions)
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
      }
      prm.leave_subsection();

      prm.enter_subsection("Element");
      prm.declare_entry(
        "Space",
        "q1",
        Patterns::Selection(ElementSpaceRegistry::names_as_pattern()),
        "The element space by name: " + ElementSpaceRegistry::documentation());
      prm.leave_subsection();

      prm.enter_subsection("Material");
      {
        prm.declare_entry("Law",
                          "neo-Hookean",
                          Patterns::Selection(
                            text::joined(Material::law_names(), "|")),
                          "Hyperelastic law (total Lagrangian).");
        prm.declare_entry("Young modulus",
                          "1",
                          Patterns::Double(),
                          "E in Pa, > 0.");
        prm.declare_entry("Poisson ratio",
                          "0.3",
                          Patterns::Double(),
                          "nu, in (-1, 0.5).");
        prm.declare_entry("Hypothesis",
                          "plane strain",
                          Patterns::Selection("plane strain|plane stress"),
                          "Planar hypothesis.");
        prm.declare_entry("Thickness",
                          "1",
                          Patterns::Double(),
                          "Out-of-plane thickness (m), > 0: forces are per "
                          "this thickness.");
        prm.declare_entry(
          "Regions",
          "",
          Patterns::Anything(),
          "Gmsh meshes: comma-separated names of Physical Surfaces that "
          "have a material of their own, each set in a subsection "
          "'Material <name>' beside this one (Law, Young modulus, Poisson "
          "ratio; an entry left unset is this subsection's). Cells of other "
          "Physical Surfaces take this subsection's material. Hypothesis and "
          "Thickness belong to the body.");
      }
      prm.leave_subsection();
      for (const std::string &region : regions)
        {
          prm.enter_subsection("Material " + region);
          declare_region_material(prm);
          prm.leave_subsection();
        }

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
          "curved boundary; q1 bodies). Example: 'left: xy; point(0, 0): y; "
          "outer: n'.");
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
    declare_contact(ParameterHandler &prm)
    {
      prm.declare_entry("Slave body",
                        "",
                        Patterns::Anything(),
                        "The body whose boundary nodes are the slave nodes.");
      prm.declare_entry(
        "Slave boundary",
        "",
        Patterns::Anything(),
        "The declared contact area on the slave body: a boundary "
        "name, or several separated by commas "
        "('bottom, left, right'), whose nodes form one set.");
      prm.declare_entry("Master body",
                        "rigid",
                        Patterns::Anything(),
                        "The body that carries the master surface, or "
                        "'rigid' for an analytic obstacle (subsection "
                        "Obstacle).");
      prm.declare_entry("Master boundary",
                        "",
                        Patterns::Anything(),
                        "The declared contact area on the master body.");
      prm.declare_entry("Surface",
                        "faceted",
                        Patterns::Selection(SurfaceRegistry::names_as_pattern(
                          SurfaceRegistry::Kind::deformable)),
                        "Representation of the master surface: " +
                          SurfaceRegistry::documentation(
                            SurfaceRegistry::Kind::deformable));
      prm.declare_entry(
        "Force transfer",
        "segment",
        Patterns::Selection("segment|spline"),
        "How a B-spline master receives the reaction: segment hands it to "
        "the two nodes of the underlying straight segment (the paper); "
        "spline uses the spline's own weights (consistent, symmetric W).");
      prm.declare_entry(
        "Faceted vertex rule",
        "kept segment",
        Patterns::Selection("kept segment|closest point|vertex normal"),
        "What a faceted master does at a vertex, where its normal jumps "
        "(doc/contact.md). kept segment: a node keeps its segment over "
        "the increment, up to half its length past either end; a new "
        "choice takes the closest point, and a node exactly on a vertex the "
        "segment leaving it. closest point: the closest point at every "
        "iteration, a node in the corner's wedge (behind both facets) "
        "meeting the vertex with the mean normal of the two facets. vertex "
        "normal: as closest point, and a node on a vertex (to 1e-9 of the "
        "segment) meets it with the mean normal too, instead of the "
        "segment leaving it: the only rule objective under a rigid turn, "
        "but a node that must slide off a vertex with friction does not "
        "converge. Other surfaces ignore this entry.");
      prm.declare_entry("Alert distance",
                        "0",
                        Patterns::Double(0.),
                        "Slave nodes farther than this from the master at the "
                        "start of an increment start it inactive; they join "
                        "the condensed problem only if an iteration would "
                        "take them behind the master.");
      prm.declare_entry(
        "Frame update",
        "iteration",
        Patterns::Selection("iteration|increment"),
        "Kept for old scenes: the active nodes are re-projected at every "
        "Newton iteration, with the contact's own terms in the tangent. "
        "'increment' (the frame frozen over an increment) was removed and "
        "is refused with a message.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(0.),
                        "Coulomb's mu (0: frictionless).");
      // The local solver's settings belong to the scene (section Contact
      // solver): the active nodes of all pairs form one local problem.
      // These entries are kept for old scenes.
      for (const auto &[entry, owner] :
           {std::pair<const char *, const char *>{"Beta", "Beta"},
            {"Tolerance", "Tolerance"},
            {"Maximum sweeps", "Maximum sweeps"}})
        prm.declare_entry(entry,
                          "",
                          Patterns::Anything(),
                          std::string("Kept for old scenes: empty, or this "
                                      "pair's value of Contact solver/") +
                            owner +
                            ", which replaces the section's (every pair "
                            "that gives one must give the same).");
      prm.enter_subsection("Obstacle");
      prm.declare_entry("Type",
                        "line",
                        Patterns::Selection(SurfaceRegistry::names_as_pattern(
                          SurfaceRegistry::Kind::rigid)),
                        SurfaceRegistry::documentation(
                          SurfaceRegistry::Kind::rigid));
      prm.declare_entry("Point",
                        "0, 0",
                        Patterns::Anything(),
                        "line: a point on it; disk, hole: the centre.");
      prm.declare_entry("Normal",
                        "0, 1",
                        Patterns::Anything(),
                        "line: the normal pointing out of the obstacle.");
      prm.declare_entry("Radius", "1", Patterns::Double(0.), "disk, hole.");
      prm.declare_entry("Motion",
                        "0, 0",
                        Patterns::Anything(),
                        "Translation of the obstacle as expressions of t.");
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
          throw InputError("--set " + assignment, text::essential_message(e));
        }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }

    /**
     * Each name once. Body and contact pair names become parts of output
     * file names
     * ("<body>-00010.vtu", "contact-<pair>-00010.csv"): a name that is a
     * path ("up/../../x") would write outside the output directory.
     */
    void
    check_file_name_parts(const std::vector<std::string> &names,
                          const std::string              &entry,
                          const std::string              &what)
    {
      for (const auto &name : names)
        {
          bool printable = true;
          for (const unsigned char c : name)
            printable = printable && c >= 32 && c != 127;
          // '"', '<', '>' and '&' would break the PVD index (XML).
          if (name.empty() || name == "." || name == ".." ||
              name.find_first_of("/\\\"<>&") != std::string::npos ||
              !printable || name.size() > 100)
            throw InputError(entry,
                             what + " name '" + name.substr(0, 100) +
                               (name.size() > 100 ? "...'" : "'") +
                               " cannot be part of a file name: use at most "
                               "100 letters, digits, spaces, '-', '_' or "
                               "'.', without '/', '\\', '\"', '<', '>' "
                               "or '&'");
        }
      for (unsigned int i = 0; i < names.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          if (names[i] == names[j])
            throw InputError(entry,
                             what + " '" + names[i] + "' is named twice");
    }



    std::vector<std::string>
    read_body_names(const std::string &text_value, const std::string &source)
    {
      const auto names = Utilities::split_string_list(text_value, ',');
      if (names.empty())
        throw InputError(source + ": Scene/Bodies",
                         "the scene needs at least one body");
      check_file_name_parts(names, source + ": Scene/Bodies", "body");
      return names;
    }

  } // namespace



  void
  SceneReader::declare_parameters(
    ParameterHandler                                      &prm,
    const std::vector<std::string>                        &body_names,
    const std::vector<std::string>                        &contact_names,
    const std::map<std::string, std::vector<std::string>> &regions)
  {
    prm.declare_entry(
      "Study",
      "simulation",
      Patterns::Selection(
        "simulation|geometric|case1|case2|case3|friction|trade"),
      "simulation: run the scene below. geometric: the "
      "geometric study of the paper's section 3.3 (see "
      "prm/geometric_study.prm); case1, case2: the beam on a "
      "half ring and the square between two half rings "
      "(sections 4.1, 4.2; prm/case1_study.prm, "
      "prm/case2_study.prm); case3: the concentric rings "
      "of section 4.3 in several variants (see "
      "prm/case3_default.prm); friction: a scene for every "
      "master and friction coefficient "
      "(prm/case3_friction.prm); trade: time and dofs "
      "against accuracy (prm/trade_study.prm). A study's "
      "own entries replace these.");
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
        const auto body_regions = regions.find(name);
        declare_body(prm,
                     body_regions == regions.end() ?
                       std::vector<std::string>() :
                       body_regions->second);
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
    prm.declare_entry("Maximum iterations",
                      "25",
                      Patterns::Integer(1),
                      "Newton iterations per increment before a cut-back.");
    prm.declare_entry("Residual tolerance",
                      "1e-9",
                      Patterns::Double(0.),
                      "Converged when |R| <= tol * max(|F_int|, |F_ext|) on "
                      "the free dofs...");
    prm.declare_entry("Displacement tolerance",
                      "1e-9",
                      Patterns::Double(0.),
                      "...and |du| <= tol * |u| (tol * 1e-12 * the largest "
                      "body's diameter while u = 0).");
    prm.leave_subsection();

    prm.enter_subsection("Contact solver");
    prm.declare_entry("Beta",
                      "1",
                      Patterns::Double(0.),
                      "Bi-potential parameter in (0, 2): rho_k = beta / "
                      "W_kk(nn) on a frictionless node, beta / the largest "
                      "eigenvalue of its 2x2 block W_kk with friction. The "
                      "active nodes of all contact pairs form one local "
                      "problem, solved with these settings.");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Relative tolerance of the local solver.");
    prm.declare_entry("Maximum sweeps",
                      "10000",
                      Patterns::Integer(1),
                      "Gauss-Seidel sweeps of the local solver.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::Anything(),
                      "Where VTU/PVD, history.csv and summary.txt go "
                      "(relative paths: from the working directory).");
    prm.declare_entry("VTU interval",
                      "1",
                      Patterns::Integer(0),
                      "Write a VTU every this many increments (0: only the "
                      "initial and final states).");
    prm.declare_entry("Initial state",
                      "true",
                      Patterns::Bool(),
                      "Write the VTU files and contact tables of increment "
                      "0 (the reference configuration, no contact force); "
                      "false: only the increments that the intervals ask "
                      "for and the final state.");
    prm.declare_entry("VTU compression",
                      "fast",
                      Patterns::Selection("fast|small|none"),
                      "zlib compression of the bodies' VTU files: fast "
                      "(zlib level 1), small (level 9, deal.II's default: "
                      "0.6 % smaller, written 5.6 times slower on the 160 x "
                      "16 rings), none (3.4 times larger).");
    prm.declare_entry("Contact table interval",
                      "0",
                      Patterns::Integer(0),
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
    prm.declare_entry("Progress",
                      "true",
                      Patterns::Bool(),
                      "Print one line per increment.");
    prm.declare_entry("Plots",
                      "false",
                      Patterns::Bool(),
                      "At the end of the run (or at a stop), draw PNGs "
                      "from the written files: history.png (every history "
                      "column against t, and the Newton iterations), and "
                      "contact-<pair>-pressure.png (the pressure along "
                      "each slave boundary at the written increments) and "
                      "deformed-mesh.png (the bodies in their last written "
                      "state, coloured by von Mises). "
                      "Needs Debian's /usr/bin/python3 with matplotlib; "
                      "without it the run says so and goes on.");
    prm.declare_entry(
      "Plot curves",
      "",
      Patterns::Anything(),
      "With Plots: curves.png, one panel per 'x column: y "
      "column' item (';'-separated), each a column of "
      "history.csv (or time), e.g. a force-displacement "
      "curve 'pad_uy_0_10: pad_Ry_top'. Checked, but drawn only with "
      "Plots = true.");
    prm.leave_subsection();

    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write <Output directory>/checkpoint.bin every this "
                      "many converged increments (0: never). 'glissade "
                      "scene.prm --restart' continues from it to the same "
                      "output as an uninterrupted run.");
    prm.declare_entry("Stop after increment",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint after this increment and stop "
                      "cleanly (0: run to the end): a long study in "
                      "batches of a queue's time limit.");
    prm.leave_subsection();
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
          throw InputError(source, text::essential_message(e));
        }
      prm.enter_subsection("Scene");
      body_names = read_body_names(prm.get("Bodies"), source);
      contact_names =
        Utilities::split_string_list(prm.get("Contact pairs"), ',');
      check_file_name_parts(contact_names,
                            source + ": Scene/Contact pairs",
                            "contact pair");
      prm.leave_subsection();
    }

    // Pass 1b: each body's material regions, whose subsections are
    // declared by name in pass 2.
    std::map<std::string, std::vector<std::string>> regions;
    {
      ParameterHandler prm;
      for (const auto &name : body_names)
        {
          prm.enter_subsection("Body " + name);
          prm.enter_subsection("Material");
          prm.declare_entry("Regions", "", Patterns::Anything());
          prm.leave_subsection();
          prm.leave_subsection();
        }
      try
        {
          prm.parse_input_from_string(text_value, "", true);
          for (const auto &o : overrides)
            if (o.find("/Material/Regions=") != std::string::npos)
              apply_override(prm, o);
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::exception &e)
        {
          throw InputError(source, text::essential_message(e));
        }
      for (const auto &name : body_names)
        {
          prm.enter_subsection("Body " + name);
          prm.enter_subsection("Material");
          regions[name] = Utilities::split_string_list(prm.get("Regions"), ',');
          prm.leave_subsection();
          prm.leave_subsection();
          const std::string entry =
            source + ": Body " + name + "/Material/Regions";
          for (unsigned int i = 0; i < regions[name].size(); ++i)
            for (unsigned int j = 0; j < i; ++j)
              if (regions[name][i] == regions[name][j])
                throw InputError(entry,
                                 "region '" + regions[name][i] +
                                   "' is named twice");
        }
    }

    // Pass 2: everything, strictly: an undeclared entry is an error.
    ParameterHandler prm;
    declare_parameters(prm, body_names, contact_names, regions);
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
        throw InputError(source, text::essential_message(e));
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
    try
      {
        return parse_parameters(prm, body_names, contact_names, source);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        // A value that matches its pattern but does not convert (a
        // denormal like 1e-320 for a double): deal.II's message names the
        // entry. Found by the fuzzer.
        throw InputError(source, text::essential_message(e));
      }
  }



  SceneDescription
  SceneReader::read_file(const std::string              &filename,
                         const std::vector<std::string> &overrides)
  {
    return read_string(read_parameter_file(filename), filename, overrides);
  }



  void
  SceneReader::parse_study(ParameterHandler               &prm,
                           const std::string              &filename,
                           const std::vector<std::string> &overrides)
  {
    const std::string text_value = read_parameter_file(filename);
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
        throw InputError(filename, text::essential_message(e));
      }
  }



  namespace
  {
    /** A value read from prm, with a failed conversion as an InputError. */
    template <typename Read>
    auto
    converted(const Read &read, const std::string &filename)
    {
      try
        {
          return read();
        }
      catch (const std::exception &e)
        {
          throw InputError(filename, text::essential_message(e));
        }
    }
  } // namespace



  double
  SceneReader::get_double(const ParameterHandler &prm,
                          const std::string      &entry,
                          const std::string      &filename)
  {
    return converted([&]() { return prm.get_double(entry); }, filename);
  }



  long int
  SceneReader::get_integer(const ParameterHandler &prm,
                           const std::string      &entry,
                           const std::string      &filename)
  {
    return converted([&]() { return prm.get_integer(entry); }, filename);
  }



  std::string
  SceneReader::study_type(const std::string &filename)
  {
    const std::string text_value = read_parameter_file(filename);
    ParameterHandler  prm;
    prm.declare_entry("Study", "simulation", Patterns::Anything());
    try
      {
        prm.parse_input_from_string(text_value, "", true);
      }
    catch (const std::exception &e)
      {
        throw InputError(filename, text::essential_message(e));
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
