// NURBS patches: bases, evaluation, knot insertion and the exact shapes
// (include/glissade/mesh/nurbs_patch.h).

#include <deal.II/base/exceptions.h>

#include <glissade/mesh/bspline_functions.h>
#include <glissade/mesh/nurbs_patch.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace glissade
{
  using namespace dealii;

  BSplineBasis::BSplineBasis(const unsigned int  degree,
                             std::vector<double> knots)
    : p(degree)
    , knot_vector(std::move(knots))
  {
    AssertThrow(knot_vector.size() >= 2 * p + 2,
                ExcMessage("too few knots for the degree"));
    for (unsigned int k = 1; k < knot_vector.size(); ++k)
      AssertThrow(knot_vector[k] >= knot_vector[k - 1],
                  ExcMessage("knots must not decrease"));
    find_spans();
  }



  void
  BSplineBasis::find_spans()
  {
    span_knot.clear();
    for (unsigned int k = p; k + p + 1 < knot_vector.size(); ++k)
      if (knot_vector[k + 1] > knot_vector[k])
        span_knot.push_back(k);
  }



  std::array<double, 2>
  BSplineBasis::span_range(const unsigned int span) const
  {
    return {{knot_vector[span_knot[span]], knot_vector[span_knot[span] + 1]}};
  }



  void
  BSplineBasis::evaluate(const unsigned int   span,
                         const double         u,
                         std::vector<double> &values,
                         std::vector<double> &first_derivatives,
                         std::vector<double> &second_derivatives) const
  {
    bspline_functions_on_span(p,
                              knot_vector,
                              span_knot[span],
                              u,
                              values,
                              first_derivatives,
                              second_derivatives);
  }



  std::vector<std::array<double, 2>>
  BSplineBasis::insert_knot(const double u)
  {
    const std::vector<double> &U = knot_vector;
    AssertThrow(u > U.front() && u < U.back(),
                ExcMessage("a knot is inserted inside the parameter range"));
    // k: the last knot not above u
    const unsigned int k =
      std::upper_bound(U.begin(), U.end(), u) - U.begin() - 1;
    const unsigned int                 n_old = n_functions();
    std::vector<std::array<double, 2>> rows(n_old + 1);
    for (unsigned int i = 0; i <= n_old; ++i)
      if (i + p <= k)
        rows[i] = {{0., 1.}};
      else if (i > k)
        rows[i] = {{1., 0.}};
      else
        {
          const double alpha = (u - U[i]) / (U[i + p] - U[i]);
          rows[i]            = {{1. - alpha, alpha}};
        }
    knot_vector.insert(knot_vector.begin() + k + 1, u);
    find_spans();
    return rows;
  }



  unsigned int
  NurbsPatch::n_unique_controls() const
  {
    return n_xi() * (closed_in_eta ? n_eta() - 1 : n_eta());
  }



  unsigned int
  NurbsPatch::unique_control(const unsigned int a, const unsigned int b) const
  {
    if (!body_numbers.empty())
      return body_numbers[a + n_xi() * b];
    return a + n_xi() * (closed_in_eta && b + 1 == n_eta() ? 0 : b);
  }



  NurbsPatch::SideSpan
  NurbsPatch::side_span(const unsigned int span_xi,
                        const unsigned int span_eta,
                        const unsigned int face) const
  {
    const unsigned int  fixed = face / 2, at_end = face % 2, moving = 1 - fixed;
    const unsigned int  span[2] = {span_xi, span_eta};
    const BSplineBasis &along   = moving == 0 ? xi : eta;
    const unsigned int  first   = along.first_function(span[moving]);
    const unsigned int  p       = along.degree();
    const unsigned int  row =
      (fixed == 0 ? xi : eta).first_function(span[fixed]) +
      (at_end ? (fixed == 0 ? xi : eta).degree() : 0);
    SideSpan side;
    for (unsigned int m = 0; m <= p; ++m)
      {
        const unsigned int a = moving == 0 ? first + m : row;
        const unsigned int b = moving == 0 ? row : first + m;
        side.controls.push_back(unique_control(a, b));
        side.weights.push_back(weights[a + n_xi() * b]);
        side.points.push_back(points[a + n_xi() * b]);
      }
    // The span is [U[i], U[i + 1]] with i = first + p.
    side.knots.assign(along.knots().begin() + first + 1,
                      along.knots().begin() + first + 2 * p + 1);
    return side;
  }



  void
  NurbsPatch::evaluate(const unsigned int span_xi,
                       const unsigned int span_eta,
                       const double       u,
                       const double       v,
                       Evaluation        &result) const
  {
    std::vector<double> N, dN, d2N, M, dM, d2M;
    xi.evaluate(span_xi, u, N, dN, d2N);
    eta.evaluate(span_eta, v, M, dM, d2M);
    const unsigned int a0 = xi.first_function(span_xi),
                       b0 = eta.first_function(span_eta);
    const unsigned int n  = N.size() * M.size();
    result.controls.resize(n);
    result.values.resize(n);
    result.parametric_gradients.resize(n);
    // The weighted products and their weight W, then R = N M w / W.
    double       W = 0.;
    Tensor<1, 2> dW;
    for (unsigned int j = 0, k = 0; j < M.size(); ++j)
      for (unsigned int i = 0; i < N.size(); ++i, ++k)
        {
          const double w     = weights[(a0 + i) + n_xi() * (b0 + j)];
          result.controls[k] = unique_control(a0 + i, b0 + j);
          result.values[k]   = N[i] * M[j] * w;
          result.parametric_gradients[k][0] = dN[i] * M[j] * w;
          result.parametric_gradients[k][1] = N[i] * dM[j] * w;
          W += result.values[k];
          dW += result.parametric_gradients[k];
        }
    result.point    = Point<2>();
    result.jacobian = Tensor<2, 2>();
    for (unsigned int j = 0, k = 0; j < M.size(); ++j)
      for (unsigned int i = 0; i < N.size(); ++i, ++k)
        {
          const double R = result.values[k] / W;
          result.parametric_gradients[k] =
            (result.parametric_gradients[k] - R * dW) / W;
          result.values[k]  = R;
          const Point<2> &P = points[(a0 + i) + n_xi() * (b0 + j)];
          result.point += R * P;
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int e = 0; e < 2; ++e)
              result.jacobian[d][e] += result.parametric_gradients[k][e] * P[d];
        }
  }



  Point<2>
  NurbsPatch::point(const unsigned int span_xi,
                    const unsigned int span_eta,
                    const double       u,
                    const double       v) const
  {
    Evaluation e;
    evaluate(span_xi, span_eta, u, v, e);
    return e.point;
  }



  NurbsPatch::Homogeneous
  NurbsPatch::homogeneous() const
  {
    Homogeneous h(points.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      h[k] = {
        {weights[k] * points[k][0], weights[k] * points[k][1], weights[k]}};
    return h;
  }



  NurbsPatch
  NurbsPatch::from_homogeneous(const BSplineBasis &xi,
                               const BSplineBasis &eta,
                               const Homogeneous  &control)
  {
    NurbsPatch patch;
    patch.xi  = xi;
    patch.eta = eta;
    for (const auto &h : control)
      {
        AssertThrow(h[2] > 0., ExcMessage("a NURBS weight must be positive"));
        patch.points.emplace_back(h[0] / h[2], h[1] / h[2]);
        patch.weights.push_back(h[2]);
      }
    return patch;
  }



  void
  NurbsPatch::insert_knot(const unsigned int direction, const double u)
  {
    // Boehm's rows act along one direction, column by column of the
    // other, on the homogeneous points (which is what keeps the rational
    // surface the same).
    const Homogeneous  old = homogeneous();
    const unsigned int n_a = n_xi(), n_b = n_eta();
    const auto         rows  = (direction == 0 ? xi : eta).insert_knot(u);
    const unsigned int new_a = direction == 0 ? n_a + 1 : n_a;
    const unsigned int new_b = direction == 1 ? n_b + 1 : n_b;
    Homogeneous        fresh(new_a * new_b);
    for (unsigned int b = 0; b < new_b; ++b)
      for (unsigned int a = 0; a < new_a; ++a)
        {
          const unsigned int i = direction == 0 ? a : b;
          auto               h = std::array<double, 3>{{0., 0., 0.}};
          for (unsigned int side = 0; side < 2; ++side)
            {
              const double c = rows[i][side];
              if (c == 0.)
                continue;
              const unsigned int old_i = side == 0 ? i - 1 : i;
              const unsigned int k =
                direction == 0 ? old_i + n_a * b : a + n_a * old_i;
              for (unsigned int d = 0; d < 3; ++d)
                h[d] += c * old[k][d];
            }
          fresh[a + new_a * b] = h;
        }
    const bool closed = closed_in_eta;
    *this             = from_homogeneous(xi, eta, fresh);
    closed_in_eta     = closed;
  }



  void
  NurbsPatch::distort(const double factor)
  {
    // (a fixed linear congruential sequence: the same patch on every
    // machine)
    unsigned long long state  = 20121127ULL;
    const auto         random = [&state]() {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return double(state >> 11) / double(1ULL << 53) * 2. - 1.;
    };
    const std::vector<Point<2>> old    = points;
    const unsigned int          last_b = n_eta() - 1;
    for (unsigned int b = 0; b < n_eta(); ++b)
      for (unsigned int a = 1; a + 1 < n_xi(); ++a)
        {
          if (!closed_in_eta && (b == 0 || b == last_b))
            continue;
          // (a closed patch's seam column is moved once, as one point)
          if (closed_in_eta && b == last_b)
            {
              points[a + n_xi() * b] = points[a];
              continue;
            }
          double nearest = std::numeric_limits<double>::max();
          for (const auto &[da, db] : std::vector<std::pair<int, int>>{
                 {-1, 0}, {1, 0}, {0, -1}, {0, 1}})
            {
              const int na = int(a) + da, nb = int(b) + db;
              if (nb < 0 || nb >= int(n_eta()))
                continue;
              nearest =
                std::min(nearest,
                         (old[na + n_xi() * nb] - old[a + n_xi() * b]).norm());
            }
          const double dx = random(), dy = random();
          points[a + n_xi() * b] +=
            factor * nearest * Tensor<1, 2>({dx, dy}) / std::sqrt(2.);
        }
  }



  namespace
  {
    /** A Bezier segment of degree p, as homogeneous points. */
    using Segment = std::vector<std::array<double, 3>>;

    /** The same segment one degree higher (Farin's elevation formula). */
    Segment
    elevate(const Segment &segment)
    {
      const unsigned int p = segment.size() - 1;
      Segment            raised(p + 2);
      raised.front() = segment.front();
      raised.back()  = segment.back();
      for (unsigned int i = 1; i <= p; ++i)
        for (unsigned int d = 0; d < 3; ++d)
          raised[i][d] = double(i) / (p + 1) * segment[i - 1][d] +
                         (1. - double(i) / (p + 1)) * segment[i][d];
      return raised;
    }

    Segment
    elevated_to(Segment segment, const unsigned int degree)
    {
      while (segment.size() < degree + 1)
        segment = elevate(segment);
      return segment;
    }

    /** The straight segment from 0 to 1 (one coordinate), degree p. */
    Segment
    unit_line(const unsigned int degree)
    {
      return elevated_to({{{0., 0., 1.}}, {{1., 0., 1.}}}, degree);
    }

    /** The unit circle's arc from angle a to b (b - a < pi), degree p. */
    Segment
    unit_arc(const double a, const double b, const unsigned int degree)
    {
      const double half = (b - a) / 2., w = std::cos(half), m = (a + b) / 2.;
      return elevated_to({{{std::cos(a), std::sin(a), 1.}},
                          {{std::cos(m), std::sin(m), w}},
                          {{std::cos(b), std::sin(b), 1.}}},
                         degree);
    }

    /** The rational point of a segment at t in [0, 1] (de Casteljau). */
    std::array<double, 2>
    segment_point(Segment s, const double t)
    {
      for (unsigned int level = s.size() - 1; level > 0; --level)
        for (unsigned int i = 0; i < level; ++i)
          for (unsigned int d = 0; d < 3; ++d)
            s[i][d] = (1. - t) * s[i][d] + t * s[i + 1][d];
      return {{s[0][0] / s[0][2], s[0][1] / s[0][2]}};
    }

    /** Open knots of pieces 0..n_pieces joined C0 (degree-fold inner). */
    std::vector<double>
    piecewise_knots(const unsigned int degree, const unsigned int n_pieces)
    {
      std::vector<double> knots(degree + 1, 0.);
      for (unsigned int k = 1; k < n_pieces; ++k)
        knots.insert(knots.end(), degree, double(k));
      knots.insert(knots.end(), degree + 1, double(n_pieces));
      return knots;
    }
  } // namespace



  NurbsPatch
  NurbsPatch::rectangle(const Point<2>            &corner_1,
                        const Point<2>            &corner_2,
                        const unsigned int         degree,
                        const std::vector<double> &x_knots,
                        const std::vector<double> &y_knots)
  {
    const Segment      line = unit_line(degree);
    const BSplineBasis basis(degree, piecewise_knots(degree, 1));
    Homogeneous        control;
    for (unsigned int b = 0; b <= degree; ++b)
      for (unsigned int a = 0; a <= degree; ++a)
        control.push_back(
          {{corner_1[0] + line[a][0] * (corner_2[0] - corner_1[0]),
            corner_1[1] + line[b][0] * (corner_2[1] - corner_1[1]),
            1.}});
    NurbsPatch patch = from_homogeneous(basis, basis, control);
    for (const double u : x_knots)
      if (u > 0. && u < 1.)
        patch.insert_knot(0, u);
    for (const double v : y_knots)
      if (v > 0. && v < 1.)
        patch.insert_knot(1, v);
    return patch;
  }



  NurbsPatch
  NurbsPatch::annulus(const Point<2>    &center,
                      const double       inner_radius,
                      const double       outer_radius,
                      const double       theta_0,
                      const double       theta_1,
                      const bool         closed,
                      const unsigned int degree,
                      const unsigned int n_through,
                      const unsigned int n_around)
  {
    // Pieces of at most a quarter turn where there are cells enough (a
    // rational quadratic arc is exact below half a turn), each a whole
    // number of cells.
    const double       angle = theta_1 - theta_0;
    const unsigned int n_pieces =
      std::min(n_around, (unsigned int)(std::ceil(angle / (M_PI / 2.) - 1e-9)));
    std::vector<unsigned int> first_cell(n_pieces + 1);
    for (unsigned int k = 0; k <= n_pieces; ++k)
      first_cell[k] = (k * n_around) / n_pieces;
    const auto vertex_angle = [&](const unsigned int i) {
      return theta_0 + angle * double(i) / double(n_around);
    };
    std::vector<Segment> arcs;
    for (unsigned int k = 0; k < n_pieces; ++k)
      arcs.push_back(unit_arc(vertex_angle(first_cell[k]),
                              vertex_angle(first_cell[k + 1]),
                              degree));
    // eta: the pieces one after the other, sharing their end points.
    Segment around;
    for (unsigned int k = 0; k < n_pieces; ++k)
      around.insert(around.end(),
                    arcs[k].begin() + (k == 0 ? 0 : 1),
                    arcs[k].end());
    const Segment line = unit_line(degree);
    Homogeneous   control;
    for (const auto &h : around)
      for (unsigned int a = 0; a <= degree; ++a)
        {
          const double r =
            inner_radius + line[a][0] * (outer_radius - inner_radius);
          control.push_back(
            {{h[2] * center[0] + r * h[0], h[2] * center[1] + r * h[1], h[2]}});
        }
    NurbsPatch patch =
      from_homogeneous(BSplineBasis(degree, piecewise_knots(degree, 1)),
                       BSplineBasis(degree, piecewise_knots(degree, n_pieces)),
                       control);
    patch.closed_in_eta = closed;
    for (unsigned int j = 1; j < n_through; ++j)
      patch.insert_knot(0, double(j) / n_through);
    // The parameter of each inner vertex angle of a piece, by bisection
    // (the angle grows along the arc).
    for (unsigned int k = 0; k < n_pieces; ++k)
      for (unsigned int i = first_cell[k] + 1; i < first_cell[k + 1]; ++i)
        {
          const double wanted = vertex_angle(i) - vertex_angle(first_cell[k]);
          double       lo = 0., hi = 1.;
          for (unsigned int iteration = 0; iteration < 200 && hi - lo > 1e-16;
               ++iteration)
            {
              const double t = (lo + hi) / 2.;
              const auto   x = segment_point(arcs[k], t);
              const double at =
                std::atan2(x[1], x[0]) - vertex_angle(first_cell[k]);
              // (the angle from the piece's start, in (-pi, pi])
              const double turned         = std::remainder(at, 2. * M_PI);
              (turned < wanted ? lo : hi) = t;
            }
          patch.insert_knot(1, k + (lo + hi) / 2.);
        }
    return patch;
  }
} // namespace glissade
