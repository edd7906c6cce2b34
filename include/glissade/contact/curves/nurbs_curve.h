#pragma once

#include <glissade/contact/curves/master_curve.h>

#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The boundary of an isogeometric body: a NURBS curve of degree p whose
   * segments are its knot spans (the boundary faces of the body's Bezier
   * elements), C^(p-1) between segments of one side of a patch and exact
   * for a circle (rational weights). The paper's third strategy against
   * faceted contact: the master is the body's own boundary, with no
   * smoothing laid over it.
   *
   * On segment i, with u the curve's parameter over the span,
   * c(s) = sum_k R_k(u(s)) P_k, R_k = N_k w_k / sum_l N_l w_l over the
   * segment's p + 1 control points P_k and weights w_k; s in [0, 1] runs
   * along the span, forwards or (`reversed`) backwards, so that the
   * segments follow the chain of the master boundary whatever the
   * direction of the patch's parameter.
   *
   * The data given to update() are the control points, not points on the
   * curve: the curve does not interpolate them. Its nodes (MasterCurve::
   * nodes(), which the projection starts from) are the segments' ends,
   * c(i, 0) = node i, computed by update(). The indices of
   * weights_and_derivatives() are control points' indices, not nodes':
   * the force at a curve point goes to the control points, by R_k.
   *
   * Each segment keeps its own 2p knots and weights, so that segments of
   * different sides of a patch (two bases) make one chain, with a corner
   * where the sides meet.
   */
  class NurbsCurve : public MasterCurve
  {
  public:
    /** One knot span of the curve. */
    struct Segment
    {
      /** The p + 1 control points nonzero on the span (indices into the
       *  control points given to update()), in the parameter's order. */
      std::vector<unsigned int> controls;
      /** Their weights (> 0). */
      std::vector<double> weights;
      /** The 2p knots U[i + 1 - p], ..., U[i + p] around the span
       *  [U[i], U[i + 1]] = [knots[p - 1], knots[p]]. */
      std::vector<double> knots;
      /** s runs from the span's end to its start. */
      bool reversed = false;
    };

    /** Throws std::invalid_argument if a segment is not of degree p (p + 1
     *  controls and weights, 2p knots, an empty span, a weight <= 0). */
    NurbsCurve(unsigned int degree, bool closed, std::vector<Segment> segments);

    /** The current positions of the control points. */
    void
    update(const std::vector<Point> &controls) override;

    unsigned int
    n_segments() const override;
    bool
    is_closed() const override;

    unsigned int
    degree_of_curve() const
    {
      return degree;
    }

    const Segment &
    segment_data(const unsigned int segment) const
    {
      return segments[segment];
    }

    /** A control point's Greville point: (segment, s) on the curve. */
    struct GrevillePoint
    {
      unsigned int segment;
      double       s;
      /** The control point (an index of the data given to update()). */
      unsigned int control;
    };

    /**
     * The Greville abscissae of the control points (the mean of the p knots
     * each function's support starts with, Hughes, Cottrell & Bazilevs
     * 2005): where each control point's function peaks, each control point
     * once, in the order of the segments. The slave points of a NURBS body
     * (Matzen, Cichosz & Bischoff 2013).
     */
    std::vector<GrevillePoint>
    greville_points() const;

    /** The number of control points update() expects. */
    unsigned int
    n_controls() const;

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

    /** The box of the segment's control points: a NURBS segment with
     *  positive weights lies in their convex hull. */
    void
    bounding_box(unsigned int segment, Point &low, Point &high) const override;

    /** R_k and dR_k/ds of the segment's control points (control indices). */
    void
    weights_and_derivatives(unsigned int               segment,
                            double                     s,
                            NodeWeightsAndDerivatives &weights) const override;

    /** R_k, dR_k/ds and d2R_k/ds2 of the segment's controls at s, in the
     *  order of Segment::controls (mortar on a NURBS slave differentiates
     *  the curve's points and normals through them). */
    void
    rational_functions(unsigned int         segment,
                       double               s,
                       std::vector<double> &R,
                       std::vector<double> &dR,
                       std::vector<double> &d2R) const;

  private:
    const unsigned int         degree;
    const bool                 closed;
    const std::vector<Segment> segments;
    unsigned int               n_control_points = 0;
    std::vector<Point>         controls;
  };
} // namespace glissade
