// The Hertz group of bipotential_tests (not a test: it prints timings; the
// benchmark target runs it), defined in bipotential_hertz_timing.cc.
#pragma once

namespace test_helpers
{
  // A rigid cylinder on an elastic half-plane: the contact load and peak
  // pressure against Hertz's solution, and the time of the local solver for
  // n = 100, 500, 2000 nodes.
  void
  test_hertz_and_timing();
} // namespace test_helpers
