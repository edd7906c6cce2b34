#pragma once

#include <glissade/contact/curves/master_curve.h>

namespace glissade
{
  /**
   * The cubic uniform B-spline that interpolates the nodes (paper section
   * 3.1, eq. 13-19): the smoothing laid over a Q4 mesh.
   *
   * Segment p is c_p(s) = T M Q_p (eq. 14-15) with T = (s^3, s^2, s, 1) and
   * Q_p = (Q_{p-1}, Q_p, Q_{p+1}, Q_{p+2}), i.e. c_p(s) = sum_k b_k(s)
   * Q_{p-1+k} with the uniform cubic B-spline basis b_k. Interpolation of the
   * nodes P_i, c_p(0) = P_p, gives (Q_{i-1} + 4 Q_i + Q_{i+1}) / 6 = P_i
   * (eq. 16), closed by one of two end conditions:
   *
   * - EndCondition::double_vertex, open curve (eq. 18): Q_{-1} = Q_0 and
   *   Q_N = Q_{N-1}, so the first and last equations become
   *   (5 Q_0 + Q_1)/6 = P_0 and (Q_{N-2} + 5 Q_{N-1})/6 = P_{N-1}. (The
   *   paper says this makes the end curvature zero; strictly it makes
   *   c''(0) = Q_1 - Q_0, which is small but not zero.) At least 2 nodes.
   * - EndCondition::periodic, closed curve (eq. 19): Q_{i+N} = Q_i, the
   *   cyclic tridiagonal system, C2 everywhere including the seam. The
   *   repeated data point P_0 = P_N of eq. 19 is implicit: give each node
   *   once. At least 3 nodes.
   *
   * Only the N control points Q_0..Q_{N-1} are stored; the ghosts Q_{-1},
   * Q_N follow from the end condition (control_point()).
   *
   * update() solves A Q = P in O(N): Thomas algorithm for the open case,
   * Sherman-Morrison on top of it for the cyclic case. The factorisation
   * depends only on N and the end condition, so it is redone only when N
   * changes.
   */
  class BSplineCurve : public MasterCurve
  {
  public:
    enum class EndCondition
    {
      double_vertex,
      periodic
    };

    explicit BSplineCurve(EndCondition end_condition);

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

    /**
     * phi_j = sum_k b_k(s) (A^-1)_{q(p-1+k), j}: every node influences every
     * segment, but (A^-1)_ij decays like (2 - sqrt 3)^|i-j| ~ 0.268^|i-j|,
     * so only about 25 nodes on each side survive the 1e-14 cut. See
     * inverse_entry() for how the entries are obtained.
     */
    void
    weights_and_derivatives(unsigned int               segment,
                            double                     s,
                            NodeWeightsAndDerivatives &weights) const override;

    void
    bounding_box(unsigned int segment, Point &low, Point &high) const override;

    /**
     * Entry (i,j) of the inverse of the N x N interpolation matrix A (with the
     * end condition folded in), so that Q_i = sum_j (A^-1)_ij P_j.
     */
    double
    inverse_entry(unsigned int i, unsigned int j) const;

    /** Control point Q_i, i in [-1, N], ghosts mapped by the end condition. */
    Point
    control_point(int i) const;

  private:
    /** Index of the stored control point that plays the role of Q_i. */
    unsigned int
    control_index(int i) const;

    /** sum_k b_k Q_{segment-1+k}: the curve or a derivative, by basis b. */
    Point
    combine_control_points(const unsigned int segment, const double b[4]) const;

    /** Factorisation and Green's function table for N nodes. O(N). */
    void
    prepare_for_size(unsigned int n);

    /** Solve T y = rhs with the precomputed Thomas factors (in place). */
    void
    thomas_solve(std::vector<Point> &rhs) const;

    const EndCondition end_condition;

    /** Number of nodes the factorisation below was made for. */
    unsigned int prepared_size = 0;

    /**
     * Thomas factors of the tridiagonal matrix T with unit off-diagonals:
     * T itself for the open case, the Sherman-Morrison modified matrix for
     * the periodic case.
     */
    std::vector<double> upper_factor;
    std::vector<double> inverse_pivot;

    /** Sherman-Morrison: gamma, z = T^-1 u and 1 + v.z (periodic only). */
    double              sherman_morrison_gamma = 0.;
    std::vector<double> sherman_morrison_z;
    double              sherman_morrison_denominator = 1.;

    /**
     * a_M(d), d in [0, M): the first row of the inverse of the M x M cyclic
     * matrix (1,4,1)/6, M = N (periodic) or 2N (double vertex).
     */
    std::vector<double> cyclic_green;

    std::vector<Point> control;
  };
} // namespace glissade
