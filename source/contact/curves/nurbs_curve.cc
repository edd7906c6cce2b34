// The boundary of an isogeometric body as a master curve
// (include/glissade/contact/curves/nurbs_curve.h).

#include <glissade/contact/curves/nurbs_curve.h>
#include <glissade/mesh/bspline_functions.h>

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace glissade
{
  NurbsCurve::NurbsCurve(const unsigned int   degree,
                         const bool           closed,
                         std::vector<Segment> curve_segments)
    : degree(degree)
    , closed(closed)
    , segments(std::move(curve_segments))
  {
    for (unsigned int i = 0; i < segments.size(); ++i)
      {
        const Segment &segment = segments[i];
        const auto     fail    = [&](const std::string &what) {
          throw std::invalid_argument("NurbsCurve: segment " +
                                      std::to_string(i) + " " + what);
        };
        if (segment.controls.size() != degree + 1 ||
            segment.weights.size() != degree + 1)
          fail("needs degree + 1 control points and weights");
        if (segment.knots.size() != 2 * degree)
          fail("needs 2 degree knots");
        if (!(segment.knots[degree] > segment.knots[degree - 1]))
          fail("is an empty span");
        for (unsigned int k = 1; k < segment.knots.size(); ++k)
          if (segment.knots[k] < segment.knots[k - 1])
            fail("has decreasing knots");
        for (const double w : segment.weights)
          if (!(w > 0.))
            fail("has a weight that is not positive");
        for (const unsigned int c : segment.controls)
          n_control_points = std::max(n_control_points, c + 1);
      }
  }



  void
  NurbsCurve::update(const std::vector<Point> &control_points)
  {
    if (control_points.size() != n_control_points)
      throw std::invalid_argument(
        "NurbsCurve::update: " + std::to_string(n_control_points) +
        " control points expected, " + std::to_string(control_points.size()) +
        " given");
    controls = control_points;
    // The nodes: each segment's start, and the last one's end on an open
    // curve.
    std::vector<Point> ends;
    for (unsigned int i = 0; i < segments.size(); ++i)
      ends.push_back(value(i, 0.));
    if (!closed && !segments.empty())
      ends.push_back(value(segments.size() - 1, 1.));
    store_nodes(ends, closed ? 3 : 2);
    cache_bounding_boxes();
  }



  unsigned int
  NurbsCurve::n_segments() const
  {
    return segments.size();
  }



  bool
  NurbsCurve::is_closed() const
  {
    return closed;
  }



  unsigned int
  NurbsCurve::n_controls() const
  {
    return n_control_points;
  }



  void
  NurbsCurve::rational_functions(const unsigned int   segment_index,
                                 const double         s,
                                 std::vector<double> &R,
                                 std::vector<double> &dR,
                                 std::vector<double> &d2R) const
  {
    assert(segment_index < segments.size());
    const Segment &segment = segments[segment_index];
    const double   a = segment.knots[degree - 1], b = segment.knots[degree];
    const double   du_ds = segment.reversed ? a - b : b - a;
    const double   u     = segment.reversed ? b + s * du_ds : a + s * du_ds;
    // (kept between calls: the contact search evaluates this at every
    // Gauss point and Newton step)
    thread_local std::vector<double> N, dN, d2N;
    bspline_functions_on_span(degree, segment.knots, degree - 1, u, N, dN, d2N);
    // R = N w / W, differentiated in u, then in s by the chain rule.
    double W = 0., dW = 0., d2W = 0.;
    for (unsigned int k = 0; k <= degree; ++k)
      {
        W += N[k] * segment.weights[k];
        dW += dN[k] * segment.weights[k];
        d2W += d2N[k] * segment.weights[k];
      }
    R.resize(degree + 1);
    dR.resize(degree + 1);
    d2R.resize(degree + 1);
    for (unsigned int k = 0; k <= degree; ++k)
      {
        const double w = segment.weights[k];
        R[k]           = w * N[k] / W;
        dR[k]          = w * (dN[k] / W - N[k] * dW / (W * W)) * du_ds;
        d2R[k]         = w *
                 (d2N[k] / W - 2. * dN[k] * dW / (W * W) -
                  N[k] * d2W / (W * W) + 2. * N[k] * dW * dW / (W * W * W)) *
                 du_ds * du_ds;
      }
  }



  MasterCurve::Point
  NurbsCurve::value(const unsigned int segment, const double s) const
  {
    Point c, dc, ddc;
    evaluate(segment, s, c, dc, ddc);
    return c;
  }



  MasterCurve::Point
  NurbsCurve::derivative(const unsigned int segment, const double s) const
  {
    Point c, dc, ddc;
    evaluate(segment, s, c, dc, ddc);
    return dc;
  }



  MasterCurve::Point
  NurbsCurve::second_derivative(const unsigned int segment,
                                const double       s) const
  {
    Point c, dc, ddc;
    evaluate(segment, s, c, dc, ddc);
    return ddc;
  }



  void
  NurbsCurve::evaluate(const unsigned int segment,
                       const double       s,
                       Point             &c,
                       Point             &dc,
                       Point             &ddc) const
  {
    std::vector<double> R, dR, d2R;
    rational_functions(segment, s, R, dR, d2R);
    c = dc = ddc = Point{{0., 0.}};
    for (unsigned int k = 0; k <= degree; ++k)
      {
        const Point &P = controls[segments[segment].controls[k]];
        for (unsigned int d = 0; d < 2; ++d)
          {
            c[d] += R[k] * P[d];
            dc[d] += dR[k] * P[d];
            ddc[d] += d2R[k] * P[d];
          }
      }
  }



  void
  NurbsCurve::bounding_box(const unsigned int segment,
                           Point             &low,
                           Point             &high) const
  {
    low = high = controls[segments[segment].controls[0]];
    for (const unsigned int k : segments[segment].controls)
      for (unsigned int d = 0; d < 2; ++d)
        {
          low[d]  = std::min(low[d], controls[k][d]);
          high[d] = std::max(high[d], controls[k][d]);
        }
  }



  std::vector<NurbsCurve::GrevillePoint>
  NurbsCurve::greville_points() const
  {
    std::vector<GrevillePoint> points;
    std::vector<bool>          placed(n_control_points, false);
    for (unsigned int i = 0; i < segments.size(); ++i)
      {
        const Segment &segment = segments[i];
        const double   a = segment.knots[degree - 1], b = segment.knots[degree];
        std::vector<std::pair<double, unsigned int>> here;
        for (unsigned int m = 0; m <= degree; ++m)
          {
            // Function m of the span starts at knot m of the 2p kept.
            double g = 0.;
            for (unsigned int k = m; k < m + degree; ++k)
              g += segment.knots[k];
            g /= degree;
            const double s = (g - a) / (b - a);
            if (placed[segment.controls[m]] || s < -1e-12 || s > 1. + 1e-12)
              continue;
            placed[segment.controls[m]] = true;
            const double clamped        = std::min(1., std::max(0., s));
            here.emplace_back(segment.reversed ? 1. - clamped : clamped, m);
          }
        std::sort(here.begin(), here.end());
        for (const auto &[s, m] : here)
          points.push_back({i, s, segment.controls[m]});
      }
    return points;
  }



  void
  NurbsCurve::weights_and_derivatives(const unsigned int         segment,
                                      const double               s,
                                      NodeWeightsAndDerivatives &weights) const
  {
    std::vector<double> R, dR, d2R;
    rational_functions(segment, s, R, dR, d2R);
    weights.clear();
    for (unsigned int k = 0; k <= degree; ++k)
      weights.push_back({segments[segment].controls[k], R[k], dR[k]});
    keep_significant(weights);
  }
} // namespace glissade
