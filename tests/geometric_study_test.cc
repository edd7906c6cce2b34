// The geometric study of section 3.3 against closed forms and theory:
// - Q4's largest gap error is the chord's sagitta, 1 - cos(pi / (2 n_e));
// - Q4's normal jumps at theta = pi/2 by the angle between two chords,
//   pi / n_e; Q8 and Q12 jump too; B-spline and Hermite do not (C1);
// - Q12 stays within about 1e-4 % of the radius (the paper's figure 13);
// - the largest errors converge at the orders interpolation theory gives
//   for a circle: degree-1 interpolation O(h^2) in position and O(h) in
//   normal; quadratic (Q8), cubic (Q12), cubic B-spline and cubic Hermite
//   O(h^4) in the radial direction (for Q8 the O(h^3) error term is
//   d^3X/dtheta^3, tangential on a circle) and O(h^3) in the normal.

#include <glissade/contact/curves/lagrange_edge_curve.h>

#include <paper_studies/geometric_study.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace glissade_tests;

namespace
{
  const std::vector<unsigned int> paper_counts =
    {16, 18, 20, 22, 24, 26, 28, 30};
}

GLISSADE_TEST(geometric_study_q4_sagitta)
{
  for (const unsigned int n_e : paper_counts)
    {
      const auto samples = GeometricStudy::evaluate("q4", n_e, 41);
      check_relative(GeometricStudy::max_gap_error_percent(samples),
                     100. * (1. - std::cos(M_PI / (2. * n_e))),
                     n_e == 30 ? 0.01 : 1e-6,
                     "Q4 max |g| (%), n_e = " + std::to_string(n_e));
    }
  // The paper's figure: 0.13 % at n_e = 30; the sagitta is 0.137 %.
  const double at_30 = GeometricStudy::max_gap_error_percent(
    GeometricStudy::evaluate("q4", 30, 41));
  check_relative(at_30, 0.137, 0.01, "Q4 max |g| at n_e = 30 vs 0.137 %");
}

GLISSADE_TEST(geometric_study_normal_continuity)
{
  for (const unsigned int n_e : paper_counts)
    {
      const double q4 = std::abs(GeometricStudy::normal_jump_degrees(
        GeometricStudy::evaluate("q4", n_e, 41)));
      check_relative(q4 * M_PI / 180.,
                     M_PI / n_e,
                     1e-12,
                     "Q4 normal jump at pi/2 (rad), n_e = " +
                       std::to_string(n_e));
      for (const std::string method : {"q8", "q12"})
        {
          const double jump = std::abs(GeometricStudy::normal_jump_degrees(
            GeometricStudy::evaluate(method, n_e, 41)));
          std::cout << "  " << method << " normal jump at pi/2: " << jump
                    << " degrees" << std::endl;
          check(jump > 1e-4, method + " should jump at pi/2");
        }
      for (const std::string method : {"bspline", "hermite"})
        {
          const double jump = std::abs(GeometricStudy::normal_jump_degrees(
            GeometricStudy::evaluate(method, n_e, 41)));
          std::cout << "  " << method << " normal jump at pi/2: " << jump
                    << " degrees" << std::endl;
          check(jump < 1e-10, method + " must be C1 at pi/2");
        }
    }
}

GLISSADE_TEST(geometric_study_q12_bound)
{
  for (const unsigned int n_e : paper_counts)
    {
      const double g = GeometricStudy::max_gap_error_percent(
        GeometricStudy::evaluate("q12", n_e, 41));
      std::cout << "  Q12 max |g| at n_e = " << n_e << ": " << g << " %"
                << std::endl;
      check(g <= 1e-4, "Q12 leaves the paper's 1e-4 % band");
    }
}

