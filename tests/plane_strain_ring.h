#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

namespace glissade_tests
{
  /**
   * The plane-strain reference of a thick ring A < R < B of compressible
   * neo-Hookean material (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
   * the law's definition, not the code's evaluation of it) under a
   * follower pressure p on its inner wall, at large strain: the radial
   * map R -> r = f(R), with principal stretches lambda_1 = f' (radial),
   * lambda_2 = f / R (hoop) and 1 (out of plane).
   *
   * Stationarity of int W(f', f / R) R dR gives (R W_1)' = W_2, with W_i =
   * dW / d lambda_i the nominal principal stresses. On the inner wall the
   * Cauchy radial stress is -p: W_1 = -p lambda_2, i.e. R W_1 = -p f(A);
   * the outer wall is free: W_1(B) = 0. In q = R W_1 and f this is a
   * first-order system (f' from W_1(f', f / R) = q / R by Newton's method,
   * W_1 rising in lambda_1), integrated by the classical Runge-Kutta
   * method from A, and f(A) found by the secant method so that q(B) = 0.
   * With `steps` steps the figures are exact to about steps^-4 (1e-13
   * at the default): far below any finite element mesh's error.
   */
  class PlaneStrainNeoHookeanRing
  {
  public:
    PlaneStrainNeoHookeanRing(const double       E,
                              const double       nu,
                              const double       A,
                              const double       B,
                              const double       pressure,
                              const unsigned int steps = 4000)
      : lambda(E * nu / ((1. + nu) * (1. - 2. * nu)))
      , mu(E / (2. * (1. + nu)))
      , A(A)
      , B(B)
      , p(pressure)
      , h((B - A) / steps)
    {
      // The small-strain answer to start from: Lame's u(A). (q(B) is found
      // to round-off of the stresses, mu's scale, not p's.)
      const double c = p * A * A / (B * B - A * A);
      double s0 = A + (1. + nu) / E * ((1. - 2. * nu) * c * A + c * B * B / A);
      double s1 = A + 1.05 * (s0 - A);
      double q0 = shoot(s0), q1 = shoot(s1);
      for (unsigned int k = 0; k < 60 && std::abs(q1) > 1e-13 * (p + mu) * A;
           ++k)
        {
          const double s2 = s1 - q1 * (s1 - s0) / (q1 - q0);
          s0              = s1;
          q0              = q1;
          s1              = s2;
          q1              = shoot(s1);
        }
      if (!(std::abs(q1) <= 1e-11 * (p + mu) * A))
        throw std::runtime_error("the ring's shooting did not converge");
      shoot(s1);
    }

    /** r = f(R), the current radius of the material circle R. */
    double
    radius(const double R) const
    {
      return hermite(R, false);
    }

    /** f'(R), the radial stretch. */
    double
    radial_stretch(const double R) const
    {
      return hermite(R, true);
    }

  private:
    double              lambda, mu, A, B, p, h;
    std::vector<double> f, df;

    /** dW / d lambda_1 at (l1, l2). */
    double
    W1(const double l1, const double l2) const
    {
      return mu * (l1 - 1. / l1) + lambda * std::log(l1 * l2) / l1;
    }

    /** The radial stretch at which W_1(l1, l2) = t. */
    double
    stretch_for(const double t, const double l2, double l1) const
    {
      for (unsigned int k = 0; k < 50; ++k)
        {
          const double slope = mu * (1. + 1. / (l1 * l1)) +
                               lambda * (1. - std::log(l1 * l2)) / (l1 * l1);
          const double step = (W1(l1, l2) - t) / slope;
          l1 -= step;
          if (std::abs(step) < 1e-16 * l1)
            break;
        }
      return l1;
    }

    /** (f', q') at (R, f, q): f' into `l1` (which holds a stretch to start
     *  Newton from), q' into `dq`. */
    void
    rates(const double R,
          const double fR,
          const double q,
          double      &l1,
          double      &dq) const
    {
      const double l2 = fR / R;
      l1              = stretch_for(q / R, l2, l1);
      dq              = mu * (l2 - 1. / l2) + lambda * std::log(l1 * l2) / l2;
    }

    /** q(B) from f(A) = s; the nodes' f and f' kept. */
    double
    shoot(const double s)
    {
      const unsigned int n =
        static_cast<unsigned int>(std::lround((B - A) / h));
      f.assign(n + 1, 0.);
      df.assign(n + 1, 0.);
      double fR = s, q = -p * s, l1 = 1.;
      for (unsigned int i = 0; i <= n; ++i)
        {
          const double R = A + i * h;
          // each stage's stretch starts Newton from the previous stage's
          double k1f = l1, k1q, k2f, k2q, k3f, k3q, k4f, k4q;
          rates(R, fR, q, k1f, k1q);
          f[i]  = fR;
          df[i] = k1f;
          if (i == n)
            break;
          k2f = k1f;
          rates(R + h / 2, fR + h / 2 * k1f, q + h / 2 * k1q, k2f, k2q);
          k3f = k2f;
          rates(R + h / 2, fR + h / 2 * k2f, q + h / 2 * k2q, k3f, k3q);
          k4f = k3f;
          rates(R + h, fR + h * k3f, q + h * k3q, k4f, k4q);
          fR += h / 6 * (k1f + 2 * k2f + 2 * k3f + k4f);
          q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
          l1 = k4f;
        }
      return q;
    }

    /** The cubic Hermite interpolant of the nodes' f (or its derivative). */
    double
    hermite(const double R, const bool derivative) const
    {
      const double       x = (R - A) / h;
      const unsigned int i = std::min<unsigned int>(
        f.size() - 2, static_cast<unsigned int>(std::max(0., std::floor(x))));
      const double t = x - i, t2 = t * t, t3 = t2 * t;
      if (!derivative)
        return (2 * t3 - 3 * t2 + 1) * f[i] + (t3 - 2 * t2 + t) * h * df[i] +
               (-2 * t3 + 3 * t2) * f[i + 1] + (t3 - t2) * h * df[i + 1];
      return ((6 * t2 - 6 * t) * f[i] + (3 * t2 - 4 * t + 1) * h * df[i] +
              (-6 * t2 + 6 * t) * f[i + 1]) /
               h +
             (3 * t2 - 2 * t) * df[i + 1];
    }
  };
} // namespace glissade_tests
