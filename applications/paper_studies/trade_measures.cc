#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <paper_studies/case3_study.h>
#include <paper_studies/contact_case_study.h>
#include <paper_studies/geometric_study.h>
#include <paper_studies/trade_measures.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The Element entries of a discretisation label (Table 1): its space,
     *  and the degree of a NURBS one (nurbs2, nurbs3). */
    std::vector<std::string>
    element_of(const std::string &discretisation)
    {
      if (discretisation.rfind("nurbs", 0) == 0)
        return {"Body beam/Element/Space=nurbs",
                "Body beam/Element/Degree=" + discretisation.substr(5)};
      static const std::map<std::string, std::string> spaces = {{"q4", "q1"},
                                                                {"q9", "q2"},
                                                                {"q16", "q3"},
                                                                {"q8", "q8"},
                                                                {"q12", "q12"},
                                                                {"hermite",
                                                                 "hermite"}};
      return {"Body beam/Element/Space=" + spaces.at(discretisation)};
    }

    /** A point's run: no progress, no VTU, its own output directory. */
    std::vector<std::string>
    quiet_output(const std::string &directory)
    {
      return {"Output/Progress=false",
              "Output/VTU interval=0",
              "Output/Directory=" + directory};
    }

    /** "n, n/15": the paper's beam and ring aspect (120 x 8). */
    std::string
    along_and_across(const unsigned int n)
    {
      return std::to_string(n) + ", " + std::to_string(std::max(1u, n / 15));
    }

    /**
     * Dofs of the nodes on an edge of n elements: what a representation of
     * the master surface carries (q8 and q12 add one and two nodes per edge,
     * Hermite six dofs per node; a NURBS edge of degree p, n + p control
     * points).
     */
    double
    edge_dofs(const std::string &method, const unsigned int n)
    {
      if (method == "nurbs2" || method == "nurbs3")
        return 2. * (n + std::stoi(method.substr(5)));
      if (method == "q8")
        return 2. * (2 * n + 1);
      if (method == "q12")
        return 2. * (3 * n + 1);
      if (method == "hermite")
        return 6. * (n + 1);
      return 2. * (n + 1);
    }

    TradePoint
    geometric_point(const std::string &measure,
                    const std::string &method,
                    const unsigned int n)
    {
      // Building and sampling a curve takes microseconds: repeat it until
      // the timer can resolve it, and report the time of one.
      TradePoint                   point;
      unsigned int                 repetitions = 0;
      Timer                        timer;
      std::vector<GeometricSample> samples;
      do
        {
          samples = GeometricStudy::evaluate(method, n, 41);
          ++repetitions;
        }
      while (timer.wall_time() < 0.05);
      point.wall_seconds = timer.wall_time() / repetitions;
      point.dofs         = edge_dofs(method, n);
      point.value        = measure == "geometric_gap" ?
                             GeometricStudy::max_gap_error_percent(samples) :
                             GeometricStudy::max_normal_error_degrees(samples);
      return point;
    }

    TradePoint
    table1_point(const std::string &discretisation,
                 const unsigned int n,
                 const std::string &scene_file,
                 const std::string &output_directory)
    {
      std::vector<std::string> overrides =
        quiet_output(output_directory + "/table1/" + discretisation + "_" +
                     std::to_string(n));
      for (const std::string &entry : element_of(discretisation))
        overrides.push_back(entry);
      overrides.push_back("Body beam/Mesh/Subdivisions=" + along_and_across(n));
      const SceneDescription scene =
        SceneReader::read_file(scene_file, overrides);
      Timer      timer;
      Simulation simulation(scene);
      simulation.run();
      TradePoint point;
      point.wall_seconds      = timer.wall_time();
      point.dofs              = simulation.body("beam").n_unknowns();
      point.newton_iterations = simulation.statistics().newton_iterations;
      point.value             = max_displacement(simulation.body("beam"));
      return point;
    }

    /** Vertical displacement of a body's vertex at a point, at the end. */
    double
    final_uy_at(const ContactCaseResult &result,
                const std::string       &body,
                const Point<2>          &where)
    {
      for (unsigned int b = 0; b < result.body_names.size(); ++b)
        if (result.body_names[b] == body)
          for (unsigned int v = 0; v < result.vertices[b].size(); ++v)
            if (result.vertices[b][v].distance(where) < 1e-9)
              return result.final_displacement[b][v][1];
      throw InputError("Trade study/Case 1",
                       "the scene's body '" + body +
                         "' has no vertex at the point the study reads");
    }

    TradePoint
    contact_case_point(const std::string         &measure,
                       const std::string         &variant,
                       const unsigned int         n,
                       const std::string         &scene_file,
                       const std::vector<double> &settings,
                       const std::string         &output_directory)
    {
      const SceneDescription   base = SceneReader::read_file(scene_file);
      std::vector<std::string> meshes;
      unsigned int             increments    = 0;
      double                   load_fraction = 1.;
      if (measure == "case1")
        // Beam and ring alike: n along, n/15 across (the paper: 120 x 8).
        for (const auto &body : base.bodies)
          meshes.push_back("Body " + body.name +
                           "/Mesh/Subdivisions=" + along_and_across(n));
      else
        {
          // Case 2: n around each ring (the scene's 120 x 8), the square
          // refined in the same ratio (the scene's 10 x 10).
          for (const auto &body : base.bodies)
            {
              // The square keeps a vertex at the middle of each side (its
              // rotation is held there): an even number of cells.
              const unsigned int m =
                body.name == "square" ?
                  2 *
                    std::max(1u,
                             static_cast<unsigned int>(std::lround(n / 24.))) :
                  n;
              const unsigned int across =
                body.name == "square" ? m : std::max(1u, n / 15);
              meshes.push_back("Body " + body.name +
                               "/Mesh/Subdivisions=" + std::to_string(m) +
                               ", " + std::to_string(across));
            }
          increments    = static_cast<unsigned int>(settings.at(0));
          load_fraction = settings.at(1);
        }
      meshes.push_back("Output/VTU interval=0");
      const ContactCaseResult r =
        ContactCaseStudy::run_variant(scene_file,
                                      variant,
                                      increments,
                                      load_fraction,
                                      output_directory + "/" + measure + "/" +
                                        std::to_string(n),
                                      false,
                                      meshes);

      TradePoint point;
      point.dofs              = r.dofs;
      point.newton_iterations = r.newton_iterations;
      point.wall_seconds      = r.wall_seconds;
      if (!r.active_nodes.empty())
        point.active_nodes =
          *std::max_element(r.active_nodes.begin(), r.active_nodes.end());
      if (measure == "case1")
        point.value = final_uy_at(r, "beam", Point<2>(0., 0.));
      else
        {
          if (r.corner_force.empty())
            throw InputError(scene_file,
                             "the trade study's case 2 needs the "
                             "scene of case 2 (two rings and a "
                             "square)");
          const auto [first, last] = ContactCaseStudy::contact_phase(r);
          point.value              = ContactCaseStudy::roughness(r.corner_force,
                                                    first + 2,
                                                    last - 1,
                                                    r.active_nodes);
        }
      return point;
    }

    TradePoint
    case3_point(const std::string         &measure,
                const std::string         &variant,
                const unsigned int         n,
                const std::string         &scene_file,
                const std::vector<double> &settings,
                const std::string         &output_directory)
    {
      // The rotation crosses angle / (360 / n) elements of the finer of
      // the two rings (Hermite: its inner ring keeps 40), each in the same
      // number of increments, so that every mesh samples its ripple alike.
      const double       angle  = settings.at(0);
      const unsigned int finest = variant == "hermite" ? std::max(n, 40u) : n;
      const unsigned int increments = static_cast<unsigned int>(
        std::ceil(angle / (360. / finest) * settings.at(1)));
      const Case3Result r = Case3Study::run_variant(
        scene_file, variant, angle, increments, output_directory + "/case3", n);
      TradePoint point;
      point.dofs              = r.dofs;
      point.newton_iterations = r.newton_iterations;
      point.active_nodes      = r.active_nodes;
      point.wall_seconds      = r.wall_seconds;
      point.value =
        measure == "case3_torque" ? r.worst_torque_percent : r.worst_spread;
      return point;
    }

    /**
     * Hertz (the scene prm/hertz_trade.prm, plane strain, small strain):
     * the peak pressure p0 of the quarter cylinder's slave points against
     * Hertz's closed form at the load the contact carries, in %. A point's
     * pressure is its normal reaction over its tributary length in the
     * reference configuration (a node's: half its reference faces; a
     * NURBS point's: its collocation area), the nominal pressure that
     * small strain speaks of (per current length it adds the surface's
     * strain, 0.3 % here); the axis point's tributary is its half in the
     * quarter model. settings: the cylinder's radius.
     */
    TradePoint
    hertz_point(const std::string         &variant,
                const unsigned int         n,
                const std::string         &scene_file,
                const std::vector<double> &settings,
                const std::string         &output_directory)
    {
      const bool        nurbs = variant.rfind("nurbs", 0) == 0;
      const std::string space =
        nurbs ? "nurbs" : (variant == "hermite" ? "hermite" : "q1");
      const std::string surface = nurbs                ? "nurbs" :
                                  variant == "bspline" ? "bspline" :
                                  variant == "hermite" ? "hermite" :
                                                         "faceted";
      const bool        mortar  = variant.find("mortar") != std::string::npos;
      std::vector<std::string> overrides = quiet_output(
        output_directory + "/hertz/" + variant + "_" + std::to_string(n));
      overrides.push_back("Contact touch/Surface=" + surface);
      overrides.push_back(std::string("Contact touch/Discretisation=") +
                          (mortar ? "mortar" : "node-to-segment"));
      for (const std::string body : {"cylinder", "block"})
        {
          overrides.push_back("Body " + body + "/Element/Space=" + space);
          overrides.push_back("Body " + body +
                              "/Mesh/Subdivisions=" + std::to_string(n) + ", " +
                              std::to_string(std::max(2u, (5 * n + 6) / 12)));
          if (nurbs)
            overrides.push_back("Body " + body +
                                "/Element/Degree=" + variant.substr(5, 1));
        }
      if (nurbs)
        overrides.push_back("Body cylinder/Mesh/File=meshes/quarter_disk_p" +
                            variant.substr(5, 1) + ".nurbs");
      const SceneDescription scene =
        SceneReader::read_file(scene_file, overrides);
      Timer      timer;
      Simulation simulation(scene);
      simulation.run();
      TradePoint point;
      point.wall_seconds      = timer.wall_time();
      point.newton_iterations = simulation.statistics().newton_iterations;
      for (const std::string body : {"cylinder", "block"})
        point.dofs += simulation.body(body).n_unknowns();

      const auto &pairs = simulation.contact().contact_pairs();
      if (pairs.size() != 1)
        throw InputError(scene_file,
                         "the trade study's Hertz measure needs one "
                         "contact pair, the cylinder's arc on the flat");
      const ContactPair &pair  = *pairs[0];
      const auto        &nodes = pair.nodes();
      // Reference tributary lengths (faces), or collocation areas.
      std::vector<double> tributary(nodes.size(), 0.);
      for (const auto &[a, b] : pair.slave_faces())
        {
          const double face =
            nodes[a].reference_position.distance(nodes[b].reference_position);
          tributary[a] += 0.5 * face;
          tributary[b] += 0.5 * face;
        }
      double       load = 0., active = 0.;
      unsigned int axis = 0;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          if (nodes[k].collocation_area != 0.)
            tributary[k] = nodes[k].collocation_area;
          if (nodes[k].active)
            {
              load += 2. * pair.reported_force(nodes[k])[1];
              ++active;
            }
          if (std::abs(nodes[k].reference_position[0]) <
              std::abs(nodes[axis].reference_position[0]))
            axis = k;
        }
      point.active_nodes = active;
      if (std::abs(nodes[axis].reference_position[0]) > 1e-12 || load <= 0.)
        throw InputError(scene_file,
                         "the trade study's Hertz measure needs a quarter "
                         "cylinder pressed on the flat with a slave point "
                         "on its axis x = 0");
      // Both bodies' material is the cylinder's (checked): E* = E / (2 (1 -
      // nu^2)) in plane strain.
      const auto material_of = [&](const std::string &name) {
        for (const auto &body : scene.bodies)
          if (body.name == name)
            return body.material;
        throw InputError(scene_file,
                         "the trade study's Hertz measure needs the bodies "
                         "'cylinder' and 'block'");
      };
      const MaterialDescription material = material_of("cylinder");
      const MaterialDescription other    = material_of("block");
      if (material.young_modulus != other.young_modulus ||
          material.poisson_ratio != other.poisson_ratio)
        throw InputError(scene_file,
                         "the trade study's Hertz measure needs the cylinder "
                         "and the block of one material");
      const double nu     = material.poisson_ratio;
      const double E_star = material.young_modulus / (2. * (1. - nu * nu));
      const double radius = settings.at(0);
      const double a      = std::sqrt(4. * load * radius / (M_PI * E_star));
      const double p0     = 2. * load / (M_PI * a);
      const double measured =
        pair.reported_reaction(nodes[axis])[1] / tributary[axis];
      point.value = std::abs(measured - p0) / p0 * 100.;
      return point;
    }
  } // namespace



  const std::vector<std::string> &
  TradeMeasures::names()
  {
    static const std::vector<std::string> all = {"geometric_gap",
                                                 "geometric_normal",
                                                 "table1",
                                                 "case1",
                                                 "case2",
                                                 "case3",
                                                 "case3_torque",
                                                 "hertz"};
    return all;
  }



  std::string
  TradeMeasures::error_name(const std::string &measure)
  {
    static const std::map<std::string, std::string> names = {
      {"geometric_gap", "largest gap error (% of R)"},
      {"geometric_normal", "largest normal error (degrees)"},
      {"table1", "largest displacement, error against the reference (%)"},
      {"case1", "tip displacement, error against the reference (%)"},
      {"case2", "corner contact-force roughness"},
      {"case3", "worst contact-force spread (%)"},
      {"case3_torque", "largest spurious torque, |T| / (R sum |f|) (%)"},
      {"hertz", "peak pressure p0, error against Hertz's (%)"}};
    return names.at(measure);
  }



  bool
  TradeMeasures::needs_reference(const std::string &measure)
  {
    return measure == "table1" || measure == "case1";
  }



  double
  TradeMeasures::error(const std::string &measure,
                       const double       value,
                       const double       reference)
  {
    if (!needs_reference(measure))
      return value;
    return std::abs(value - reference) / std::abs(reference) * 100.;
  }



  const std::vector<std::string> &
  TradeMeasures::discretisations(const std::string &measure)
  {
    static const std::vector<std::string> geometric = {
      "q4", "q8", "q12", "bspline", "hermite", "nurbs2", "nurbs3"};
    static const std::vector<std::string> table1 = {
      "q4", "q8", "q9", "q12", "q16", "hermite", "nurbs2", "nurbs3"};
    static const std::vector<std::string> contact = {
      "q4", "bspline", "bspline-spline", "hermite", "mortar"};
    // (case 3 with both rings NURBS, mortar on the inner ring's boundary)
    static const std::vector<std::string> case3 = {"q4",
                                                   "bspline",
                                                   "bspline-spline",
                                                   "hermite",
                                                   "mortar",
                                                   "nurbs2-mortar",
                                                   "nurbs3-mortar"};
    // (Hertz: Q4 or Hermite bodies with node-to-segment on the flat's
    // faceted, B-spline or Hermite top; Q4 with mortar; NURBS with mortar)
    static const std::vector<std::string> hertz = {
      "q4", "bspline", "hermite", "mortar", "nurbs2-mortar", "nurbs3-mortar"};
    if (measure == "table1")
      return table1;
    if (measure == "hertz")
      return hertz;
    if (measure.rfind("geometric", 0) == 0)
      return geometric;
    if (measure.rfind("case3", 0) == 0)
      return case3;
    return contact;
  }



  TradePoint
  TradeMeasures::run(const std::string         &measure,
                     const std::string         &discretisation,
                     const unsigned int         n,
                     const std::string         &scene,
                     const std::vector<double> &settings,
                     const std::string         &output_directory)
  {
    if (measure.rfind("geometric", 0) == 0)
      return geometric_point(measure, discretisation, n);
    if (measure == "table1")
      return table1_point(discretisation, n, scene, output_directory);
    if (measure == "case1" || measure == "case2")
      return contact_case_point(
        measure, discretisation, n, scene, settings, output_directory);
    if (measure == "case3" || measure == "case3_torque")
      return case3_point(
        measure, discretisation, n, scene, settings, output_directory);
    if (measure == "hertz")
      return hertz_point(discretisation, n, scene, settings, output_directory);
    throw InputError("Trade study/Measures",
                     "unknown measure '" + measure + "'");
  }
} // namespace glissade
