#pragma once

#include <cmath>
#include <vector>

namespace glissade
{
  /**
   * The n + 1 ends of n intervals that split [0, 1] with sizes in
   * geometric progression, the last `ratio` times the first (Mesh/Grading;
   * ratio 1: equal intervals). The ends are exactly 0 and 1.
   */
  inline std::vector<double>
  graded_interval_ends(const unsigned int n, const double ratio)
  {
    std::vector<double> ends(n + 1, 0.);
    const double        growth = n > 1 ? std::pow(ratio, 1. / (n - 1.)) : 1.;
    double              size = 1., total = 0.;
    for (unsigned int i = 0; i < n; ++i, size *= growth)
      {
        total += size;
        ends[i + 1] = total;
      }
    for (double &end : ends)
      end /= total;
    ends[n] = 1.;
    return ends;
  }
} // namespace glissade
