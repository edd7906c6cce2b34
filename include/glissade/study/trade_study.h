#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /**
   * The speed-accuracy trade (`Study = trade`): the paper's question "how
   * fine must plain Q4 be to match B-spline or Hermite", answered in
   * figures. On case 3 (the concentric rings) it runs every discretisation
   * of the interface (Q4, Q4 + B-spline, Hermite) at every number of
   * elements around the rings it is given, over the same rotation, and
   * records for each point the dofs, the Newton iterations, the active
   * contact nodes, the wall time and the accuracy (the worst spread of the
   * contact forces around their equilibrium value, which is 0 for the
   * exact circle). It writes trade_case3.csv, a Pareto picture (spread
   * against time) and prints the cross-overs: the cheapest Q4 mesh that
   * matches each smoothed discretisation, and what it costs.
   */
  class TradeStudy
  {
  public:
    /** Reads the study's .prm, runs the sweep, writes CSV and PNG. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
