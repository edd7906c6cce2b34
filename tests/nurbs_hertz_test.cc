// Hertz's cylinder on a flat with isogeometric bodies (issue 52): the
// scene prm/hertz_cylinder_nurbs.prm, both bodies NURBS patches graded
// towards the contact (Mesh/Grading), mortar with the cylinder's exact arc
// as the slave, against Hertz's closed form at the load the contact
// carries (plane strain, E* = E / (2 (1 - nu^2)) for two equal bodies).
// The same problem on Q4 meshes with mortar is tests/mortar_test.cc's
// mortar_hertz_cylinder_on_flat.

#include <glissade/body/body.h>
#include <glissade/body/body_measures.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/surfaces/master_chain.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/fe/nurbs_space.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  struct HertzFigures
  {
    double load = 0., half_width = 0., peak_pressure = 0.;
    double profile_error = 0., oscillation = 0.;
  };

  /**
   * Hertz's figures of a NURBS slave with mortar, read off its points (the
   * arc's Greville points, one per control point A). A point's pressure is
   * its multiplier lambda_A, its normal reaction over int R_A dA: with the
   * dual basis the coefficient is the pressure about A, as a Q4 node's
   * force over its tributary length is (tests/mortar_test.cc), per
   * reference length; over the arc's stretch ds / dS there, the Cauchy
   * pressure Hertz speaks of. The load per unit length P = 2 sum f_y (the
   * quarter model); the half-width from the second moment, sum f_y x^2 /
   * sum f_y = a^2 / 4 for p = p0 sqrt(1 - x^2 / a^2); p0 at the point on
   * the axis. Inside 0.9 a, the largest |p_A - Hertz(x_A)| / p0 and the
   * largest point-to-point oscillation of that error, |e_k - (e_k-1 +
   * e_k+1) / 2| / p0, with Hertz's a and p0 at the measured load.
   */
  HertzFigures
  hertz_figures(const ContactPair &pair,
                const double       reduced_modulus,
                HertzFigures      &hertz)
  {
    const Body &body = pair.slave();
    const auto &u    = body.displacement();
    double      sum = 0., moment = 0.;
    for (const ContactNode &node : pair.nodes())
      {
        const double x = node.reference_position[0] + node.displacement(u)[0];
        sum += node.force()[1];
        moment += node.force()[1] * x * x;
      }
    HertzFigures measured;
    measured.load       = 2. * sum;
    measured.half_width = 2. * std::sqrt(moment / sum);
    hertz.load          = measured.load;
    hertz.half_width    = std::sqrt(4. * hertz.load / (M_PI * reduced_modulus));
    hertz.peak_pressure = 2. * hertz.load / (M_PI * hertz.half_width);
    const double a = hertz.half_width, p0 = hertz.peak_pressure;

    // The slave arc as the pair built it (its points are the curve's
    // Greville points in order), for the stretch at each point.
    const NurbsBoundary arc = NurbsBoundary::build(
      dynamic_cast<const NurbsSpace &>(body.space()),
      MasterChain::build(body, "arc", "Contact touch/Slave boundary"));
    NurbsCurve &curve    = *arc.curve;
    const auto  greville = curve.greville_points();
    check(greville.size() == pair.nodes().size(),
          "a slave point per control point of the arc");
    std::vector<MasterCurve::Point> reference(curve.n_controls()),
      current(curve.n_controls());
    for (unsigned int k = 0; k < curve.n_controls(); ++k)
      {
        const Point<2> X = arc.control_points[k];
        reference[k]     = {{X[0], X[1]}};
        current[k]       = {
                {X[0] + u(arc.control_dofs[k][0]), X[1] + u(arc.control_dofs[k][1])}};
      }
    const auto speed = [&](const std::vector<MasterCurve::Point> &controls,
                           const unsigned int                     g) {
      curve.update(controls);
      const auto dx = curve.derivative(greville[g].segment, greville[g].s);
      return std::hypot(dx[0], dx[1]);
    };
    std::vector<std::pair<double, double>> along; // x, pressure
    for (unsigned int g = 0; g < greville.size(); ++g)
      {
        const ContactNode &node = pair.nodes()[g];
        curve.update(reference);
        const auto X = curve.value(greville[g].segment, greville[g].s);
        check(std::hypot(X[0] - node.reference_position[0],
                         X[1] - node.reference_position[1]) < 1e-12,
              "the slave points are the arc's Greville points");
        along.emplace_back(node.reference_position[0] + node.displacement(u)[0],
                           node.reaction[1] / node.collocation_area *
                             speed(reference, g) / speed(current, g));
      }
    std::sort(along.begin(), along.end());
    measured.peak_pressure = along[0].second;
    std::vector<double> error;
    for (const auto &[x, p] : along)
      error.push_back(p - p0 * std::sqrt(std::max(0., 1. - x * x / (a * a))));
    for (unsigned int k = 0; k + 1 < along.size(); ++k)
      if (along[k].first < 0.9 * a)
        {
          // (the point on the axis: its mirror image has the error of its
          // neighbour)
          const double before = k > 0 ? error[k - 1] : error[1];
          measured.profile_error =
            std::max(measured.profile_error, std::abs(error[k]) / p0);
          measured.oscillation =
            std::max(measured.oscillation,
                     std::abs(error[k] - 0.5 * (before + error[k + 1])) / p0);
        }
    return measured;
  }
} // namespace

