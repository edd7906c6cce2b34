// The B-spline functions on one span
// (include/glissade/mesh/bspline_functions.h).

#include <glissade/mesh/bspline_functions.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace glissade
{
  void
  bspline_functions_on_span(const unsigned int         degree,
                            const std::vector<double> &U,
                            const unsigned int         i,
                            const double               u,
                            std::vector<double>       &values,
                            std::vector<double>       &first_derivatives,
                            std::vector<double>       &second_derivatives)
  {
    const unsigned int p = degree;
    // (on the stack: the curves evaluate this at every Gauss point and
    // Newton step of the contact search)
    constexpr unsigned int max_degree = 10;
    if (p > max_degree)
      throw std::invalid_argument("B-spline functions of degree " +
                                  std::to_string(p) + " (at most " +
                                  std::to_string(max_degree) + ")");
    // Piegl & Tiller's A2.3: the triangle ndu of the functions of every
    // degree up to p and the knot differences, then the derivatives from
    // it.
    using Row = std::array<double, max_degree + 1>;
    std::array<Row, max_degree + 1> ndu{};
    Row                             left{}, right{};
    std::array<Row, 2>              a{};
    const unsigned int              n_derivatives = std::min(2u, p);
    std::array<Row, 3>              ders{};
    ndu[0][0] = 1.;
    for (unsigned int j = 1; j <= p; ++j)
      {
        left[j]      = u - U[i + 1 - j];
        right[j]     = U[i + j] - u;
        double saved = 0.;
        for (unsigned int r = 0; r < j; ++r)
          {
            ndu[j][r]         = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j]         = saved + right[r + 1] * temp;
            saved             = left[j - r] * temp;
          }
        ndu[j][j] = saved;
      }
    for (unsigned int j = 0; j <= p; ++j)
      ders[0][j] = ndu[j][p];
    for (int r = 0; r <= int(p); ++r)
      {
        unsigned int s1 = 0, s2 = 1;
        a[0][0] = 1.;
        for (int k = 1; k <= int(n_derivatives); ++k)
          {
            double    d  = 0.;
            const int rk = r - k, pk = int(p) - k;
            if (r >= k)
              {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d        = a[s2][0] * ndu[rk][pk];
              }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : int(p) - r;
            for (int j = j1; j <= j2; ++j)
              {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
              }
            if (r <= pk)
              {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
              }
            ders[k][r] = d;
            std::swap(s1, s2);
          }
      }
    double factor = p;
    for (unsigned int k = 1; k <= n_derivatives; ++k)
      {
        for (unsigned int j = 0; j <= p; ++j)
          ders[k][j] *= factor;
        factor *= double(p) - double(k);
      }
    values.assign(ders[0].begin(), ders[0].begin() + p + 1);
    first_derivatives.assign(ders[1].begin(), ders[1].begin() + p + 1);
    second_derivatives.assign(ders[2].begin(), ders[2].begin() + p + 1);
  }

} // namespace glissade
