#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace glissade_tests
{
  /** Hertz's figures of a plane (line) contact, measured or closed form. */
  struct HertzFigures
  {
    double load = 0., half_width = 0., peak_pressure = 0.;
    /** Inside 0.9 a: the largest |p - Hertz| / p0, and the largest
     *  point-to-point oscillation of that error over p0. */
    double profile_error = 0., oscillation = 0.;
  };

  /** One slave point of a quarter model: its current x (0 on the axis),
   *  its force's y component and its pressure. */
  struct HertzPoint
  {
    double x, force, pressure;
  };

  /**
   * Hertz's figures of a cylinder pressed on a flat, read off the slave
   * points of a quarter model (x >= 0), sorted by x, the first on the
   * axis, whose pressure the caller gives for the whole of it: the load
   * per unit length P = 2 sum f; the half-width from the second moment,
   * sum f x^2 / sum f = a^2 / 4 for p = p0 sqrt(1 - x^2 / a^2); the peak
   * pressure the axis point's. `hertz` gets the closed form at the
   * measured load (plane strain, radius R: a = sqrt(4 P R / (pi E*)), p0 =
   * 2 P / (pi a)); inside 0.9 a, the largest |p_k - Hertz(x_k)| / p0 and
   * the largest oscillation of that error, |e_k - (e_k-1 + e_k+1) / 2| /
   * p0 (Hertz's own curvature taken out; the axis point's mirror image
   * has its neighbour's error).
   */
  inline HertzFigures
  hertz_line_contact(const std::vector<HertzPoint> &points,
                     const double                   reduced_modulus,
                     HertzFigures                  &hertz,
                     const double                   radius = 1.)
  {
    HertzFigures measured;
    double       sum = 0., moment = 0.;
    for (const HertzPoint &point : points)
      {
        sum += point.force;
        moment += point.force * point.x * point.x;
      }
    measured.load          = 2. * sum;
    measured.half_width    = 2. * std::sqrt(moment / sum);
    measured.peak_pressure = points.front().pressure;
    hertz.load             = measured.load;
    hertz.half_width =
      std::sqrt(4. * hertz.load * radius / (M_PI * reduced_modulus));
    hertz.peak_pressure   = 2. * hertz.load / (M_PI * hertz.half_width);
    const double        a = hertz.half_width, p0 = hertz.peak_pressure;
    std::vector<double> error;
    for (const HertzPoint &point : points)
      error.push_back(
        point.pressure -
        p0 * std::sqrt(std::max(0., 1. - point.x * point.x / (a * a))));
    for (unsigned int k = 0; k + 1 < points.size(); ++k)
      if (points[k].x < 0.9 * a)
        {
          const double before = k > 0 ? error[k - 1] : error[1];
          measured.profile_error =
            std::max(measured.profile_error, std::abs(error[k]) / p0);
          measured.oscillation =
            std::max(measured.oscillation,
                     std::abs(error[k] - 0.5 * (before + error[k + 1])) / p0);
        }
    return measured;
  }

  /** One line of the measured figures beside Hertz's, and the support's
   *  load (twice the quarter's reaction) beside the contact's. */
  inline std::string
  describe(const HertzFigures &measured,
           const HertzFigures &hertz,
           const double        support_load)
  {
    std::ostringstream out;
    out.precision(10);
    out << "P = " << measured.load << " (support " << support_load
        << "), a = " << measured.half_width << " (Hertz " << hertz.half_width
        << "), p0 = " << measured.peak_pressure << " (Hertz "
        << hertz.peak_pressure << "); inside 0.9 a: largest |p - Hertz| / p0 "
        << measured.profile_error << ", largest oscillation / p0 "
        << measured.oscillation;
    return out.str();
  }
} // namespace glissade_tests
