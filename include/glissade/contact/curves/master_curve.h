#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * A parametric 2D curve made of segments, used as the master surface of a
   * node-to-segment contact pair (Batailly, Magnain, Chevaugeon 2012,
   * sections 2.3 and 3).
   *
   * The curve is built from N data nodes (the current positions of the master
   * nodes on the contact boundary). Segment i joins node i to node i+1; for a
   * closed curve the last segment, N-1, joins node N-1 to node 0, so an open
   * curve has N-1 segments and a closed one N. On every segment the local
   * coordinate s runs over [0,1], with c(i,0) = node i and c(i,1) = node i+1
   * for all curves derived from this class (they all interpolate the nodes).
   *
   * <h3>Orientation convention</h3>
   * The unit tangent is t = c'/|c'| and the unit normal is n = e3 x t =
   * (-t_y, t_x) (paper eq. 27), i.e. t turned by +90 degrees: n points to the
   * left of the direction of travel. The caller must order the nodes so that
   * n points out of the master body, i.e. the master body lies to the right of
   * the direction of travel; for a closed master boundary this means the nodes
   * go round the body clockwise. The signed gap of a point x is then
   * g = (x - c(s*)) . n, positive when x is outside the master body.
   *
   * <h3>Closest-point projection</h3>
   * project() is written once here, on top of evaluate(), and follows the
   * detection procedure of the paper (section 3.1): nearest data node first,
   * then the segments adjacent to it, then a safeguarded Newton iteration on
   * f(s) = (c(s) - x) . c'(s) = 0 on each. The details and the rules used to
   * break ties are documented at project().
   *
   * Derived classes implement update() (rebuild from new node positions,
   * called every step, O(N)) and the evaluation functions. They must call
   * store_nodes() from update() so that the base class knows the nodes.
   *
   * All const member functions are free of hidden state, so project() may be
   * called concurrently from several threads on the same curve.
   */
  class MasterCurve
  {
  public:
    using Point = std::array<double, 2>;

    /**
     * A list of (node index, coefficient) pairs.
     */
    using NodeWeights = std::vector<std::pair<unsigned int, double>>;

    /**
     * The result of project(). All members are always finite (no NaN), even
     * when valid is false, except for an empty curve or a non-finite x.
     */
    struct Projection
    {
      /**
       * True if x has a counterpart on the curve that the contact algorithm
       * can use: an orthogonal projection on a segment, or a convex corner
       * (on_vertex). False beyond an open end (beyond_end: the paper's "no
       * xi in [-1,1]" case; all other members are still filled in for the
       * caller who wants to use them anyway), for a curve without segments,
       * and for a non-finite x.
       */
      bool valid = false;

      /** Segment of the closest point, and local coordinate s in [0,1]. */
      unsigned int segment = 0;
      double       s       = 0.;

      /** The closest point c(segment, s). */
      Point point = {{0., 0.}};

      /** Unit tangent and unit normal n = (-t_y, t_x) used for the gap. */
      Point tangent = {{1., 0.}};
      Point normal  = {{0., 1.}};

      /** Signed gap (x - point) . normal. */
      double gap = 0.;

      /** Euclidean distance |x - point|. */
      double distance = 0.;

      /** Newton iterations spent on the retained candidate (0 at an end). */
      unsigned int newton_iterations = 0;

      /**
       * The closest point is a data node at which the curve has a corner
       * (tangent discontinuity) and x lies in the normal cone of that corner:
       * no segment contains an orthogonal projection. The normal is then the
       * normalised average of the two adjacent segment normals (the normal
       * of the outgoing segment if they cancel) and segment/s describe the
       * node as s = 0 of the segment leaving it.
       */
      bool on_vertex = false;

      /**
       * The closest point is the first or last node of an open curve and x
       * is not on the normal line there (it lies beyond the end). The normal
       * is the end segment's normal at the end; valid is false.
       */
      bool beyond_end = false;
    };

    /**
     * Signature of a replacement for the brute-force nearest-node search,
     * e.g. a bucket search built by the caller from nodes() after each
     * update(). It must return the index of a node closest to x.
     */
    using NearestNodeSearch = std::function<unsigned int(const Point &)>;

    /** Hard cap on the safeguarded Newton iterations on one segment. */
    static constexpr unsigned int max_newton_iterations = 60;

    virtual ~MasterCurve() = default;

    /**
     * Rebuild the curve from the current node positions. O(N).
     */
    virtual void
    update(const std::vector<Point> &nodes) = 0;

    virtual unsigned int
    n_segments() const = 0;
    virtual bool
    is_closed() const = 0;

    /** Number of data nodes given to the last update(). */
    unsigned int
    n_nodes() const;

    /** The data nodes given to the last update(). */
    const std::vector<Point> &
    nodes() const;

    /** The two data nodes joined by a segment: {i, i+1} (or {N-1, 0}). */
    std::array<unsigned int, 2>
    segment_nodes(unsigned int segment) const;

    /**
     * Diagonal of the bounding box of the nodes (1 if they all coincide):
     * the length used to make tolerances relative.
     */
    double
    length_scale() const;

    /** Position, first and second derivative with respect to s. */
    virtual Point
    value(unsigned int segment, double s) const = 0;
    virtual Point
    derivative(unsigned int segment, double s) const = 0;
    virtual Point
    second_derivative(unsigned int segment, double s) const = 0;

    /**
     * All three at once. The default calls the three functions above;
     * derived classes override it because project() calls it in its inner
     * loop.
     */
    virtual void
    evaluate(unsigned int segment,
             double       s,
             Point       &value,
             Point       &first_derivative,
             Point       &second_derivative) const;

    /** A weight phi_j(s) of node j and its derivative d phi_j / ds. */
    struct WeightAndDerivative
    {
      unsigned int node;
      double       value;
      double       derivative;
    };
    using NodeWeightsAndDerivatives = std::vector<WeightAndDerivative>;

    /**
     * Coefficients phi_j such that c(segment, s) = sum_j phi_j node_j, the
     * weights that hand a contact force at c(segment, s) to the master nodes.
     * Only entries with |phi_j| > 1e-14 max_k |phi_k| are returned, sorted by
     * node index. The vector is cleared first. (Filters
     * weights_and_derivatives().)
     */
    void
    weights(unsigned int segment, double s, NodeWeights &node_weights) const;

    /**
     * The weights phi_j and their derivatives d phi_j / ds, so that also
     * c'(segment, s) = sum_j phi_j' node_j: what the consistent
     * linearisation of the contact needs (the master point slides along the
     * curve, theory.md section 4.2). An entry is kept if its value or its
     * derivative is above 1e-14 times the largest of its kind; sorted by
     * node index; the vector is cleared first.
     */
    virtual void
    weights_and_derivatives(unsigned int               segment,
                            double                     s,
                            NodeWeightsAndDerivatives &weights) const = 0;

    /**
     * The two linear hat weights {(node a, 1-s), (node b, s)} of the straight
     * segment joining the end nodes of the segment: the paper hands the
     * contact reaction to these two nodes of the underlying Q4 edge, whatever
     * the smoothing.
     */
    std::array<std::pair<unsigned int, double>, 2>
    underlying_segment_weights(unsigned int segment, double s) const;

    /**
     * An axis-aligned box that contains the whole segment (s in [0,1]), e.g.
     * the box of its Bezier or B-spline control polygon. project() uses it to
     * skip segments that cannot hold a closer point.
     */
    virtual void
    bounding_box(unsigned int segment, Point &low, Point &high) const = 0;

    /**
     * Unit tangent c'/|c'|. Where the parametrisation degenerates (|c'| is
     * zero, e.g. on a segment between two coincident nodes) the direction
     * from the previous to the next distinct node is used instead, and
     * (1,0) if all nodes coincide, so the result is never NaN.
     */
    Point
    unit_tangent(unsigned int segment, double s) const;

    /** n = (-t_y, t_x) with t = unit_tangent(). */
    Point
    unit_normal(unsigned int segment, double s) const;

    /**
     * Closest-point projection of x on the curve.
     *
     * 1. The nearest data node k (brute force O(N), ties to the lowest index,
     *    or the search given to set_nearest_node_search()).
     * 2. The segments adjacent to k: two, wrapping round for a closed curve,
     *    one at the ends of an open curve.
     * 3. On each segment, the minimiser of |c(s) - x| over [0,1]: f(s) =
     *    (c - x) . c' is sampled at s = 0, 1/4, 1/2, 3/4, 1; every sample
     *    interval where f goes from negative to positive brackets a local
     *    minimum, which a Newton iteration (f' = c'.c' + (c - x).c'') finds;
     *    a Newton step that leaves the bracket, or does not shrink f fast
     *    enough, is replaced by bisection, and at most
     *    max_newton_iterations are done, so it can neither diverge nor loop.
     *    Converged when |ds| < 1e-14 or |f| < 1e-15 |c'| (|c - x| + L);
     *    a root within 1e-13 of an end is snapped to that end. The two ends
     *    s = 0 and s = 1 are candidates too.
     * 4. Walk: while the best candidate sits at s = 0 (s = 1) of its segment
     *    and the previous (next) segment has not been searched, search it.
     *    This catches a closest segment that is not adjacent to the nearest
     *    node (coarse or strongly curved curves); at most n_segments() are
     *    searched.
     * 5. Choice: the smallest distance wins. Two candidates whose distances
     *    differ by less than 1e-13 (L + distances) are a tie (the distance
     *    is flat near its minimum, so it cannot separate two nearby
     *    candidates), broken first in favour of a stationary point (f = 0: an
     *    orthogonal projection) over a clamped segment end, then by the
     *    smaller (segment, s) after writing a segment end s = 1 as s = 0 of
     *    the next segment. A data node is therefore always reported as s = 0
     *    of the segment leaving it (node 0 of a closed curve as segment 0,
     *    s = 0, consistently across the seam), except the last node of an
     *    open curve (last segment, s = 1); and of two equally close distinct
     *    points (e.g. x on an axis of symmetry) the one on the lower segment
     *    index is returned. The same x always gives the same result.
     * 6. Global check: if the best point so far is a node where no
     *    orthogonal projection exists (a corner or an open end), or always if
     *    set_global_search(true) was called, every segment whose
     *    bounding_box() is closer than the best distance is searched too
     *    (O(N) box tests). This catches a closer segment elsewhere, e.g. a
     *    long segment of a coarse curve next to the end of another branch.
     * 7. If the closest point is a node, the orthogonality (x - c) . t = 0 is
     *    tested with the tangents of the outgoing and incoming segments: if
     *    it holds for one of them, that segment is reported (outgoing first);
     *    otherwise the node is a convex corner (on_vertex) or an open end
     *    (beyond_end), see Projection.
     *
     * Limitation: without set_global_search(true), an orthogonal projection
     * found from the nearest node is accepted even if another part of the
     * curve is closer (a local, not the global, minimum of the distance).
     * That takes a nearest node that is not on the closest segment while its
     * own segments still hold an orthogonal projection: x far from the curve
     * compared with the segment length and curvature radius (e.g. near the
     * centre of a wavy closed curve), or next to a segment much longer than
     * those of another branch nearby. Also, two extra stationary points
     * inside one quarter of a segment (a wiggle) can go unseen by step 3.
     * The global search costs one sweep over the cached boxes plus the
     * segments that survive it.
     */
    Projection
    project(const Point &x) const;

    /**
     * Replace the brute-force nearest node search (an empty function restores
     * it). The search must be rebuilt by the caller when the nodes move.
     */
    void
    set_nearest_node_search(const NearestNodeSearch &search);

    /**
     * Self-contact's projection: the closest point to x on the segments
     * whose bounding box lies within `reach` of x and that `allowed` admits,
     * among the projections that `accept` admits (the part of a body's
     * surface that faces a node of the same surface); invalid if there is
     * none. On each segment, steps 3 and 7 of project(); the segments are
     * searched nearest box first, and those whose box is farther than the
     * best point found are not searched. O(N) box tests.
     */
    Projection
    project_among(const Point                                   &x,
                  double                                         reach,
                  const std::function<bool(unsigned int)>       &allowed,
                  const std::function<bool(const Projection &)> &accept) const;

    /** Index of a node closest to x (lowest index on ties for brute force). */
    unsigned int
    nearest_node(const Point &x) const;

    /**
     * If true, project() always runs the global check of its step 6 and so
     * returns the global closest point; default false (the paper's local
     * search, plus the global check only at corners and open ends).
     */
    void
    set_global_search(bool global);

  protected:
    /**
     * Store the nodes and the length scale; derived classes call it first in
     * update(). Throws std::invalid_argument if there are fewer than
     * minimum_number nodes.
     */
    void
    store_nodes(const std::vector<Point> &nodes, unsigned int minimum_number);

    /**
     * Cache bounding_box() of every segment for the global check of
     * project(). Derived classes call it at the end of update() (and
     * whenever else their segments change); without it, or if the cache is
     * stale in size, project() calls bounding_box() directly, which is
     * correct but slower.
     */
    void
    cache_bounding_boxes();

    /**
     * Drops the entries that are insignificant in both value and
     * derivative (1e-14 of the largest of their kind) and sorts by node.
     */
    static void
    keep_significant(NodeWeightsAndDerivatives &weights);

    /** Segment before / after a segment: false if none (open ends). */
    bool
    previous_segment(unsigned int segment, unsigned int &previous) const;
    bool
    next_segment(unsigned int segment, unsigned int &next) const;

  private:
    /**
     * What happens at a node: the segments leaving and entering it, their
     * unit tangents there, and whether x - node is orthogonal to each.
     */
    struct NodeCase
    {
      bool         has_outgoing           = false;
      bool         has_incoming           = false;
      unsigned int outgoing               = 0;
      unsigned int incoming               = 0;
      Point        outgoing_tangent       = {{1., 0.}};
      Point        incoming_tangent       = {{1., 0.}};
      bool         orthogonal_to_outgoing = false;
      bool         orthogonal_to_incoming = false;
    };

    NodeCase
    classify_node(unsigned int node, const Point &x) const;

    /**
     * Step 6 of project(): the segments not yet searched whose bounding
     * box is within sqrt(reach2) of x, as (squared box distance, segment),
     * nearest first.
     */
    std::vector<std::pair<double, unsigned int>>
    boxes_within(const Point                     &x,
                 double                           reach2,
                 const std::vector<unsigned int> &searched) const;

    /**
     * Steps 5 and 7 of project(): the result for the closest point found,
     * at (segment, s) after newton_iterations; at a node, an orthogonal
     * projection on one of its segments, a convex corner or an open end.
     */
    Projection
    projection_from(unsigned int segment,
                    double       s,
                    unsigned int newton_iterations,
                    const Point &x) const;

    std::vector<Point>                node_positions;
    std::vector<std::array<Point, 2>> segment_boxes;
    double                            scale = 1.;
    NearestNodeSearch                 nearest_node_search;
    bool                              global_search = false;
  };
} // namespace glissade
