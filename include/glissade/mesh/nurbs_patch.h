#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace glissade
{
  /**
   * The B-spline functions of one parametric direction: a degree and a
   * non-decreasing knot vector, open (the first and last knots repeated
   * degree + 1 times). A span is a knot interval of nonzero length; on span
   * s the degree + 1 functions first_function(s), ... are the nonzero ones
   * (Piegl & Tiller, The NURBS Book, 1997, algorithms A2.1 and A2.3).
   */
  class BSplineBasis
  {
  public:
    BSplineBasis() = default;
    BSplineBasis(const unsigned int degree, std::vector<double> knots);

    unsigned int
    degree() const
    {
      return p;
    }
    const std::vector<double> &
    knots() const
    {
      return knot_vector;
    }
    unsigned int
    n_functions() const
    {
      return knot_vector.size() - p - 1;
    }
    unsigned int
    n_spans() const
    {
      return span_knot.size();
    }
    /** [u_s, u_{s+1}]: the parameters span s covers. */
    std::array<double, 2>
    span_range(const unsigned int span) const;
    /** The first of the degree + 1 functions nonzero on span s. */
    unsigned int
    first_function(const unsigned int span) const
    {
      return span_knot[span] - p;
    }

    /**
     * The degree + 1 functions nonzero on `span` and their first and second
     * derivatives at u (u in the span's range).
     */
    void
    evaluate(const unsigned int   span,
             const double         u,
             std::vector<double> &values,
             std::vector<double> &first_derivatives,
             std::vector<double> &second_derivatives) const;

    /**
     * Boehm's knot insertion: the knot vector with u added, and for each
     * new coefficient i the pair of old ones it combines,
     * c_new[i] = a c_old[i - 1] + b c_old[i] (a row (a, b) per new
     * coefficient; the coefficients are homogeneous control points).
     */
    std::vector<std::array<double, 2>>
    insert_knot(const double u);

  private:
    unsigned int        p = 0;
    std::vector<double> knot_vector;
    /** For each span, the knot index k with u_k < u_{k+1}. */
    std::vector<unsigned int> span_knot;

    void
    find_spans();
  };



  /**
   * A single-patch NURBS surface X(xi, eta) = sum_ab R_ab(xi, eta) P_ab,
   * R_ab = N_a(xi) M_b(eta) w_ab / W: its two bases, its control points and
   * weights (index a + n_xi b), and the rational functions and their
   * parametric derivatives on a span (Bezier element).
   *
   * A patch may close on itself in eta (a whole ring): its last column of
   * control points is then its first, and unique_control() numbers them as
   * one.
   *
   * The builders give the paper's shapes exactly (a circle has rational
   * weights; no polynomial of any degree reproduces it): a rectangle, a
   * sector of an annulus or the whole annulus, first as coarse Bezier
   * pieces (arcs of at most 120 degrees joined C0, degree-elevated to the
   * degree asked), then refined by knot insertion at the parameters of the
   * given vertex positions, once each (continuity C^(p-1) inside a piece,
   * C0 where pieces join). The knots of an arc are not uniform: a rational
   * quadratic cannot run along a circle at constant speed, so that a
   * uniform subdivision in angle (the meshes of MeshFactory) is found by
   * solving for the parameter of each angle.
   */
  class NurbsPatch
  {
  public:
    /** The rational functions nonzero on one span at one point. */
    struct Evaluation
    {
      dealii::Point<2> point;
      /** jacobian[i][j] = dX_i / d(xi, eta)_j. */
      dealii::Tensor<2, 2> jacobian;
      /** unique_control() of each function, (degree_xi + 1) (degree_eta +
       *  1) of them, xi fastest. */
      std::vector<unsigned int>         controls;
      std::vector<double>               values;
      std::vector<dealii::Tensor<1, 2>> parametric_gradients;
    };

    BSplineBasis                  xi, eta;
    std::vector<dealii::Point<2>> points;
    std::vector<double>           weights;
    bool                          closed_in_eta = false;
    /** When the patch is one of a body's several (NurbsMultipatch): each
     *  control point's number in the body, index a + n_xi b, a point of a
     *  joined side numbered once for both patches. Empty: the patch is
     *  the body, and unique_control() numbers its own points. */
    std::vector<unsigned int> body_numbers;

    unsigned int
    n_xi() const
    {
      return xi.n_functions();
    }
    unsigned int
    n_eta() const
    {
      return eta.n_functions();
    }
    /** The number of distinct control points (a closed patch's seam once). */
    unsigned int
    n_unique_controls() const;
    /** Control (a, b) as one number, the seam of a closed patch once (its
     *  body number, if the patch has them). */
    unsigned int
    unique_control(const unsigned int a, const unsigned int b) const;

    /** X, its Jacobian and the functions of span (s_xi, s_eta) at (u, v). */
    void
    evaluate(const unsigned int span_xi,
             const unsigned int span_eta,
             const double       u,
             const double       v,
             Evaluation        &result) const;

    /** The point only. */
    dealii::Point<2>
    point(const unsigned int span_xi,
          const unsigned int span_eta,
          const double       u,
          const double       v) const;

    /**
     * The patch's boundary on one side of span (span_xi, span_eta): `face`
     * in deal.II's numbering (0, 1: u fixed at the span's low or high end;
     * 2, 3: v), which must lie on a side of the patch. There only the
     * side's row of control points has nonzero functions (open knot
     * vectors): the p + 1 of them nonzero on the span (unique_control()
     * numbers), in the order of the moving parameter, their weights and
     * positions, and the 2p knots around the span (NurbsCurve::Segment).
     */
    struct SideSpan
    {
      std::vector<unsigned int>     controls;
      std::vector<double>           weights;
      std::vector<dealii::Point<2>> points;
      std::vector<double>           knots;
    };
    SideSpan
    side_span(unsigned int span_xi,
              unsigned int span_eta,
              unsigned int face) const;

    /** The rectangle [x0, x1] x [y0, y1], a knot at each fraction of
     *  x_knots and y_knots inside (0, 1) (graded_interval_ends). */
    static NurbsPatch
    rectangle(const dealii::Point<2>    &corner_1,
              const dealii::Point<2>    &corner_2,
              const unsigned int         degree,
              const std::vector<double> &x_knots,
              const std::vector<double> &y_knots);

    /**
     * The annulus r_in <= |X - c| <= r_out between the angles theta_0 and
     * theta_1 (radians; the whole ring if `closed`), xi radial and eta
     * along theta, its knots at n_through equal radial intervals and at
     * n_around equal angles.
     */
    static NurbsPatch
    annulus(const dealii::Point<2> &center,
            const double            inner_radius,
            const double            outer_radius,
            const double            theta_0,
            const double            theta_1,
            const bool              closed,
            const unsigned int      degree,
            const unsigned int      n_through,
            const unsigned int      n_around);

    /**
     * Moves each control point off the patch's boundary by a pseudo-random
     * vector (the same for the same patch) of length up to `factor` times
     * the distance to its nearest neighbour in the control net: a
     * distorted patch (Mesh/Distortion), its boundary unchanged.
     */
    void
    distort(const double factor);

    /** Inserts u in xi (direction 0) or eta (1), the surface unchanged. */
    void
    insert_knot(const unsigned int direction, const double u);

    /** The patch from its bases and homogeneous points (w X, w Y, w),
     *  index a + n_xi b. */
    static NurbsPatch
    from_homogeneous(const BSplineBasis                       &xi,
                     const BSplineBasis                       &eta,
                     const std::vector<std::array<double, 3>> &control);

  private:
    /** Homogeneous control points (w X, w Y, w), index a + n_xi b. */
    using Homogeneous = std::vector<std::array<double, 3>>;

    Homogeneous
    homogeneous() const;
  };
} // namespace glissade
