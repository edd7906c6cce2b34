// Small helpers shared by bipotential_tests.cc: the check counter, number
// formatting and tiny problem builders.

#pragma once

#include <glissade/contact/local_solvers/bipotential_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../harness.h"

namespace test_helpers
{
  using glissade::BiPotentialSolver;
  using glissade::ComplianceMatrix;
  using Vector2    = BiPotentialSolver::Vector2;
  using NodeStatus = BiPotentialSolver::NodeStatus;

  /** A line of the test's table (glissade_tests::expect). */
  inline void
  check(const bool passed, const std::string &what)
  {
    glissade_tests::expect(passed, what);
  }

  inline std::string
  format(const char  *pattern,
         const double a,
         const double b = 0.,
         const double c = 0.,
         const double d = 0.)
  {
    char buffer[512];
    std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
    return buffer;
  }

  inline double
  max_difference(const std::vector<Vector2> &a, const std::vector<Vector2> &b)
  {
    double result = 0.;
    for (std::size_t k = 0; k < a.size(); ++k)
      result = std::max(
        {result, std::abs(a[k][0] - b[k][0]), std::abs(a[k][1] - b[k][1])});
    return result;
  }

  inline double
  max_abs(const std::vector<Vector2> &a)
  {
    double result = 0.;
    for (const Vector2 &v : a)
      result = std::max({result, std::abs(v[0]), std::abs(v[1])});
    return result;
  }

  inline ComplianceMatrix
  single_node(const double w_tt, const double w_tn, const double w_nn)
  {
    ComplianceMatrix W(1);
    W.set_block(0, 0, {{{{w_tt, w_tn}}, {{w_tn, w_nn}}}});
    return W;
  }

  // Closed forms are checked to 1e-12, so these tests iterate to round-off
  // rather than to the default relative tolerance of 1e-10.
  inline BiPotentialSolver
  tight_solver()
  {
    BiPotentialSolver::Settings settings;
    settings.change_tolerance   = 1e-14;
    settings.residual_tolerance = 1e-14;
    return BiPotentialSolver(settings);
  }

  inline const char *
  name(const NodeStatus status)
  {
    return status == NodeStatus::open  ? "open" :
           status == NodeStatus::stick ? "stick" :
                                         "slip";
  }

} // namespace test_helpers
