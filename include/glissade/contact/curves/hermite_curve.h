#pragma once

#include <glissade/contact/curves/master_curve.h>

namespace glissade
{
  /**
   * A piecewise cubic Hermite curve: the curved edge of the paper's Hermite
   * elements (section 3.2), seen from the contact module.
   *
   * Segment i is c(s) = H00(s) x_a + H01(s) x_b + H10(s) d_a + H11(s) d_b,
   * with x_a, x_b its end nodes and d_a, d_b the tangents dx/ds at its ends,
   * taken with respect to the local coordinate s in [0,1] (for an element edge
   * parametrised by xi in [-1,1], s = (xi + 1)/2 and dx/ds = 2 dx/dxi). The
   * tangents belong to the segment, so a curve with corners (different
   * tangents on either side of a node) is allowed; set_node_tangents() is the
   * shortcut for a C1 curve.
   *
   * update() sets the positions, set_segment_tangents() / set_node_tangents()
   * the tangents; they may be called in either order, but the curve can only
   * be evaluated once there is exactly one tangent pair per segment
   * (std::logic_error otherwise).
   *
   * weights() returns the coefficients H00, H01 on the two end positions, so
   * they sum to one; tangent_weights() returns H10, H11, the coefficients on
   * the tangent data, which the caller maps to its derivative dofs.
   *
   * An open curve needs at least 2 nodes, a closed one at least 3.
   */
  class HermiteCurve : public MasterCurve
  {
  public:
    explicit HermiteCurve(bool closed);

    /** New positions; the tangents are kept. */
    void
    update(const std::vector<Point> &nodes) override;

    /** New positions and, per segment, {dx/ds at s=0, dx/ds at s=1}. */
    void
    update(const std::vector<Point>                &nodes,
           const std::vector<std::array<Point, 2>> &segment_tangents);

    /** Per segment: {dx/ds at s = 0, dx/ds at s = 1}. */
    void
    set_segment_tangents(const std::vector<std::array<Point, 2>> &tangents);

    /**
     * One tangent dx/ds per node, shared by the two segments meeting there
     * (a C1 curve). Needs n_nodes() to be known, i.e. after update().
     */
    void
    set_node_tangents(const std::vector<Point> &tangents);

    /** The tangent data of a segment. */
    const std::array<Point, 2> &
    segment_tangents(unsigned int segment) const;

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

    /**
     * {H10(s), H11(s)}: the coefficients of the tangents d_a, d_b of the
     * segment in c(segment, s).
     */
    std::array<double, 2>
    tangent_weights(unsigned int segment, double s) const;

    /** {H10(s), H11(s), H10'(s), H11'(s)}. */
    std::array<double, 4>
    tangent_weights_and_derivatives(unsigned int segment, double s) const;

  private:
    /** Throws unless there is one tangent pair per segment. */
    void
    check_tangents() const;

    /** sum of the four Hermite functions (or derivatives) times the data. */
    Point
    combine(unsigned int segment, const double h[4]) const;

    const bool                        closed;
    std::vector<std::array<Point, 2>> tangents;
  };
} // namespace glissade
