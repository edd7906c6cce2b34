#include <glissade/contact/curves/bspline_curve.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace glissade
{
  namespace
  {
    using Point = MasterCurve::Point;

    // Uniform cubic B-spline basis on one segment, i.e. the columns of T M
    // (paper eq. 15), and its first and second derivatives with respect to s.
    inline void
    basis(const double s, double b[4])
    {
      const double t = 1. - s;
      b[0]           = t * t * t / 6.;
      b[1]           = (3. * s * s * s - 6. * s * s + 4.) / 6.;
      b[2]           = (-3. * s * s * s + 3. * s * s + 3. * s + 1.) / 6.;
      b[3]           = s * s * s / 6.;
    }

    inline void
    basis_derivative(const double s, double db[4])
    {
      const double t = 1. - s;
      db[0]          = -0.5 * t * t;
      db[1]          = 0.5 * (3. * s * s - 4. * s);
      db[2]          = 0.5 * (-3. * s * s + 2. * s + 1.);
      db[3]          = 0.5 * s * s;
    }

    inline void
    basis_second_derivative(const double s, double ddb[4])
    {
      ddb[0] = 1. - s;
      ddb[1] = 3. * s - 2.;
      ddb[2] = 1. - 3. * s;
      ddb[3] = s;
    }

    // Beyond this distance |i-j| the entries of A^-1 are below
    // sqrt(3) 0.268^31 ~ 3e-18, far under the 1e-14 cut of weights().
    constexpr unsigned int weight_band = 30;
  } // namespace



  BSplineCurve::BSplineCurve(const EndCondition ends)
    : end_condition(ends)
  {}



  unsigned int
  BSplineCurve::n_segments() const
  {
    const unsigned int n = n_nodes();
    if (n == 0)
      return 0;
    return is_closed() ? n : n - 1;
  }



  bool
  BSplineCurve::is_closed() const
  {
    return end_condition == EndCondition::periodic;
  }



  unsigned int
  BSplineCurve::control_index(const int i) const
  {
    // Called four times per evaluation: avoid integer division, i is
    // always in [-1, N+1].
    const int n = static_cast<int>(control.size());
    assert(i >= -n && i < 2 * n);
    if (is_closed())
      return static_cast<unsigned int>(i < 0 ? i + n : (i >= n ? i - n : i));
    // Double vertex: Q_{-1} = Q_0, Q_N = Q_{N-1}.
    return static_cast<unsigned int>(std::min(std::max(i, 0), n - 1));
  }



  MasterCurve::Point
  BSplineCurve::control_point(const int i) const
  {
    return control[control_index(i)];
  }



  void
  BSplineCurve::prepare_for_size(const unsigned int n)
  {
    // Everything below depends on N and the end condition only, never on
    // the node positions: it is done once, and again only if N changes.
    //
    // We work with B = 6 A = tridiag(1, 4, 1) (+ end modifications) and
    // right hand side 6 P.
    std::vector<double> diagonal(n, 4.);
    if (is_closed())
      {
        // Sherman-Morrison: B = T + u v^T with u = (gamma, 0, ..., 0, 1),
        // v = (1, 0, ..., 0, 1/gamma), which puts the two corner entries
        // B_{0,N-1} = B_{N-1,0} = 1 into the rank-one term. gamma = -4
        // (minus the diagonal, as recommended by Numerical Recipes) keeps T
        // strictly diagonally dominant: diagonal 8, 4, ..., 4, 4.25.
        sherman_morrison_gamma = -4.;
        diagonal[0] -= sherman_morrison_gamma;
        diagonal[n - 1] -= 1. / sherman_morrison_gamma;
      }
    else
      {
        // Double vertex: the ghost equals its neighbour, so 1 + 4 -> 5.
        diagonal[0]     = 5.;
        diagonal[n - 1] = 5.;
      }

    // Thomas algorithm factors for unit sub- and super-diagonals.
    upper_factor.assign(n, 0.);
    inverse_pivot.assign(n, 0.);
    inverse_pivot[0] = 1. / diagonal[0];
    upper_factor[0]  = inverse_pivot[0];
    for (unsigned int i = 1; i < n; ++i)
      {
        inverse_pivot[i] = 1. / (diagonal[i] - upper_factor[i - 1]);
        upper_factor[i]  = inverse_pivot[i];
      }

    if (is_closed())
      {
        // z = T^-1 u, and the denominator 1 + v.z of Sherman-Morrison.
        std::vector<Point> u(n, Point{{0., 0.}});
        u[0][0]     = sherman_morrison_gamma;
        u[n - 1][0] = 1.;
        thomas_solve(u);
        sherman_morrison_z.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          sherman_morrison_z[i] = u[i][0];
        sherman_morrison_denominator =
          1. + sherman_morrison_z[0] +
          sherman_morrison_z[n - 1] / sherman_morrison_gamma;
      }

    // The inverse of A for weights(). Three ways were possible: solve A x =
    // e_j for the needed columns on demand (O(N) per column, a cache to
    // manage), precompute the banded rows by solving (O(N^2) once per N), or
    // use the closed form, which is what we do since A^-1 has one:
    //
    // The bi-infinite system x_{k-1} + 4 x_k + x_{k+1} = delta_k has the
    // solution x_k = z^|k| / (2 sqrt 3), z = sqrt 3 - 2 (the root of
    // z^2 + 4z + 1 = 0 with |z| < 1). Summing its periodic images gives the
    // inverse of the M x M cyclic matrix A = (1,4,1)/6 in closed form:
    //   (A^-1)_ij = a_M((i - j) mod M),
    //   a_M(d) = sqrt 3 (z^d + z^(M-d)) / (1 - z^M),   0 <= d < M.
    // The double-vertex condition Q_{-1} = Q_0, Q_N = Q_{N-1} is a mirror
    // about the half-integer points -1/2 and N - 1/2: the open system of N
    // nodes is the cyclic system of 2N nodes with mirror-symmetric data
    // P_0..P_{N-1}, P_{N-1}..P_0 (its unique solution is mirror-symmetric,
    // hence satisfies eq. 18). So, by the method of images,
    //   (A^-1)_ij = a_2N((i - j) mod 2N) + a_2N((i + j + 1) mod 2N).
    // Each entry is then an O(1) table look-up, exact to round-off for every
    // N (the test program checks it against a dense inverse), and the table
    // costs O(N) once per N. It is independent of the Thomas solve used by
    // update(), which the tests exploit: weights() . nodes == value().
    const unsigned int m       = is_closed() ? n : 2 * n;
    const double       root    = 2. - std::sqrt(3.); // |z|
    const double       z_m     = (m % 2 ? -1. : 1.) * std::pow(root, m);
    const auto         z_power = [root](const unsigned int d) {
      return (d % 2 ? -1. : 1.) * std::pow(root, d);
    };
    cyclic_green.resize(m);
    for (unsigned int d = 0; d < m; ++d)
      cyclic_green[d] =
        std::sqrt(3.) * (z_power(d) + z_power(m - d)) / (1. - z_m);

    prepared_size = n;
  }



  void
  BSplineCurve::thomas_solve(std::vector<Point> &rhs) const
  {
    const unsigned int n = rhs.size();
    for (unsigned int d = 0; d < 2; ++d)
      {
        rhs[0][d] *= inverse_pivot[0];
        for (unsigned int i = 1; i < n; ++i)
          rhs[i][d] = (rhs[i][d] - rhs[i - 1][d]) * inverse_pivot[i];
        for (unsigned int i = n - 1; i-- > 0;)
          rhs[i][d] -= upper_factor[i] * rhs[i + 1][d];
      }
  }



  void
  BSplineCurve::update(const std::vector<Point> &nodes)
  {
    store_nodes(nodes, is_closed() ? 3 : 2);
    const unsigned int n = nodes.size();
    if (n != prepared_size)
      prepare_for_size(n);

    control.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      control[i] = {{6. * nodes[i][0], 6. * nodes[i][1]}};
    thomas_solve(control);

    if (is_closed())
      {
        // Q = y - (v.y / (1 + v.z)) z.
        for (unsigned int d = 0; d < 2; ++d)
          {
            const double factor =
              (control[0][d] + control[n - 1][d] / sherman_morrison_gamma) /
              sherman_morrison_denominator;
            for (unsigned int i = 0; i < n; ++i)
              control[i][d] -= factor * sherman_morrison_z[i];
          }
      }
    cache_bounding_boxes();
  }



  double
  BSplineCurve::inverse_entry(const unsigned int i, const unsigned int j) const
  {
    const unsigned int n = n_nodes();
    assert(i < n && j < n);
    if (is_closed())
      return cyclic_green[(i + n - j) % n];
    const unsigned int m = 2 * n;
    return cyclic_green[(i + m - j) % m] + cyclic_green[(i + j + 1) % m];
  }



  MasterCurve::Point
  BSplineCurve::combine_control_points(const unsigned int segment,
                                       const double       b[4]) const
  {
    Point c = {{0., 0.}};
    for (int k = 0; k < 4; ++k)
      {
        const Point &q = control[control_index(int(segment) - 1 + k)];
        c[0] += b[k] * q[0];
        c[1] += b[k] * q[1];
      }
    return c;
  }



  MasterCurve::Point
  BSplineCurve::value(const unsigned int segment, const double s) const
  {
    assert(segment < n_segments());
    double b[4];
    basis(s, b);
    return combine_control_points(segment, b);
  }



  MasterCurve::Point
  BSplineCurve::derivative(const unsigned int segment, const double s) const
  {
    assert(segment < n_segments());
    double b[4];
    basis_derivative(s, b);
    return combine_control_points(segment, b);
  }



  MasterCurve::Point
  BSplineCurve::second_derivative(const unsigned int segment,
                                  const double       s) const
  {
    assert(segment < n_segments());
    double b[4];
    basis_second_derivative(s, b);
    return combine_control_points(segment, b);
  }



  void
  BSplineCurve::evaluate(const unsigned int segment,
                         const double       s,
                         Point             &value_at_s,
                         Point             &first_derivative,
                         Point             &second_derivative_at_s) const
  {
    assert(segment < n_segments());
    double b[4], db[4], ddb[4];
    basis(s, b);
    basis_derivative(s, db);
    basis_second_derivative(s, ddb);
    value_at_s = first_derivative = second_derivative_at_s = {{0., 0.}};
    for (int k = 0; k < 4; ++k)
      {
        const Point &q = control[control_index(int(segment) - 1 + k)];
        for (unsigned int d = 0; d < 2; ++d)
          {
            value_at_s[d] += b[k] * q[d];
            first_derivative[d] += db[k] * q[d];
            second_derivative_at_s[d] += ddb[k] * q[d];
          }
      }
  }



  void
  BSplineCurve::weights_and_derivatives(
    const unsigned int         segment,
    const double               s,
    NodeWeightsAndDerivatives &weights) const
  {
    assert(segment < n_segments());
    weights.clear();
    const unsigned int n = n_nodes();

    double b[4], db[4];
    basis(s, b);
    basis_derivative(s, db);
    unsigned int slot[4];
    for (int k = 0; k < 4; ++k)
      slot[k] = control_index(int(segment) - 1 + k);

    // The nodes within weight_band of the four control points, each once.
    std::vector<unsigned int> columns;
    const int                 first = int(segment) - 1 - int(weight_band);
    const int                 last  = int(segment) + 2 + int(weight_band);
    if (is_closed())
      {
        if (last - first + 1 >= int(n))
          for (unsigned int j = 0; j < n; ++j)
            columns.push_back(j);
        else
          for (int j = first; j <= last; ++j)
            columns.push_back(static_cast<unsigned int>((j + int(n)) % int(n)));
        std::sort(columns.begin(), columns.end());
      }
    else
      for (int j = std::max(first, 0); j <= std::min(last, int(n) - 1); ++j)
        columns.push_back(j);

    weights.reserve(columns.size());
    for (const unsigned int j : columns)
      {
        double phi = 0., dphi = 0.;
        for (int k = 0; k < 4; ++k)
          {
            const double a = inverse_entry(slot[k], j);
            phi += b[k] * a;
            dphi += db[k] * a;
          }
        weights.push_back({j, phi, dphi});
      }
    keep_significant(weights);
  }



  void
  BSplineCurve::bounding_box(const unsigned int segment,
                             Point             &low,
                             Point             &high) const
  {
    // Convex hull property: the basis functions are non-negative and sum to
    // one on [0,1], so the segment lies in the hull of its 4 control points.
    const int p = int(segment);
    low = high = control[control_index(p - 1)];
    for (int k = 0; k < 3; ++k)
      {
        const Point &q = control[control_index(p + k)];
        for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = std::min(low[d], q[d]);
            high[d] = std::max(high[d], q[d]);
          }
      }
  }
} // namespace glissade
