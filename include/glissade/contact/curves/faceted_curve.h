#pragma once

#include <glissade/contact/curves/master_curve.h>

namespace glissade
{
  /**
   * The piecewise linear curve through the nodes: the master surface of a
   * plain Q4 mesh, with the facetisation the paper sets out to remove.
   *
   * Segment i is c(s) = (1 - s) x_i + s x_{i+1}; its weights are the two hat
   * functions, so weights() and underlying_segment_weights() agree. The
   * normal jumps at every node; project() reports a point in the normal cone
   * of a convex corner as on_vertex (see MasterCurve::Projection).
   *
   * An open curve needs at least 2 nodes, a closed one at least 3.
   */
  class FacetedCurve : public MasterCurve
  {
  public:
    explicit FacetedCurve(bool closed);

    void
    update(const std::vector<Point> &nodes) override;

    unsigned int
    n_segments() const override;
    bool
    is_closed() const override;

    Point
    value(unsigned int segment, double s) const override;
    Point
    derivative(unsigned int segment, double s) const override;
    Point
    second_derivative(unsigned int segment, double s) const override;
    void
    evaluate(unsigned int segment,
             double       s,
             Point       &value,
             Point       &first_derivative,
             Point       &second_derivative) const override;

    void
    bounding_box(unsigned int segment, Point &low, Point &high) const override;

    void
    weights_and_derivatives(unsigned int               segment,
                            double                     s,
                            NodeWeightsAndDerivatives &weights) const override;

  private:
    const bool closed;
  };
} // namespace glissade
