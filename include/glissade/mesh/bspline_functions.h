#pragma once

#include <vector>

namespace glissade
{
  /**
   * The degree + 1 B-spline functions nonzero on the knot span
   * [U[i], U[i + 1]) at u, and their first and second derivatives (Piegl &
   * Tiller, The NURBS Book, 1997, algorithm A2.3). Only the knots
   * U[i + 1 - degree], ..., U[i + degree] are read, so a curve may keep just
   * the 2 degree knots around each of its spans (NurbsCurve). Without
   * deal.II, so that the master curves (glissade_core) use it as the patches
   * (BSplineBasis) do.
   */
  void
  bspline_functions_on_span(unsigned int               degree,
                            const std::vector<double> &U,
                            unsigned int               i,
                            double                     u,
                            std::vector<double>       &values,
                            std::vector<double>       &first_derivatives,
                            std::vector<double>       &second_derivatives);
} // namespace glissade
