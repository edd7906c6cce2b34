#include <glissade/contact/curves/hermite_curve.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace glissade
{
  namespace
  {

    // The axis-aligned box of a few points.
    inline void
    box_of(const std::initializer_list<MasterCurve::Point> points,
           MasterCurve::Point                             &low,
           MasterCurve::Point                             &high)
    {
      low  = *points.begin();
      high = low;
      for (const auto &p : points)
        for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
    }
    // Cubic Hermite functions, ordered (H00, H01, H10, H11): value at a,
    // value at b, slope at a, slope at b.
    inline void
    hermite(const double s, double h[4])
    {
      const double s2 = s * s, s3 = s2 * s;
      h[0] = 2. * s3 - 3. * s2 + 1.;
      h[1] = -2. * s3 + 3. * s2;
      h[2] = s3 - 2. * s2 + s;
      h[3] = s3 - s2;
    }

    inline void
    hermite_derivative(const double s, double h[4])
    {
      const double s2 = s * s;
      h[0]            = 6. * s2 - 6. * s;
      h[1]            = -6. * s2 + 6. * s;
      h[2]            = 3. * s2 - 4. * s + 1.;
      h[3]            = 3. * s2 - 2. * s;
    }

    inline void
    hermite_second_derivative(const double s, double h[4])
    {
      h[0] = 12. * s - 6.;
      h[1] = -12. * s + 6.;
      h[2] = 6. * s - 4.;
      h[3] = 6. * s - 2.;
    }
  } // namespace



  HermiteCurve::HermiteCurve(const bool closed_curve)
    : closed(closed_curve)
  {}



  void
  HermiteCurve::update(const std::vector<Point> &nodes)
  {
    store_nodes(nodes, closed ? 3 : 2);
    if (tangents.size() == n_segments())
      cache_bounding_boxes();
  }



  void
  HermiteCurve::update(
    const std::vector<Point>                &nodes,
    const std::vector<std::array<Point, 2>> &segment_tangents)
  {
    update(nodes);
    set_segment_tangents(segment_tangents);
  }



  void
  HermiteCurve::set_segment_tangents(
    const std::vector<std::array<Point, 2>> &segment_tangents)
  {
    tangents = segment_tangents;
    if (tangents.size() == n_segments())
      cache_bounding_boxes();
  }



  void
  HermiteCurve::set_node_tangents(const std::vector<Point> &node_tangents)
  {
    if (node_tangents.size() != n_nodes())
      throw std::invalid_argument(
        "HermiteCurve::set_node_tangents: one tangent per node is needed "
        "(call update() first)");
    tangents.resize(n_segments());
    for (unsigned int i = 0; i < n_segments(); ++i)
      {
        const auto ends = segment_nodes(i);
        tangents[i]     = {{node_tangents[ends[0]], node_tangents[ends[1]]}};
      }
    cache_bounding_boxes();
  }



  const std::array<MasterCurve::Point, 2> &
  HermiteCurve::segment_tangents(const unsigned int segment) const
  {
    check_tangents();
    return tangents[segment];
  }



  void
  HermiteCurve::check_tangents() const
  {
    if (tangents.size() != n_segments())
      throw std::logic_error(
        "HermiteCurve: the tangents do not match the segments; call "
        "set_segment_tangents() or set_node_tangents() after update()");
  }



  unsigned int
  HermiteCurve::n_segments() const
  {
    const unsigned int n = n_nodes();
    if (n == 0)
      return 0;
    return closed ? n : n - 1;
  }



  bool
  HermiteCurve::is_closed() const
  {
    return closed;
  }



  MasterCurve::Point
  HermiteCurve::combine(const unsigned int segment, const double h[4]) const
  {
    assert(segment < n_segments());
    check_tangents();
    const auto   ends = segment_nodes(segment);
    const Point &a = nodes()[ends[0]], &b = nodes()[ends[1]];
    const Point &da = tangents[segment][0], &db = tangents[segment][1];
    return {{h[0] * a[0] + h[1] * b[0] + h[2] * da[0] + h[3] * db[0],
             h[0] * a[1] + h[1] * b[1] + h[2] * da[1] + h[3] * db[1]}};
  }



  MasterCurve::Point
  HermiteCurve::value(const unsigned int segment, const double s) const
  {
    double h[4];
    hermite(s, h);
    return combine(segment, h);
  }



  MasterCurve::Point
  HermiteCurve::derivative(const unsigned int segment, const double s) const
  {
    double h[4];
    hermite_derivative(s, h);
    return combine(segment, h);
  }



  MasterCurve::Point
  HermiteCurve::second_derivative(const unsigned int segment,
                                  const double       s) const
  {
    double h[4];
    hermite_second_derivative(s, h);
    return combine(segment, h);
  }



  void
  HermiteCurve::evaluate(const unsigned int segment,
                         const double       s,
                         Point             &value_at_s,
                         Point             &first_derivative,
                         Point             &second_derivative_at_s) const
  {
    double h[4];
    hermite(s, h);
    value_at_s = combine(segment, h);
    hermite_derivative(s, h);
    first_derivative = combine(segment, h);
    hermite_second_derivative(s, h);
    second_derivative_at_s = combine(segment, h);
  }



  void
  HermiteCurve::weights_and_derivatives(
    const unsigned int         segment,
    const double               s,
    NodeWeightsAndDerivatives &weights) const
  {
    double h[4], dh[4];
    hermite(s, h);
    hermite_derivative(s, dh);
    const auto ends = segment_nodes(segment);
    weights         = {{ends[0], h[0], dh[0]}, {ends[1], h[1], dh[1]}};
    keep_significant(weights);
  }



  std::array<double, 2>
  HermiteCurve::tangent_weights(const unsigned int segment,
                                const double       s) const
  {
    const auto both = tangent_weights_and_derivatives(segment, s);
    return {{both[0], both[1]}};
  }



  std::array<double, 4>
  HermiteCurve::tangent_weights_and_derivatives(const unsigned int segment,
                                                const double       s) const
  {
    (void)segment;
    assert(segment < n_segments());
    double h[4], dh[4];
    hermite(s, h);
    hermite_derivative(s, dh);
    return {{h[2], h[3], dh[2], dh[3]}};
  }



  void
  HermiteCurve::bounding_box(const unsigned int segment,
                             Point             &low,
                             Point             &high) const
  {
    // The Bezier control points of the cubic: a, a + d_a/3, b - d_b/3, b;
    // the segment lies in their convex hull.
    check_tangents();
    const auto   ends = segment_nodes(segment);
    const Point &a = nodes()[ends[0]], &b = nodes()[ends[1]];
    const Point &da = tangents[segment][0], &db = tangents[segment][1];
    box_of({a,
            Point{{a[0] + da[0] / 3., a[1] + da[1] / 3.}},
            Point{{b[0] - db[0] / 3., b[1] - db[1] / 3.}},
            b},
           low,
           high);
  }
} // namespace glissade
