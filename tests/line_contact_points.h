#pragma once

// The closed slave nodes of a plane (line) contact seen whole, on both
// sides of its centre, and Hertz's figures read off them: what the tests of
// a cylinder on a body (tests/cattaneo_mindlin_test.cc,
// tests/hertz_two_cylinders_test.cc) measure. (A quarter model's, one side
// of its axis: hertz_line_contact.h.)

#include <glissade/contact/contact_pair.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace glissade_tests
{
  /** A closed slave node: where it is along the contact, its tractions. */
  struct LineContactPoint
  {
    unsigned int node;
    /** From the centre of the normal reactions, along x. */
    double x, normal_reaction, pressure;
    /** Along x: positive where the master pushes the slave towards -x. */
    double shear;
    bool   sticks;
  };

  /** A contact's closed nodes, sorted along x, and Hertz's figures of it. */
  struct LineContact
  {
    std::vector<LineContactPoint> points;
    /** The normal reactions' sum, and the half-width from their second
     *  moment (sum r x^2 / sum r = a^2 / 4 for Hertz's profile). */
    double load = 0., half_width = 0.;
    /** The pressure at the node nearest the centre, and where it is. */
    double peak_pressure = 0., peak_x = 1e300;

    explicit LineContact(const glissade::ContactPair &pair)
    {
      using Status       = glissade::BiPotentialSolver::NodeStatus;
      const auto &u      = pair.slave().displacement();
      const auto  area   = pair.tributary_areas();
      double      moment = 0.;
      for (unsigned int k = 0; k < pair.nodes().size(); ++k)
        {
          const glissade::ContactNode &node = pair.nodes()[k];
          if (!node.active || node.status == Status::open || area[k] <= 0.)
            continue;
          const double x = node.reference_position[0] + node.displacement(u)[0];
          // r_t is along the node's tangent, which may point either way
          // along x.
          const double along = node.tangent[0] >= 0. ? 1. : -1.;
          points.push_back({k,
                            x,
                            node.reaction[1],
                            node.reaction[1] / area[k],
                            -along * node.reaction[0] / area[k],
                            node.status == Status::stick});
          load += node.reaction[1];
          moment += node.reaction[1] * x;
        }
      std::sort(points.begin(), points.end(), [](const auto &p, const auto &q) {
        return p.x < q.x;
      });
      const double centre   = moment / load;
      double       sum_r_x2 = 0.;
      for (LineContactPoint &point : points)
        {
          point.x -= centre;
          sum_r_x2 += point.normal_reaction * point.x * point.x;
          if (std::abs(point.x) < std::abs(peak_x))
            {
              peak_x        = point.x;
              peak_pressure = point.pressure;
            }
        }
      half_width = 2. * std::sqrt(sum_r_x2 / load);
    }

    /** Inside 0.9 a: the largest |p - p0 sqrt(1 - x^2 / a^2)| / p0. */
    double
    profile_error(const double a, const double p0) const
    {
      double largest = 0.;
      for (const LineContactPoint &point : points)
        if (std::abs(point.x) < 0.9 * a)
          largest = std::max(largest,
                             std::abs(point.pressure -
                                      p0 * std::sqrt(1. - point.x * point.x /
                                                            (a * a))) /
                               p0);
      return largest;
    }
  };

  /** Hertz's a and p0 of two cylinders (or a cylinder on a flat: R* = R)
   *  carrying P per unit length, E* their plane-strain modulus. */
  inline std::pair<double, double>
  hertz_cylinders(const double P,
                  const double reduced_radius,
                  const double E_star)
  {
    const double a = std::sqrt(4. * P * reduced_radius / (M_PI * E_star));
    return {a, 2. * P / (M_PI * a)};
  }
} // namespace glissade_tests
