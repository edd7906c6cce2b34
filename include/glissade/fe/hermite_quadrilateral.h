#pragma once

#include <array>
#include <functional>

namespace glissade
{
  /**
   * The 4-node C1-edge Hermite quadrilateral of Batailly, Magnain, Chevaugeon
   * (Comput. Mech. 2012), section 3.2: the 12-term cubic space of eq. 22
   *
   *   1, xi, eta, xi^2, xi eta, eta^2, xi^3, xi^2 eta, xi eta^2, eta^3,
   *   xi^3 eta, xi eta^3
   *
   * (Adini's space, which is also the cubic serendipity space), with three
   * degrees of freedom per node and per displacement component (eq. 21):
   * u, du/dx, du/dy. This class is one scalar component; a vector field uses
   * the same 12 functions per component (eq. 30).
   *
   * <h3>Reference cell and node numbering</h3>
   * The reference cell is [-1, 1]^2 with coordinates (xi, eta). Nodes use the
   * paper's counterclockwise numbering, 0-based here:
   *
   *   node 0 = paper node 1 = (-1, -1)      3 ----- 2
   *   node 1 = paper node 2 = ( 1, -1)      |       |
   *   node 2 = paper node 3 = ( 1,  1)      |       |
   *   node 3 = paper node 4 = (-1,  1)      0 ----- 1
   *
   * deal.II numbers the vertices of a quadrilateral lexicographically
   * (0 = (0,0), 1 = (1,0), 2 = (0,1), 3 = (1,1) on its unit cell [0,1]^2), so
   * paper node 2 <-> deal.II vertex 3 and paper node 3 <-> deal.II vertex 2;
   * use node_from_dealii_vertex() / dealii_vertex_from_node(). deal.II's unit
   * coordinate is x_hat = (xi + 1) / 2, hence d/dx_hat = 2 d/dxi.
   *
   * Every per-element array of 12 entries is ordered node by node and, within
   * a node, (value, x-derivative, y-derivative) for physical quantities or
   * (value, xi-derivative, eta-derivative) for reference quantities: entry
   * 3 a + k is dof k of node a. This is the paper's N_1 ... N_12 order.
   *
   * <h3>Geometry</h3>
   * The geometry is isoparametric with the same space:
   *   X(xi, eta) = sum_a  N_a^value X_a + N_a^xi X_xi,a + N_a^eta X_eta,a,
   * where X_xi,a and X_eta,a are dX/dxi and dX/deta at node a. On a curved
   * body they come from its exact parametrization (see from_parametrization());
   * with deal.II, X_xi,a = +-0.5 * manifold.get_tangent_vector(X_a, X_b) for
   * the neighbour b of a along xi (+ if b lies at larger xi), provided the
   * manifold's geodesics are uniformly parametrized in the element's chart
   * (true for PolarManifold on (r, theta) cells). On a straight-sided mesh
   * they are half the edge vectors (from_straight_sides()), and X is then
   * exactly the bilinear map.
   *
   * <h3>Physical shape functions</h3>
   * Reference derivative dofs follow from physical ones through the node's
   * Jacobian: du/dxi = X_xi,a . grad u, du/deta = X_eta,a . grad u. Hence
   *   phi_a^value = N_a^value,
   *   phi_a^x     = X_xi,a[0] N_a^xi + X_eta,a[0] N_a^eta,
   *   phi_a^y     = X_xi,a[1] N_a^xi + X_eta,a[1] N_a^eta.
   * Two elements sharing an edge share the edge's reference tangent at both
   * of its nodes (when both take it from the same parametrization, or both
   * from the straight edge), so traces agree: the element is C0-conforming.
   * Along a boundary whose reference tangents at a node are parallel in the
   * two neighbouring elements (a smooth parametrized boundary), the deformed
   * boundary x = X + u keeps a continuous tangent direction: the deformed
   * tangent at the node is (I + grad u_a) X_s,a in both elements.
   *
   * <h3>Edges</h3>
   * Edge e runs counterclockwise from node e to node (e + 1) % 4, with local
   * coordinate s in [-1, 1] (s = -1 at node e); the outward normal is then the
   * tangent turned clockwise. Edge 0: eta = -1, xi = s; edge 1: xi = 1,
   * eta = s; edge 2: eta = 1, xi = -s; edge 3: xi = -1, eta = -s.
   * deal.II face f maps to edge_from_dealii_face(f); deal.II orders a face's
   * vertices lexicographically, so its faces 0 and 3 run opposite to our s.
   */
  class HermiteQuadrilateral
  {
  public:
    using Vector = std::array<double, 2>;
    /** jacobian[i][j] = dX_i / dxi_j with (xi_0, xi_1) = (xi, eta). */
    using Jacobian = std::array<std::array<double, 2>, 2>;
    /** Twelve scalars in the dof order described above. */
    using ShapeArray = std::array<double, 12>;

    static constexpr unsigned int n_nodes            = 4;
    static constexpr unsigned int dofs_per_node      = 3;
    static constexpr unsigned int dofs_per_component = 12;
    static constexpr unsigned int n_edges            = 4;

    /** What the element needs to know about one of its nodes. */
    struct NodeGeometry
    {
      Vector point;       ///< X_a
      Vector tangent_xi;  ///< X_xi,a  = dX/dxi  at the node
      Vector tangent_eta; ///< X_eta,a = dX/deta at the node
    };

    /** A parametrization evaluated at (p, q): X and its two derivatives. */
    struct ParametrizationValue
    {
      Vector point;
      Vector d_dp;
      Vector d_dq;
    };

