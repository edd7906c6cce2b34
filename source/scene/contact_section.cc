// Contact <name> (a pair and its rigid Obstacle) and Contact solver (the
// local solver of the condensed problem, one for all pairs).

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/contact/discretisation/contact_discretisation.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace glissade
{
  using namespace dealii;

  void
  ContactSolverSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact solver");
    prm.declare_entry(
      "Method",
      "condensed",
      Patterns::Selection("condensed|sparse"),
      "How the Newton step of the bodies in contact is solved. condensed: "
      "each body factorised alone, the problem condensed on the active "
      "nodes (W = H K^-1 H^T, dense) and solved by the bi-potential method "
      "(the paper's). sparse: the bodies in contact and the reactions of "
      "the active nodes as one sparse system (one LU per active-set pass), "
      "the statuses by a primal-dual active-set iteration: the same "
      "contact law, with memory and time that grow like the bodies' and "
      "not like the square of the active nodes (doc/performance.md); Beta, "
      "Tolerance and Maximum sweeps do not apply.");
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
  }



  void
  ContactSolverSettings::parse_parameters(SectionReader &prm)
  {
    prm.enter_subsection("Contact solver");
    method = prm.get("Method") == "sparse" ? Method::sparse : Method::condensed;
    beta   = prm.get_double("Beta");
    tolerance  = prm.get_double("Tolerance");
    max_sweeps = prm.get_integer("Maximum sweeps");
    prm.leave_subsection();
    if (!(beta > 0. && beta < 2.))
      throw InputError(prm.file() + ": Contact solver/Beta",
                       "must lie in (0, 2)");
    if (!(tolerance > 0.))
      throw InputError(prm.file() + ": Contact solver/Tolerance",
                       "must be > 0: the local solver's residual is never "
                       "exactly zero (1e-10 is the default)");
  }



  void
  ContactDescription::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Slave body",
                      "",
                      Patterns::Anything(),
                      "The body whose boundary nodes are the slave nodes. "
                      "Against a rigid obstacle, several bodies ('a, b, "
                      "c') or '*' (every body of Scene/Contact bodies): a "
                      "pair of each, '<body> on <pair>', with this pair's "
                      "settings; contact_force(<pair>) in the history sums "
                      "them.");
    prm.declare_entry("Slave boundary",
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
                      "The declared contact area on the master body: a "
                      "boundary name, or several separated by commas "
                      "('inner, outer'). Each connected piece of it is a "
                      "curve of the master surface (a body with a hole: its "
                      "outer boundary and the hole's wall).");
    declare_settings(prm);
    prm.declare_entry(
      "Frame update",
      "iteration",
      Patterns::Selection("iteration|increment"),
      "Kept for old scenes: the active nodes are re-projected at every "
      "Newton iteration, with the contact's own terms in the tangent. "
      "'increment' (the frame frozen over an increment) was removed and "
      "is refused with a message.");
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
    declare_obstacle(prm);
  }



  void
  ContactDescription::declare_settings(ParameterHandler &prm)
  {
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
      "spline uses the spline's own weights (consistent, symmetric W). "
      "Under a dynamic scheme it is always spline: segment's forces are "
      "not the gap's gradient, and their work on a node sliding over a step "
      "is not the contact law's (doc/theory.md, 'Forces over a step').");
    prm.declare_entry("Discretisation",
                      "node-to-segment",
                      Patterns::Selection(
                        ContactDiscretisation::names_as_pattern()),
                      "How the contact constraint is written per slave "
                      "node: " +
                        ContactDiscretisation::documentation());
    prm.declare_entry(
      "Mortar multipliers",
      "dual",
      Patterns::Selection("dual|standard"),
      "Mortar with a NURBS slave: the functions of the multiplier. dual: "
      "the element-wise dual functions of the slave boundary's R_A (Seitz "
      "et al. 2016), a pressure without point-to-point oscillation (Hertz's "
      "p0 within 0.5 %); standard: R_A themselves (De Lorenzis et al. "
      "2011), whose pressure alternates from point to point by up to 18 % "
      "of p0 on Hertz, but which holds where dual stops: a coarse curved "
      "slave sliding deep into a soft master (the NURBS die of the ironing "
      "study). Mortar on Q1 faces is dual only (doc/contact.md, 'Mortar "
      "with a NURBS slave').");
    // The master surfaces' own entries (Faceted vertex rule, ...).
    SurfaceRegistry::declare_parameters(prm, SurfaceRegistry::Kind::deformable);
    prm.declare_entry("Alert distance",
                      "0",
                      Patterns::Double(0.),
                      "Slave nodes farther than this from the master at the "
                      "start of an increment start it inactive; they join "
                      "the condensed problem only if an iteration would "
                      "take them behind the master.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0.),
                      "Coulomb's mu (0: frictionless).");
  }



  void
  ContactDescription::declare_obstacle(ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    prm.declare_entry("Type",
                      "line",
                      Patterns::Selection(SurfaceRegistry::names_as_pattern(
                        SurfaceRegistry::Kind::rigid)),
                      SurfaceRegistry::documentation(
                        SurfaceRegistry::Kind::rigid));
    // The pose of every obstacle: a reference point, its translation and a
    // rotation about it. Each kind's shape is its own (below).
    prm.declare_entry("Point",
                      "0, 0",
                      Patterns::Anything(),
                      "line: a point on it; disk, hole, casing: the centre.");
    prm.declare_entry("Motion",
                      "0, 0",
                      Patterns::Anything(),
                      "Translation of the obstacle as expressions of t.");
    prm.declare_entry(
      "Rotation",
      "0",
      Patterns::Anything(),
      "Rotation of the obstacle about its Point, counterclockwise, in "
      "radians, as an expression of t: it turns a line's normal and a "
      "casing's lobes, and for every obstacle it moves the material that "
      "friction rubs against (a turning drum). A blade turning at Omega "
      "sees its casing turn as '-Omega*t'.");
    // The rigid obstacles' own entries (Normal, Radius, Lobes, ...).
    SurfaceRegistry::declare_parameters(prm, SurfaceRegistry::Kind::rigid);
    prm.leave_subsection();
  }



  void
  ContactSolverSettings::take_pair_entries(SectionReader     &prm,
                                           const std::string &pair_entry)
  {
    // Each pair's value is its own entry or the section's; the active nodes
    // of all pairs form one local problem, so the values must agree.
    const auto take = [&](const std::string &setting, auto &value) {
      const auto   first = set_by_pair.find(setting);
      const double section =
        first == set_by_pair.end() ? double(value) : section_values.at(setting);
      const double given = prm.number_or_inherited(
        setting,
        section,
        pair_entry,
        " (this entry is kept for old scenes: set Contact solver/" + setting +
          " instead, once for all pairs)");
      if (first != set_by_pair.end() && given != double(value))
        throw InputError(pair_entry + "/" + setting,
                         "differs from " + first->second + "/" + setting +
                           ": the active nodes of all pairs form one local "
                           "problem, solved with one set of settings; set "
                           "Contact solver/" +
                           setting + " once for all pairs");
      if (setting == "Maximum sweeps" &&
          !(given >= 1. && given <= 1e9 && given == std::floor(given)))
        throw InputError(pair_entry + "/" + setting,
                         "must be a whole number of at least 1");
      if (first == set_by_pair.end())
        {
          section_values[setting] = section;
          set_by_pair.emplace(setting, pair_entry);
        }
      value = static_cast<std::decay_t<decltype(value)>>(given);
    };
    take("Beta", beta);
    take("Tolerance", tolerance);
    take("Maximum sweeps", max_sweeps);
    if (!(beta > 0. && beta < 2.))
      throw InputError(pair_entry + "/Beta", "must lie in (0, 2)");
    if (!(tolerance > 0.))
      throw InputError(pair_entry + "/Tolerance",
                       "must be > 0: the local solver's residual is never "
                       "exactly zero (1e-10 is the default)");
  }



  void
  ContactDescription::parse_parameters(
    SectionReader                  &prm,
    const std::vector<std::string> &body_names)
  {
    entry          = prm.file() + ": Contact " + name;
    slave_body     = prm.get("Slave body");
    slave_boundary = prm.get("Slave boundary");
    master_body    = prm.get("Master body");
    master = master_body == "rigid" ? MasterKind::obstacle : MasterKind::body;
    master_boundary = prm.get("Master boundary");
    parse_settings(prm);
    if (prm.get("Frame update") == "increment")
      throw InputError(
        entry + "/Frame update",
        "'increment' (the contact frame frozen over an increment) was "
        "removed: the tangent now holds the contact's own terms, so the "
        "frame is updated at every Newton iteration and converges "
        "quadratically in the true frame (doc/contact.md); delete this "
        "line");
    prm.enter_subsection("Obstacle");
    obstacle = prm.get("Type");
    obstacle_point =
      entry_format::coordinates(prm.get("Point"), entry + "/Obstacle/Point");
    obstacle_motion   = text::split_top_level(prm.get("Motion"), ',');
    obstacle_rotation = text::trim(prm.get("Rotation"));
    if (master == MasterKind::obstacle)
      surface_settings =
        SurfaceRegistry::parse_parameters(prm.handler(),
                                          SurfaceRegistry::Kind::rigid,
                                          obstacle,
                                          entry + "/Obstacle",
                                          prm.file());
    prm.leave_subsection();
    check_sides(body_names);
    if (obstacle_motion.size() != 2)
      throw InputError(entry + "/Obstacle/Motion",
                       "expected two expressions 'x(t), y(t)'");
    entry_format::check_expressions(obstacle_motion,
                                    entry + "/Obstacle/Motion");
    entry_format::check_expressions({obstacle_rotation},
                                    entry + "/Obstacle/Rotation");
  }



  void
  ContactDescription::parse_settings(SectionReader &prm)
  {
    surface            = prm.get("Surface");
    discretisation     = prm.get("Discretisation");
    mortar_multipliers = prm.get("Mortar multipliers") == "standard" ?
                           MortarMultipliers::standard :
                           MortarMultipliers::dual;
    if (master == MasterKind::body)
      surface_settings =
        SurfaceRegistry::parse_parameters(prm.handler(),
                                          SurfaceRegistry::Kind::deformable,
                                          surface,
                                          entry,
                                          prm.file());
    force_transfer = prm.get("Force transfer") == "spline" ?
                       ContactDescription::ForceTransfer::spline :
                       ContactDescription::ForceTransfer::segment;
    alert_distance = prm.get_double("Alert distance");
    friction       = prm.get_double("Friction coefficient");
    if (friction > 100.)
      throw InputError(entry + "/Friction coefficient",
                       "is " + std::to_string(friction) +
                         ": above 100 the local solver's cone is too "
                         "sharp to converge in double precision; such "
                         "a contact sticks for any load, so use 100");
  }



  void
  ContactDescription::check_sides(
    const std::vector<std::string> &body_names) const
  {
    const auto known = [&](const std::string &b) {
      return std::find(body_names.begin(), body_names.end(), b) !=
             body_names.end();
    };
    // (several bodies, or every body of Scene/Contact bodies, '*', against
    // a rigid obstacle: SceneReader makes a pair of each)
    if (slave_body != "*")
      for (const std::string &body : text::split_top_level(slave_body, ','))
        if (!known(text::trim(body)))
          throw InputError(entry + "/Slave body",
                           "there is no body '" + text::trim(body) + "'");
    if (master == MasterKind::body && !known(master_body))
      throw InputError(entry + "/Master body",
                       "there is no body '" + master_body +
                         "' (or use 'rigid')");
    if (slave_boundary.empty())
      throw InputError(entry + "/Slave boundary", "must be given");
    if (master == MasterKind::body && master_boundary.empty())
      throw InputError(entry + "/Master boundary", "must be given");
  }
} // namespace glissade