GLISSADE_TEST(geometric_study_convergence_orders)
{
  struct Expected
  {
    std::string method;
    double      gap_order;
    double      normal_order;
  };
  const std::vector<Expected> theory = {{"q4", 2, 1},
                                        {"q8", 4, 3},
                                        {"q12", 4, 3},
                                        {"bspline", 4, 3},
                                        {"hermite", 4, 3}};
  for (const auto &t : theory)
    {
      std::vector<double> gaps, normals;
      for (const unsigned int n_e : paper_counts)
        {
          const auto samples = GeometricStudy::evaluate(t.method, n_e, 41);
          gaps.push_back(GeometricStudy::max_gap_error_percent(samples));
          normals.push_back(GeometricStudy::max_normal_error_degrees(samples));
        }
      const double gap_order =
        GeometricStudy::convergence_order(paper_counts, gaps);
      const double normal_order =
        GeometricStudy::convergence_order(paper_counts, normals);
      std::cout << "  " << t.method << ": measured order of max |g| "
                << gap_order << " (theory " << t.gap_order
                << "), of max |dtheta| " << normal_order << " (theory "
                << t.normal_order << ")" << std::endl;
      // The B-spline's double-vertex ends are only O(h^2); their influence
      // decays by 2 - sqrt(3) per node and is still visible at n_e = 16.
      const double margin = (t.method == "bspline" ? 0.25 : 0.05);
      check(std::abs(gap_order - t.gap_order) <= margin,
            t.method + ": gap order differs from theory");
      check(std::abs(normal_order - t.normal_order) <= margin,
            t.method + ": normal order differs from theory");
    }
}

// The Q8/Q12 edge curve: it interpolates its nodes, reproduces polynomials
// of its degree exactly, its weights reproduce its points, and its Bezier
// box contains it.
GLISSADE_TEST(surface_lagrange_edge_curve)
{
  for (const unsigned int degree : {2u, 3u})
    {
      // Nodes on y = x^degree at x = 0, 1/p, ..., 3 (three segments).
      const auto f = [degree](const double x) { return std::pow(x, degree); };
      std::vector<MasterCurve::Point> vertices, edge;
      for (unsigned int i = 0; i <= 3; ++i)
        vertices.push_back({{double(i), f(i)}});
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 1; j < degree; ++j)
          {
            const double x = i + double(j) / degree;
            edge.push_back({{x, f(x)}});
          }
      LagrangeEdgeCurve curve(degree, false);
      curve.update(vertices, edge);
      double worst = 0., worst_weights = 0.;
      bool   inside = true;
      for (unsigned int segment = 0; segment < 3; ++segment)
        {
          MasterCurve::Point low, high;
          curve.bounding_box(segment, low, high);
          for (double s = 0.; s <= 1.; s += 0.05)
            {
              const auto c = curve.value(segment, s);
              worst        = std::max(worst,
                               std::abs(c[1] - f(c[0])) +
                                 std::abs(c[0] - (segment + s)));
              MasterCurve::NodeWeights w;
              curve.weights(segment, s, w);
              MasterCurve::Point sum = {{0., 0.}};
              for (const auto &[node, phi] : w)
                {
                  const auto &p = node < vertices.size() ?
                                    vertices[node] :
                                    edge[node - vertices.size()];
                  sum[0] += phi * p[0];
                  sum[1] += phi * p[1];
                }
              worst_weights =
                std::max(worst_weights,
                         std::hypot(sum[0] - c[0], sum[1] - c[1]));
              inside = inside && c[0] >= low[0] - 1e-12 &&
                       c[0] <= high[0] + 1e-12 && c[1] >= low[1] - 1e-12 &&
                       c[1] <= high[1] + 1e-12;
            }
        }
      std::cout << "  degree " << degree << ": distance from y = x^p: " << worst
                << ", weights vs value: " << worst_weights << std::endl;
      check(worst < 1e-12, "does not reproduce a polynomial of its degree");
      check(worst_weights < 1e-12, "weights do not reproduce the curve");
      check(inside, "the curve leaves its bounding box");
    }
}

// The NURBS row: the isogeometric half ring's outer side is the circle
// itself (rational weights), so its gap and normal errors are round-off at
// every n_e, and its normal does not jump at theta = pi/2 (C^(p-1) inside
// the patch).
GLISSADE_TEST(geometric_study_nurbs_exact)
{
  for (const std::string method : {"nurbs2", "nurbs3"})
    for (const unsigned int n_e : paper_counts)
      {
        const auto   samples = GeometricStudy::evaluate(method, n_e, 41);
        const double gap     = GeometricStudy::max_gap_error_percent(samples);
        const double normal = GeometricStudy::max_normal_error_degrees(samples);
        const double jump =
          std::abs(GeometricStudy::normal_jump_degrees(samples));
        std::cout << "  " << method << ", n_e = " << n_e << ": max |g| " << gap
                  << " %, max |dtheta| " << normal << " degrees, jump " << jump
                  << std::endl;
        expect(gap <= 1e-12 && normal <= 1e-10 && jump <= 1e-10,
               method + " at round-off, n_e = " + std::to_string(n_e));
      }
}