// The target: p0 and a within 1 % of Hertz's and the pressure's
// point-to-point oscillation below 1 % of p0 inside 0.9 a, with mortar for
// degrees 2 and 3; the contact load equal to the support's reaction.
// Knot-to-segment (the Greville points, collocation areas) on the same
// patches is printed beside it.
GLISSADE_TEST(nurbs_contact_hertz_cylinder_on_flat)
{
  for (const auto &[degree, discretisation] :
       std::vector<std::pair<unsigned int, std::string>>{
         {2, "mortar"}, {3, "mortar"}, {2, "node-to-segment"}})
    {
      const std::string p = std::to_string(degree);
      Simulation        simulation(SceneReader::read_file(
        source_path("prm/hertz_cylinder_nurbs.prm"),
        {"Body cylinder/Mesh/File=meshes/quarter_disk_p" + p + ".nurbs",
                "Body cylinder/Element/Degree=" + p,
                "Body block/Element/Degree=" + p,
                "Contact touch/Discretisation=" + discretisation,
                "Output/Directory=nurbs_hertz_cylinder_p" + p,
                "Output/VTU interval=0",
                "Output/Progress=false"}));
      simulation.run();
      const ContactPair &pair   = *simulation.contact().contact_pairs()[0];
      const double       E_star = 200. / (2. * (1. - 0.3 * 0.3));
      HertzFigures       hertz;
      const HertzFigures measured = hertz_figures(pair, E_star, hertz);
      const double       reaction =
        support_reaction(simulation.body("cylinder"), "top")[1];
      std::cout << "  p = " << degree << ", " << discretisation
                << ": P = " << measured.load << " (support " << -2. * reaction
                << "), a = " << measured.half_width << " (Hertz "
                << hertz.half_width << "), p0 = " << measured.peak_pressure
                << " (Hertz " << hertz.peak_pressure
                << "); inside 0.9 a: largest |p - Hertz| / p0 "
                << measured.profile_error << ", largest oscillation / p0 "
                << measured.oscillation << std::endl;
      check_relative(measured.load,
                     -2. * reaction,
                     1e-9,
                     "p = " + p + ": contact load against the support");
      if (discretisation != "mortar")
        continue;
      check(hertz.half_width > 0.04 && hertz.half_width < 0.06,
            "a / R is not about 0.05");
      check_relative(measured.half_width, hertz.half_width, 1e-2, "a");
      check_relative(measured.peak_pressure, hertz.peak_pressure, 1e-2, "p0");
      check(measured.oscillation <= 1e-2,
            "p = " + p + ": the pressure oscillates by more than 1 % of p0");
    }
}
