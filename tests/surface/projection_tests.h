// The projection groups of surface_tests, defined in projection_tests.cc.
#pragma once

namespace surface_test_tools
{
  // The projection is at least as close as any sampled curve point, and is
  // an orthogonal projection unless flagged otherwise.
  void
  test_projection_is_closest();

  // Convergence of the projection on an N-node circle, at the interpolation
  // order of each kind of curve, and of an open B-spline on a half circle.
  void
  test_circle_convergence();

  // The awkward cases: no NaN, flags as documented, bounded iterations.
  void
  test_projection_robustness();
} // namespace surface_test_tools
