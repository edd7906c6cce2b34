#pragma once

// Case 3's rings under the compression alone, against the closed form:
// with frictionless contact at coincident nodes and a radial load, the two
// rings carry it like one Lame ring a = 0.5, b = 2 clamped at r = a, under
// the pressure p = 400 / (2 pi b) of the 400 N of radial nodal forces.
// Shared by the tests that check a way of solving the contact against it.

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <glissade/body/body.h>
#include <glissade/body/body_measures.h>

#include <cmath>

namespace glissade_tests
{
  /** Lame's ring, small strain (the load strains the rings by about 1e-3). */
  struct LameRings
  {
    double u_outer;            // u_r(b)
    double interface_pressure; // -sigma_rr(c), c = 1.25

    explicit LameRings(const double E)
    {
      const double nu = 0.3, a = 0.5, b = 2., c = 1.25;
      const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      const double mu     = E / (2. * (1. + nu));
      const double p      = 400. / (2. * M_PI * b);
      // u = A (r - a^2 / r), sigma_rr = 2 (lambda + mu) A + 2 mu A a^2 / r^2.
      const double A = -p / (2. * (lambda + mu) + 2. * mu * a * a / (b * b));
      u_outer        = A * (b - a * a / b);
      interface_pressure =
        -A * (2. * (lambda + mu) + 2. * mu * a * a / (c * c));
    }
  };

  /** Mean u_r over the 40 nodes of radius r (case 3's meshes). */
  inline double
  mean_radial_displacement(const glissade::Body &body, const double r)
  {
    double sum = 0.;
    for (unsigned int i = 0; i < 40; ++i)
      {
        const double               theta = 2. * M_PI * i / 40.;
        const dealii::Point<2>     X(r * std::cos(theta), r * std::sin(theta));
        const dealii::Tensor<1, 2> d = vertex_displacement(body, X);
        sum += (d[0] * X[0] + d[1] * X[1]) / r;
      }
    return sum / 40.;
  }
} // namespace glissade_tests
