#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/plotting.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <paper_studies/case3_study.h>
#include <paper_studies/study_progress.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The variants whose outer ring alone is of another element (fig 29's
     * Hermite, the NURBS outer rings with Q4 inner ones): run at each of
     * the study's outer element counts, the inner ring kept.
     */
    bool
    refines_outer_ring_only(const std::string &variant)
    {
      return variant == "hermite" || variant == "nurbs2-master" ||
             variant == "nurbs3-master" || variant == "mortar-nurbs2" ||
             variant == "mortar-nurbs3";
    }

    /**
     * The variants run at each of the study's outer element counts: those
     * above, and the NURBS rings with mortar, both rings refined (the
     * trade between unknowns and spread of the exact rings).
     */
    bool
    runs_at_each_count(const std::string &variant)
    {
      return refines_outer_ring_only(variant) || variant == "nurbs2-mortar" ||
             variant == "nurbs3-mortar";
    }
  } // namespace



  double
  Case3Study::paper_spread(const std::string &variant)
  {
    return variant.rfind("q4", 0) == 0 ? 4.8 :
           variant == "bspline"        ? 0.0015 :
                                         0.1;
  }



  Case3Result
  Case3Study::run_variant(const std::string &scene_file,
                          const std::string &variant,
                          const double       rotation_degrees,
                          const unsigned int rotation_increments,
                          const std::string &output_directory,
                          const unsigned int outer_elements)
  {
    // Another number of elements (fig 29, the trade study): "hermite20".
    const std::string label =
      variant +
      (outer_elements != 40 ? std::to_string(outer_elements) : std::string());
    std::vector<std::string> overrides = {
      "Load program/Stage end times=1, " +
        std::to_string(1. + rotation_degrees / 180.),
      "Load program/Stage increments=10, " +
        std::to_string(rotation_increments),
      "Output/Progress=false",
      "Output/VTU interval=0",
      "Output/Directory=" + output_directory + "/" + label};
    if (outer_elements != 40)
      {
        // The outer ring's supports hold its tangential displacement at
        // 0, 90, 180 and 270 degrees: these must be nodes.
        if (outer_elements % 4 != 0)
          throw InputError("Case 3 study: elements around",
                           "the outer ring needs a multiple of 4 elements "
                           "(its supports sit at 0, 90, 180 and 270 "
                           "degrees); got " +
                             std::to_string(outer_elements));
        // Hermite (fig 29) and the NURBS outer rings change the outer ring
        // only; Q4 and B-spline refine both rings alike, radially too, at
        // the paper's aspect.
        const bool        outer_only = refines_outer_ring_only(variant);
        const std::string around     = std::to_string(outer_elements);
        const std::string across =
          std::to_string(std::max(4u, outer_elements / 10));
        overrides.push_back("Body outer/Mesh/Subdivisions=" + around + ", " +
                            (outer_only ? "4" : across));
        if (!outer_only)
          overrides.push_back("Body inner/Mesh/Subdivisions=" + around + ", " +
                              across);
        // The same total load (400 N) on fewer or more outer nodes.
        const std::string f = std::to_string(400. / outer_elements);
        overrides.push_back(
          "Body outer/Boundary conditions/Nodal loads=outer: -" + f +
          "*x/sqrt(x^2+y^2)*min(t, 1), -" + f + "*y/sqrt(x^2+y^2)*min(t, 1)");
      }
    // A NURBS outer ring takes the 400 N as the uniform traction they
    // stand for on its radius 2 (its vertices' point forces would not be
    // a pressure for its functions).
    if (variant.find("nurbs") != std::string::npos)
      {
        const std::string p = std::to_string(400. / (4. * M_PI));
        overrides.push_back("Body outer/Boundary conditions/Nodal loads=");
        overrides.push_back(
          "Body outer/Boundary conditions/Tractions=outer: -" + p +
          "*x/sqrt(x^2+y^2)*min(t, 1), -" + p + "*y/sqrt(x^2+y^2)*min(t, 1)");
      }
    if (variant == "q4")
      overrides.push_back("Contact interface/Surface=faceted");
    else if (variant == "q4-closest" || variant == "q4-vertex" ||
             variant == "q4-kept")
      {
        // The faceted master with a given vertex rule (issue 22's study).
        overrides.push_back("Contact interface/Surface=faceted");
        overrides.push_back(
          std::string("Contact interface/Faceted vertex rule=") +
          (variant == "q4-closest" ? "closest point" :
           variant == "q4-kept"    ? "kept segment" :
                                     "vertex normal"));
      }
    else if (variant == "bspline")
      overrides.push_back("Contact interface/Surface=bspline");
    else if (variant == "mortar" || variant == "mortar-bspline" ||
             variant == "mortar-hermite")
      {
        // Mortar over the faceted master (the element edges), the closed
        // B-spline, or the Hermite outer ring's C1 edge.
        overrides.push_back(std::string("Contact interface/Surface=") +
                            (variant == "mortar"         ? "faceted" :
                             variant == "mortar-bspline" ? "bspline" :
                                                           "hermite"));
        overrides.push_back("Contact interface/Discretisation=mortar");
        if (variant == "mortar-hermite")
          overrides.push_back("Body outer/Element/Space=hermite");
      }
    else if (variant == "bspline-spline")
      {
        overrides.push_back("Contact interface/Surface=bspline");
        overrides.push_back("Contact interface/Force transfer=spline");
      }
    else if (variant == "hermite")
      {
        overrides.push_back("Body outer/Element/Space=hermite");
        overrides.push_back("Contact interface/Surface=hermite");
      }
    else if (variant == "nurbs2-master" || variant == "nurbs3-master" ||
             variant == "mortar-nurbs2" || variant == "mortar-nurbs3")
      {
        // The outer ring isogeometric, its exact boundary the master of the
        // Q4 inner ring's nodes (as hermite changes the outer ring only),
        // node-to-segment or mortar.
        const bool mortar = variant.rfind("mortar", 0) == 0;
        overrides.push_back("Body outer/Element/Space=nurbs");
        overrides.push_back("Body outer/Element/Degree=" +
                            variant.substr(mortar ? 12 : 5, 1));
        overrides.push_back("Contact interface/Surface=nurbs");
        if (mortar)
          overrides.push_back("Contact interface/Discretisation=mortar");
      }
    else if (variant == "nurbs2" || variant == "nurbs3" ||
             variant == "nurbs2-mortar" || variant == "nurbs3-mortar")
      {
        // Both rings isogeometric (the exact circles), the outer ring's
        // boundary the master; the inner ring's Greville points the slave
        // points, or its own boundary with mortar; the supports and nodal
        // loads act through the functions at the vertices.
        for (const std::string body : {"inner", "outer"})
          {
            overrides.push_back("Body " + body + "/Element/Space=nurbs");
            overrides.push_back("Body " + body +
                                "/Element/Degree=" + variant.substr(5, 1));
          }
        overrides.push_back("Contact interface/Surface=nurbs");
        if (variant.find("mortar") != std::string::npos)
          overrides.push_back("Contact interface/Discretisation=mortar");
      }
    else
      throw InputError(
        "Case 3 study/Variants",
        "unknown variant '" + variant +
          "' (known: q4, q4-vertex, q4-closest, q4-kept, bspline, "
          "bspline-spline, hermite, mortar, mortar-bspline, "
          "mortar-hermite, nurbs2, nurbs3, nurbs2-mortar, nurbs3-mortar, "
          "nurbs2-master, nurbs3-master, mortar-nurbs2, mortar-nurbs3)");

    Simulation  simulation(SceneReader::read_file(scene_file, overrides));
    Case3Result result;
    result.variant = label;
    for (const auto &b : simulation.bodies())
      result.dofs += b->n_unknowns();
    auto       &pair  = *simulation.contact().contact_pairs().at(0);
    const Body &inner = pair.slave();
    // The interface radius of prm/case3_rings.prm (the scale of a torque).
    const double interface_radius = 1.25;
    const double step = rotation_degrees * M_PI / 180. / rotation_increments;
    double       previous_torque = 0., previous_force = 0.;
    // Fig 28: the master curve (a deformable master's) near the node, two
    // elements either side.
    const auto *curve_surface =
      variant == "bspline" || variant == "hermite" ?
        dynamic_cast<const CurveSurface *>(&pair.surface()) :
        nullptr;
    const double window_degrees = 2. * 360. / outer_elements;
    // A NURBS ring's slave points are its Greville points, closer together
    // where the ring's arcs join: what is uniform there is the pressure,
    // a point's reaction over its area (its collocation area, or int R_A
    // with mortar), not the force.
    const bool                per_area = variant.rfind("nurbs", 0) == 0;
    const std::vector<double> area     = pair.tributary_areas();
    simulation.on_increment = [&](const unsigned int increment, double) {
      if (curve_surface)
        {
          const MasterCurve &curve = curve_surface->master_curve();
          std::vector<std::array<double, 2>> profile;
          for (unsigned int segment = 0; segment < curve.n_segments();
               ++segment)
            for (unsigned int k = 0; k < 16; ++k)
              {
                MasterCurve::Point c, dc, ddc;
                curve.evaluate(segment, k / 16., c, dc, ddc);
                const double angle = std::atan2(c[1], c[0]) * 180. / M_PI;
                if (std::abs(angle) <= window_degrees)
                  profile.push_back({{angle, std::hypot(c[0], c[1])}});
              }
          std::sort(profile.begin(), profile.end());
          result.master_profile.push_back(std::move(profile));
        }
      std::vector<double> forces;
      double              torque = 0., total_force = 0.;
      for (unsigned int k = 0; k < pair.nodes().size(); ++k)
        if (const ContactNode &node = pair.nodes()[k]; node.active)
          {
            // (per area: the reaction over it, the contact tables'
            // pressure; with mortar on a NURBS slave the resultant of the
            // point's forces is shorter, their normal turning across its
            // function's support)
            forces.push_back(per_area ?
                               std::hypot(node.reaction[0], node.reaction[1]) /
                                 area[k] :
                               node.force().norm());
            // The slave nodes are on the inner ring: x x f about (0, 0) at
            // the node's current position (its own value dofs: no vertex
            // search at every increment).
            const Point<2> x =
              node.reference_position + node.displacement(inner.displacement());
            const Tensor<1, 2> f = node.force();
            torque += x[0] * f[1] - x[1] * f[0];
            total_force += f.norm();
          }
      result.node_force.push_back(
        pair.node_at(Point<2>(interface_radius, 0.)).force().norm());
      if (increment > 10)
        {
          // The trapezoidal rule over the increment's rotation.
          result.spurious_work += 0.5 * (previous_torque + torque) * step;
          result.tangential_work_scale +=
            0.5 * (previous_force + total_force) * interface_radius * step;
          const double ratio =
            total_force > 0. ?
              100. * torque / (interface_radius * total_force) :
              0.;
          result.torque_percent.push_back(ratio);
          result.worst_torque_percent =
            std::max(result.worst_torque_percent, std::abs(ratio));
        }
      previous_torque = torque;
      previous_force  = total_force;
      double mean     = 0.;
      for (const double f : forces)
        mean += f / forces.size();
      result.mean_force.push_back(mean);
      result.smallest_force.push_back(
        forces.empty() ? 0. : *std::min_element(forces.begin(), forces.end()));
      result.largest_force.push_back(
        forces.empty() ? 0. : *std::max_element(forces.begin(), forces.end()));
      if (increment <= 10 || forces.empty())
        return;
      double spread = 0.;
      for (const double f : forces)
        spread = std::max(spread, std::abs(f - mean) / mean * 100.);
      result.spread_percent.push_back(spread);
      if (spread >= result.worst_spread)
        {
          result.worst_spread    = spread;
          result.worst_increment = increment;
          result.worst_distribution.clear();
          for (const double f : forces)
            result.worst_distribution.push_back((f / mean - 1.) * 100.);
        }
    };
    Timer timer;
    simulation.run();
    result.wall_seconds      = timer.wall_time();
    result.newton_iterations = simulation.statistics().newton_iterations;
    result.active_nodes      = pair.n_active();
    return result;
  }



  void
  Case3Study::write_fig28(const std::vector<Case3Result> &results,
                          const double                    rotation_degrees,
                          const unsigned int              rotation_increments,
                          const std::string              &directory)
  {
    const Case3Result *bspline = nullptr, *hermite = nullptr;
    for (const auto &r : results)
      {
        if (r.variant == "bspline")
          bspline = &r;
        if (r.variant == "hermite")
          hermite = &r;
      }
    // The first element of rotation, where fig 27's pattern shows once.
    const unsigned int per_element = static_cast<unsigned int>(
      std::lround(rotation_increments * 9. / rotation_degrees));
    if (!bspline || !hermite || per_element < 4 ||
        bspline->node_force.size() < 10 + per_element ||
        hermite->node_force.size() < 10 + per_element)
      return;
    // i1: the node at mid-element, where the paper sees the two smooth
    // masters match; i2: where their forces on the node differ most.
    const unsigned int i1 = 10 + per_element / 2;
    unsigned int       i2 = 11;
    for (unsigned int i = 11; i <= 10 + per_element; ++i)
      if (std::abs(hermite->node_force[i - 1] - bspline->node_force[i - 1]) >
          std::abs(hermite->node_force[i2 - 1] - bspline->node_force[i2 - 1]))
        i2 = i;
    AtomicFile csv(directory + "/case3_fig28.csv");
    csv.stream() << "variant,increment,role,node_angle,angle,radius\n"
                 << std::setprecision(12);
    for (const auto *r : {bspline, hermite})
      for (const auto &[i, role] :
           {std::pair<unsigned int, const char *>{i1, "i1"}, {i2, "i2"}})
        for (const auto &[angle, radius] : r->master_profile.at(i - 1))
          csv.stream() << r->variant << ',' << i << ',' << role << ','
                       << (i - 10) * rotation_degrees / rotation_increments
                       << ',' << angle << ',' << radius << '\n';
    csv.commit();
    std::cout << "Fig 28: master curves at increment " << i1
              << " (node at mid-element: |F_hermite - F_bspline| = "
              << std::abs(hermite->node_force[i1 - 1] -
                          bspline->node_force[i1 - 1])
              << " N) and " << i2 << " (the largest difference, "
              << std::abs(hermite->node_force[i2 - 1] -
                          bspline->node_force[i2 - 1])
              << " N)\n";
  }



  void
  Case3Study::run(const std::string              &prm_file,
                  const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "case3", Patterns::Selection("case3"));
    prm.enter_subsection("Case 3 study");
    prm.declare_entry("Scene",
                      "case3_rings.prm",
                      Patterns::Anything(),
                      "The rings' scene (relative to this file's folder).");
    prm.declare_entry("Variants",
                      "q4, bspline, hermite",
                      Patterns::List(Patterns::Selection(
                        "q4|q4-vertex|q4-closest|q4-kept|bspline|hermite|"
                        "mortar|mortar-bspline|mortar-hermite|nurbs2|nurbs3|"
                        "nurbs2-mortar|nurbs3-mortar|nurbs2-master|"
                        "nurbs3-master|mortar-nurbs2|mortar-nurbs3")),
                      "Discretisations of the interface. q4 uses the "
                      "scene's Faceted vertex rule; q4-vertex, q4-closest "
                      "and q4-kept the rules vertex normal, closest point "
                      "and kept segment (doc/contact.md); mortar, "
                      "mortar-bspline and mortar-hermite the mortar "
                      "discretisation over the faceted master, the B-spline "
                      "and the Hermite outer ring's edge; nurbs2 and nurbs3 "
                      "both rings isogeometric of degree 2 or 3 (the exact "
                      "circles), knot-to-segment on the outer ring's exact "
                      "boundary, the spread that of the points' pressure; "
                      "nurbs2-mortar, nurbs3-mortar both rings with mortar "
                      "on the inner ring's own boundary; "
                      "nurbs2-master, nurbs3-master the outer ring only, "
                      "node-to-segment; mortar-nurbs2, mortar-nurbs3 the "
                      "same with mortar. A NURBS outer ring is loaded by the "
                      "traction the 400 N stand for.");
    prm.declare_entry("Rotation angle",
                      "9",
                      Patterns::Double(0.),
                      "Degrees of rotation after the compression (the paper: "
                      "180; one element of the outer ring: 9).");
    prm.declare_entry("Rotation increments",
                      "50",
                      Patterns::Integer(1),
                      "Increments of the rotation (the paper: 1000 for 180 "
                      "degrees, i.e. 50 per element).");
    prm.declare_entry("Hermite outer elements",
                      "40",
                      Patterns::List(Patterns::Integer(4)),
                      "Elements around the outer ring for the hermite variant "
                      "(fig 29: the paper uses 10, 20, 40; the supports need "
                      "a multiple of 4), and for the variants with a NURBS "
                      "outer ring and a Q4 inner one (nurbs2-master, "
                      "nurbs3-master, mortar-nurbs2, mortar-nurbs3; the "
                      "inner ring keeps 40), and for both NURBS rings with "
                      "mortar (nurbs2-mortar, nurbs3-mortar: both refined, "
                      "a tenth as many elements through, at least 4). The "
                      "nodal loads are scaled to keep the total of 400 N.");
    prm.declare_entry("Output directory",
                      "output/case3_study",
                      Patterns::Anything(),
                      "Where CSVs and PNGs go.");
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, overrides);
    prm.enter_subsection("Case 3 study");
    const std::string scene = text::path_beside(prm_file, prm.get("Scene"));
    const auto        variants =
      Utilities::split_string_list(prm.get("Variants"), ',');
    const double angle =
      SceneReader::get_double(prm, "Rotation angle", prm_file);
    const unsigned int increments =
      SceneReader::get_integer(prm, "Rotation increments", prm_file);
    const std::string         directory = prm.get("Output directory");
    std::vector<unsigned int> outer_elements;
    for (const auto &n :
         Utilities::split_string_list(prm.get("Hermite outer elements"), ','))
      outer_elements.push_back(Utilities::string_to_int(n));
    prm.leave_subsection();
    std::filesystem::create_directories(directory);

    std::vector<Case3Result> results;
    unsigned int             n_runs = 0;
    for (const auto &variant : variants)
      n_runs += runs_at_each_count(variant) ? outer_elements.size() : 1;
    StudyProgress progress(n_runs);
    for (const auto &variant : variants)
      for (const unsigned int n : runs_at_each_count(variant) ?
                                    outer_elements :
                                    std::vector<unsigned int>{40})
        {
          std::ostringstream what;
          what << "case 3, " << variant << " (" << n
               << " outer elements): compression (10 increments), rotation "
                  "by "
               << angle << " degrees (" << increments << " increments)";
          progress.next(what.str());
          results.push_back(
            run_variant(scene, variant, angle, increments, directory, n));
        }

    AtomicFile csv(directory + "/case3_spread.csv");
    csv.stream()
      << "variant,increment,spread_percent,node_force,torque_percent,"
         "mean_force,smallest_force,largest_force\n";
    for (const auto &r : results)
      for (unsigned int i = 0; i < r.node_force.size(); ++i)
        csv.stream() << r.variant << ',' << i + 1 << ','
                     << (i >= 10 ? r.spread_percent[i - 10] : 0.) << ','
                     << r.node_force[i] << ','
                     << (i >= 10 ? r.torque_percent[i - 10] : 0.) << ','
                     << r.mean_force[i] << ',' << r.smallest_force[i] << ','
                     << r.largest_force[i] << '\n';
    csv.commit();
    AtomicFile worst(directory + "/case3_worst.csv");
    worst.stream() << "variant,node,deviation_percent\n";
    for (const auto &r : results)
      for (unsigned int k = 0; k < r.worst_distribution.size(); ++k)
        worst.stream() << r.variant << ',' << k << ','
                       << r.worst_distribution[k] << '\n';
    worst.commit();
    write_fig28(results, angle, increments, directory);

    // The paper's figure where it gives one (not for 12 or 20 elements).
    const auto paper_figure = [](const std::string &variant) {
      std::ostringstream text;
      text << paper_spread(variant);
      return text.str();
    };
    std::cout << "\nCase 3, spread of the interface contact forces around F_e "
                 "(worst rotation increment)\n"
              << std::setw(10) << "method" << std::setw(14) << "spread (%)"
              << std::setw(14) << "paper (%)" << std::setw(10) << "dofs"
              << std::setw(14) << "wall (s)" << std::setw(16) << "|T|/(R F) (%)"
              << std::setw(16) << "work of T (J)" << std::setw(14)
              << "/ R F theta" << '\n';
    for (const auto &r : results)
      std::cout << std::setw(10) << r.variant << std::setw(14)
                << std::setprecision(3) << r.worst_spread << std::setw(14)
                << (r.variant.rfind("q4", 0) == 0 || r.variant == "bspline" ||
                        r.variant == "hermite" ?
                      paper_figure(r.variant) :
                      std::string("-"))
                << std::setw(10) << r.dofs << std::setw(14) << r.wall_seconds
                << std::setw(16) << r.worst_torque_percent << std::setw(16)
                << r.spurious_work << std::setw(14)
                << r.spurious_work / std::max(r.tangential_work_scale, 1e-300)
                << '\n';
    std::cout << "(T: the torque of the contact forces on the inner ring, "
                 "zero for exact frictionless contact of round rings: its "
                 "largest value over the rotation and its work)\n";
    std::cout << std::flush;
    plot_with_python("plot_case3.py", directory);
  }
} // namespace glissade
