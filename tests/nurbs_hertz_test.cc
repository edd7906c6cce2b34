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

#include "hertz_line_contact.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /**
   * A NURBS slave's points (the arc's Greville points, one per control
   * point A) as Hertz's points. A point's pressure is its multiplier
   * lambda_A, its normal reaction over int R_A dA: with the dual basis
   * the coefficient is the pressure about A, as a Q4 node's force over its
   * tributary length is (tests/mortar_test.cc), per reference length; over
   * the arc's stretch ds / dS there, the Cauchy pressure Hertz speaks of.
   */
  std::vector<HertzPoint>
  slave_points(const ContactPair &pair)
  {
    const Body &body = pair.slave();
    const auto &u    = body.displacement();
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
    std::vector<HertzPoint> points;
    for (unsigned int g = 0; g < greville.size(); ++g)
      {
        const ContactNode &node = pair.nodes()[g];
        curve.update(reference);
        const auto X = curve.value(greville[g].segment, greville[g].s);
        check(std::hypot(X[0] - node.reference_position[0],
                         X[1] - node.reference_position[1]) < 1e-12,
              "the slave points are the arc's Greville points");
        points.push_back({node.reference_position[0] + node.displacement(u)[0],
                          node.force()[1],
                          node.reaction[1] / node.collocation_area *
                            speed(reference, g) / speed(current, g)});
      }
    std::sort(points.begin(),
              points.end(),
              [](const HertzPoint &a, const HertzPoint &b) {
                return a.x < b.x;
              });
    return points;
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
      const HertzFigures measured =
        hertz_line_contact(slave_points(pair), E_star, hertz);
      const double reaction =
        support_reaction(simulation.body("cylinder"), "top")[1];
      std::cout << "  p = " << degree << ", " << discretisation << ": "
                << describe(measured, hertz, -2. * reaction) << std::endl;
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
