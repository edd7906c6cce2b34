#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /**
   * The speed-accuracy trade (`Study = trade`): the paper's question "how
   * fine must plain Q4 be to match B-spline or Hermite", answered in
   * figures on each of the paper's measures of accuracy (TradeMeasures):
   * the geometric gap and normal errors, Table 1's displacement, case 1's
   * tip displacement, case 2's force smoothness and case 3's force spread.
   * For every measure it sweeps the discretisations and mesh sizes the
   * .prm gives; each point runs in its own process, so that its peak
   * memory is its own. It writes trade_<measure>.csv, a Pareto picture per
   * measure (error against wall time and dofs), trade_tables.md, and
   * prints the tables and the cross-overs: the cheapest Q4 mesh that
   * matches each other point, or beyond the sweep the power laws fitted to
   * the Q4 points.
   */
  class TradeStudy
  {
  public:
    /** Reads the study's .prm, runs the sweep, writes CSV and PNG. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
