// Cases 1 and 2 of the paper (sections 4.1, 4.2), checked against what
// the paper states and against references that do not come from the code:
// the exact circle of a rigid ring, mirror symmetry, and the smoothness of
// a history (a smooth curve's second differences shrink like the square of
// the increment; a jump in the slope does not).

#include <paper_studies/contact_case_study.h>

#include <algorithm>
#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  double
  largest(const std::vector<double> &values)
  {
    return *std::max_element(values.begin(), values.end());
  }
} // namespace

// Case 1, rigid ring (fig 16): at every increment no beam node is inside
// the exact circle, and the nodes that carry a force lie on it.
GLISSADE_TEST(case1_rigid_ring_no_penetration)
{
  const ContactCaseResult r = ContactCaseStudy::run_variant(
    source_path("prm/case1_rigid_ring.prm"), "q4", 0, 1., "case1_test");
  const double deepest = -*std::min_element(r.min_obstacle_distance.begin(),
                                            r.min_obstacle_distance.end());
  unsigned int loaded  = 0;
  for (const auto &[x, f] : r.contact_forces)
    loaded += f.norm() > 0. ? 1 : 0;
  std::cout << "  " << r.increments << " increments, deepest penetration "
            << std::max(deepest, 0.)
            << " m, loaded nodes off the circle by <= " << r.max_active_distance
            << " m, " << loaded << " beam nodes loaded at the end" << std::endl;
  check(r.min_obstacle_distance.size() == r.increments,
        "one measure per increment");
  check(deepest <= 1e-10, "a beam node penetrates the rigid ring");
  check(r.max_active_distance <= 1e-10, "a loaded node is off the circle");
  check(loaded >= 2, "the beam should rest on the ring");
}

// Case 1, flexible ring (fig 17): B-spline and Hermite give the same
// deformed structures. Shortened to 20 increments (the full run: 50).
GLISSADE_TEST(case1_flexible_ring_bspline_hermite_agree)
{
  const auto run = [](const std::string &variant) {
    return ContactCaseStudy::run_variant(
      source_path("prm/case1_beam_ring.prm"), variant, 20, 1., "case1_test");
  };
  const ContactCaseResult q4 = run("q4"), bspline = run("bspline"),
                          hermite = run("hermite");
  const double b_h = ContactCaseStudy::final_difference(hermite, bspline);
  const double q_h = ContactCaseStudy::final_difference(hermite, q4);
  std::cout << "  final displacement, largest difference over the largest "
               "displacement: B-spline vs Hermite "
            << b_h * 100. << " %, Q4 vs Hermite " << q_h * 100. << " %"
            << std::endl;
  // The paper (section 4.1): no difference is visible between the linear
  // mesh and either smoothing, and B-spline and Hermite match. The bodies
  // differ (Q4 against Hermite elements): at 120 x 8 the paper's Table 1
  // puts Q4 and H4 0.7 % apart, so 2 % is the element's share. (With the
  // frame frozen over an increment, B-spline came out closer to Hermite
  // than Q4, 0.98 against 1.03 %; solved in the true frame the order is
  // the other one, 1.40 against 0.77 %, and 1.40 against 1.22 % since the
  // faceted master's vertices carry their normal cone: the three agree
  // within the element's share, which is what the paper claims.)
  check(b_h < 0.02, "B-spline and Hermite should agree within 2 %");
  check(q_h < 0.02, "Q4 and Hermite should agree within 2 %");
}

// Case 2, symmetry configuration (fig 19): mirror nodes have mirror
// displacements and contact forces, to 1e-8 relative.
GLISSADE_TEST(case2_symmetry)
{
  for (const std::string variant : {"q4", "bspline", "hermite"})
    {
      const ContactCaseResult r = ContactCaseStudy::run_variant(
        source_path("prm/case2_symmetry.prm"), variant, 20, 0.5, "case2_test");
      const double u = largest(r.symmetry_displacement),
                   f = largest(r.symmetry_force);
      std::cout << "  " << variant << ": symmetry error of u " << u << ", of f "
                << f << " (largest over " << r.increments << " increments)"
                << std::endl;
      check(u <= 1e-8 && f <= 1e-8, variant + ": not symmetric to 1e-8");
      check(largest(r.corner_force) > 0.,
            variant + ": the square never touched");
    }
}

// Case 2, large sliding (figs 20-23): the corner node's contact force jumps
// in slope with Q4 as the node passes the master's vertices; with
// smoothing it does not. The run covers the contact phase at the paper's
// resolution (0.0001 m of push per increment, 250 increments). The
// Hermite run is the suite's longest (about 4 minutes).
GLISSADE_TEST(case2_sliding_smoothness)
{
  std::vector<ContactCaseResult> runs;
  for (const std::string variant : {"q4", "bspline", "hermite"})
    runs.push_back(ContactCaseStudy::run_variant(
      source_path("prm/case2_sliding.prm"), variant, 250, 0.5, "case2_test"));
  std::vector<double> force_roughness, kinks;
  for (const auto &r : runs)
    {
      const auto [first, last] = ContactCaseStudy::contact_phase(r);
      force_roughness.push_back(ContactCaseStudy::roughness(
        r.corner_force, first + 2, last - 1, r.active_nodes));
      kinks.push_back(
        ContactCaseStudy::kink_concentration(r.corner_ux, first + 2, last - 1));
      std::cout << "  " << r.variant << ": corner in contact over increments "
                << first + 1 << "-" << last << "; force roughness "
                << force_roughness.back()
                << ", share of |d2 u_x| in the top 10 % " << kinks.back()
                << std::endl;
    }
  std::cout << "  roughness ratio Q4 / B-spline "
            << force_roughness[0] / force_roughness[1] << ", Q4 / Hermite "
            << force_roughness[0] / force_roughness[2] << std::endl;
  check(force_roughness[0] >= 10. * force_roughness[1],
        "B-spline force history should be 10x smoother than Q4's");
  check(force_roughness[0] >= 10. * force_roughness[2],
        "Hermite force history should be 10x smoother than Q4's");
  check(kinks[0] > kinks[1] && kinks[0] > kinks[2],
        "Q4's u_x should be more piecewise linear");
}
