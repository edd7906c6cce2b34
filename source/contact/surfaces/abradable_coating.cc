// An abradable coating's worn profile
// (include/glissade/contact/surfaces/abradable_coating.h).

#include <glissade/contact/surfaces/abradable_coating.h>

#include <algorithm>
#include <cmath>

namespace glissade
{
  namespace
  {
    constexpr double two_pi = 6.283185307179586476925286766559;

    /** psi in [0, 2 pi). */
    double
    wrapped(const double psi)
    {
      const double w = std::fmod(psi, two_pi);
      return w < 0. ? w + two_pi : w;
    }
  } // namespace



  AbradableCoating::AbradableCoating(const double       thickness,
                                     const double       yield_pressure,
                                     const unsigned int cells)
    : layer_thickness(thickness)
    , pressure(yield_pressure)
    , depth(cells, 0.)
  {}



  std::array<double, 3>
  AbradableCoating::worn(const double psi) const
  {
    const unsigned int n = depth.size();
    const double       h = two_pi / n;
    const double       x = wrapped(psi) / h;
    const unsigned int k = std::min(n - 1, static_cast<unsigned int>(x));
    const double       s = x - k;
    // Catmull-Rom on w_k-1, w_k, w_k+1, w_k+2 (periodic): C1
    const double p0 = depth[(k + n - 1) % n], p1 = depth[k],
                 p2 = depth[(k + 1) % n], p3 = depth[(k + 2) % n];
    const double a = -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3;
    const double b = p0 - 2.5 * p1 + 2. * p2 - 0.5 * p3;
    const double c = -0.5 * p0 + 0.5 * p2;
    return {{((a * s + b) * s + c) * s + p1,
             ((3. * a * s + 2. * b) * s + c) / h,
             (6. * a * s + 2. * b) / (h * h)}};
  }



  void
  AbradableCoating::wear_along(
    const double                         psi_0,
    const double                         rho_0,
    const double                         psi_1,
    const double                         rho_1,
    const std::function<double(double)> &casing_radius)
  {
    const unsigned int n = depth.size();
    const double       h = two_pi / n;
    // The shorter way from psi_0 to psi_1.
    double sweep = wrapped(psi_1 - psi_0);
    if (sweep > 0.5 * two_pi)
      sweep -= two_pi;
    const double start   = std::min(psi_0, psi_0 + sweep),
                 end     = std::max(psi_0, psi_0 + sweep);
    const auto radius_at = [&](const double psi) {
      return sweep == 0. ? std::max(rho_0, rho_1) :
                           rho_0 + (rho_1 - rho_0) * (psi - psi_0) / sweep;
    };
    // Every cell angle within the path, and the path's two ends' cells.
    const long first = static_cast<long>(std::ceil(start / h)),
               last  = static_cast<long>(std::floor(end / h));
    std::vector<std::pair<long, double>> visited;
    for (long j = first; j <= last; ++j)
      visited.emplace_back(j, radius_at(j * h));
    visited.emplace_back(std::lround(psi_0 / h), rho_0);
    visited.emplace_back(std::lround((psi_0 + sweep) / h), rho_1);
    for (const auto &[j, rho] : visited)
      {
        const unsigned int cell = ((j % long(n)) + long(n)) % long(n);
        const double       surface_at_casing = casing_radius(cell * h);
        const double       cut = rho - (surface_at_casing - layer_thickness);
        depth[cell] = std::max(depth[cell], std::min(layer_thickness, cut));
      }
  }



  double
  AbradableCoating::removed_area(
    const std::function<double(double)> &casing_radius) const
  {
    const unsigned int n    = depth.size();
    const double       h    = two_pi / n;
    double             area = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double inner = casing_radius(k * h) - layer_thickness;
        area += 0.5 * (std::pow(inner + depth[k], 2) - inner * inner) * h;
      }
    return area;
  }
} // namespace glissade
