#include <glissade/contact/curves/faceted_curve.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <initializer_list>

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
  } // namespace

  FacetedCurve::FacetedCurve(const bool closed_curve)
    : closed(closed_curve)
  {}



  void
  FacetedCurve::update(const std::vector<Point> &nodes)
  {
    store_nodes(nodes, closed ? 3 : 2);
    cache_bounding_boxes();
  }



  unsigned int
  FacetedCurve::n_segments() const
  {
    const unsigned int n = n_nodes();
    if (n == 0)
      return 0;
    return closed ? n : n - 1;
  }



  bool
  FacetedCurve::is_closed() const
  {
    return closed;
  }



  MasterCurve::Point
  FacetedCurve::value(const unsigned int segment, const double s) const
  {
    const auto   ends = segment_nodes(segment);
    const Point &a = nodes()[ends[0]], &b = nodes()[ends[1]];
    return {{(1. - s) * a[0] + s * b[0], (1. - s) * a[1] + s * b[1]}};
  }



  MasterCurve::Point
  FacetedCurve::derivative(const unsigned int segment, double) const
  {
    const auto   ends = segment_nodes(segment);
    const Point &a = nodes()[ends[0]], &b = nodes()[ends[1]];
    return {{b[0] - a[0], b[1] - a[1]}};
  }



  MasterCurve::Point
  FacetedCurve::second_derivative(const unsigned int segment, double) const
  {
    (void)segment;
    assert(segment < n_segments());
    return {{0., 0.}};
  }



  void
  FacetedCurve::evaluate(const unsigned int segment,
                         const double       s,
                         Point             &value_at_s,
                         Point             &first_derivative,
                         Point             &second_derivative_at_s) const
  {
    const auto   ends = segment_nodes(segment);
    const Point &a = nodes()[ends[0]], &b = nodes()[ends[1]];
    value_at_s = {{(1. - s) * a[0] + s * b[0], (1. - s) * a[1] + s * b[1]}};
    first_derivative       = {{b[0] - a[0], b[1] - a[1]}};
    second_derivative_at_s = {{0., 0.}};
  }



  void
  FacetedCurve::weights_and_derivatives(
    const unsigned int         segment,
    const double               s,
    NodeWeightsAndDerivatives &weights) const
  {
    const auto ends = segment_nodes(segment);
    weights         = {{ends[0], 1. - s, -1.}, {ends[1], s, 1.}};
    keep_significant(weights);
  }



  void
  FacetedCurve::bounding_box(const unsigned int segment,
                             Point             &low,
                             Point             &high) const
  {
    const auto ends = segment_nodes(segment);
    box_of({nodes()[ends[0]], nodes()[ends[1]]}, low, high);
  }
} // namespace glissade