    /** Everything a bilinear form needs at one reference point. */
    struct PointValues
    {
      Vector                 point;
      Jacobian               jacobian;
      double                 jacobian_determinant;
      ShapeArray             shape_values;
      std::array<Vector, 12> shape_gradients; ///< (d/dX, d/dY)
    };

    /**
     * One point of a deformed edge, x(s) = X(s) + u(s), and the weights that
     * tie it to the element's dofs: for each displacement component c,
     *   x_c(s) = X_c(s) + sum_i weights[i] U_c,i,
     * so a point force F applied at s contributes weights[i] F_c to dof i of
     * component c (eq. 29-30; distribute_force() does this). The s-derivatives
     * of the weights give the tangent's (and its derivative's) dependence on
     * the dofs, for a consistent linearization of the contact terms.
     * Only the 6 entries of the edge's two nodes are nonzero.
     */
    struct EdgePoint
    {
      Vector     position;           ///< x(s)
      Vector     tangent;            ///< dx/ds
      Vector     tangent_derivative; ///< d^2x/ds^2 (for a Newton projection)
      ShapeArray weights;            ///< phi_i(s)
      ShapeArray weights_ds;         ///< d phi_i / ds
      ShapeArray weights_ds2;        ///< d^2 phi_i / ds^2
    };

    /** A deal.II face seen as one of our edges. */
    struct EdgeOfFace
    {
      unsigned int edge;
      bool         reversed; ///< true if deal.II's face coordinate runs as -s
    };

    // ------------------------------------------------------------ numbering
    /** Reference coordinates (xi_a, eta_a) of node a (0-based paper order). */
    static Vector
    node_reference_point(unsigned int node);

    /** deal.II lexicographic vertex v -> our node (0,1,3,2; an involution). */
    static unsigned int
    node_from_dealii_vertex(unsigned int vertex);

    /** Our node -> deal.II lexicographic vertex. */
    static unsigned int
    dealii_vertex_from_node(unsigned int node);

    /** The two nodes of edge e, in the direction of increasing s. */
    static std::array<unsigned int, 2>
    edge_nodes(unsigned int edge);

    /** deal.II face f (0: xi=-1, 1: xi=1, 2: eta=-1, 3: eta=1) as an edge. */
    static EdgeOfFace
    edge_from_dealii_face(unsigned int face);

    /** (xi, eta) of the point at local coordinate s on edge e. */
    static Vector
    edge_reference_point(unsigned int edge, double s);

    /** d(xi, eta)/ds along edge e (a constant unit vector). */
    static Vector
    edge_reference_direction(unsigned int edge);

    // -------------------------------------------- reference shape functions
    /** N_1 ... N_12 of eq. 23 at (xi, eta). */
    static ShapeArray
    reference_values(double xi, double eta);

    /** (dN/dxi, dN/deta) of each function (eq. 24-25, corrected). */
    static std::array<Vector, 12>
    reference_gradients(double xi, double eta);

    /** (d2N/dxi2, d2N/dxi deta, d2N/deta2) of each function. */
    static std::array<std::array<double, 3>, 12>
    reference_hessians(double xi, double eta);

    // ------------------------------------------------------------ creation
    /** An element from its four nodes, in (0-based) paper order. */
    explicit HermiteQuadrilateral(const std::array<NodeGeometry, 4> &nodes);

    /**
     * A straight-sided element from its vertices in paper order: the
     * tangents are half the edge vectors leaving each node, so the geometry
     * is exactly the bilinear map.
     */
    static HermiteQuadrilateral
    from_straight_sides(const std::array<Vector, 4> &vertices);

    /**
     * An element covering the parameter box [p0, p1] x [q0, q1] of a
     * parametrization X(p, q): xi runs along p, eta along q, so
     * X_xi = dX/dp (p1 - p0)/2 and X_eta = dX/dq (q1 - q0)/2. For a ring
     * element, p = r and q = theta gives a radial xi direction. The box must
     * be oriented so that the element is counterclockwise (det J > 0).
     */
    static HermiteQuadrilateral
    from_parametrization(
      const std::function<ParametrizationValue(double, double)>
                   &parametrization,
      const Vector &p_range,
      const Vector &q_range);

    const NodeGeometry &
    node_geometry(unsigned int node) const;

    // --------------------------------------------------------- evaluation
    /** X(xi, eta). */
    Vector
    point(double xi, double eta) const;

    /** dX/d(xi, eta) at (xi, eta). */
    Jacobian
    jacobian(double xi, double eta) const;

    /** Point, Jacobian, det J, physical shape values and gradients. */
    PointValues
    evaluate(double xi, double eta) const;

    /**
     * Applies the node transformation to any reference quantity: given
     * N_i (or one derivative of them), returns phi_i (or the same derivative
     * of them) in the physical dof order.
     */
    ShapeArray
    physical_from_reference(const ShapeArray &reference) const;

    /**
     * Sum over nodes of reference[3a] X_a + reference[3a+1] X_xi,a +
     * reference[3a+2] X_eta,a: the geometry (or one derivative of it) from
     * the reference shape functions (or that derivative of them).
     */
    Vector
    geometry_from_reference(const ShapeArray &reference) const;

    /**
     * The deformed edge at s, given the element's 12 physical dofs of each
     * displacement component (pass zeros for the undeformed edge).
     */
    EdgePoint
    edge_point(unsigned int      edge,
               double            s,
               const ShapeArray &displacement_x_dofs,
               const ShapeArray &displacement_y_dofs) const;

    /** Nodal forces of a point force F at an edge point (eq. 29). */
    static std::array<ShapeArray, 2>
    distribute_force(const EdgePoint &edge_point, const Vector &force);

  private:
    std::array<NodeGeometry, 4> nodes;
  };
} // namespace glissade
