#include <glissade/fe/hermite_quadrilateral.h>

#include <stdexcept>

namespace glissade
{
  namespace
  {
    // Node reference coordinates in the paper's counterclockwise order.
    constexpr double node_xi[4]  = {-1.0, 1.0, 1.0, -1.0};
    constexpr double node_eta[4] = {-1.0, -1.0, 1.0, 1.0};

    void
    check_index(const unsigned int index, const char *what)
    {
      if (index >= 4)
        throw std::out_of_range(what);
    }
  } // namespace

  // ---------------------------------------------------------------- numbering
  HermiteQuadrilateral::Vector
  HermiteQuadrilateral::node_reference_point(const unsigned int node)
  {
    check_index(node, "HermiteQuadrilateral: node index out of range");
    return {{node_xi[node], node_eta[node]}};
  }

  unsigned int
  HermiteQuadrilateral::node_from_dealii_vertex(const unsigned int vertex)
  {
    check_index(vertex, "HermiteQuadrilateral: vertex index out of range");
    // Lexicographic (0,1,2,3) = (--, +-, -+, ++); counterclockwise swaps the
    // last two.
    constexpr unsigned int map[4] = {0, 1, 3, 2};
    return map[vertex];
  }

  unsigned int
  HermiteQuadrilateral::dealii_vertex_from_node(const unsigned int node)
  {
    // The permutation (2 3) is its own inverse.
    return node_from_dealii_vertex(node);
  }

  std::array<unsigned int, 2>
  HermiteQuadrilateral::edge_nodes(const unsigned int edge)
  {
    check_index(edge, "HermiteQuadrilateral: edge index out of range");
    return {{edge, (edge + 1) % 4}};
  }

  HermiteQuadrilateral::EdgeOfFace
  HermiteQuadrilateral::edge_from_dealii_face(const unsigned int face)
  {
    check_index(face, "HermiteQuadrilateral: face index out of range");
    // deal.II face 0 (xi=-1) runs from vertex 0 to 2, i.e. upward, while our
    // edge 3 runs downward; face 3 (eta=1) runs rightward, our edge 2
    // leftward.
    constexpr EdgeOfFace map[4] = {{3, true},
                                   {1, false},
                                   {0, false},
                                   {2, true}};
    return map[face];
  }

  HermiteQuadrilateral::Vector
  HermiteQuadrilateral::edge_reference_point(const unsigned int edge,
                                             const double       s)
  {
    check_index(edge, "HermiteQuadrilateral: edge index out of range");
    const Vector start     = node_reference_point(edge);
    const Vector direction = edge_reference_direction(edge);
    // Start at node e for s = -1 and move by (s + 1) along the direction.
    return {{start[0] + (s + 1.0) * direction[0],
             start[1] + (s + 1.0) * direction[1]}};
  }

  HermiteQuadrilateral::Vector
  HermiteQuadrilateral::edge_reference_direction(const unsigned int edge)
  {
    check_index(edge, "HermiteQuadrilateral: edge index out of range");
    constexpr double direction[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    return {{direction[edge][0], direction[edge][1]}};
  }

  // ------------------------------------------------- reference shape functions
  //
  // With (xi_a, eta_a) the coordinates of node a and xi0 = xi_a xi,
  // eta0 = eta_a eta, the three functions of node a are
  //
  //   N_a^value = 1/8 (1 + xi0)(1 + eta0)(2 + xi0 + eta0 - xi^2 - eta^2)
  //   N_a^xi    = -xi_a/8  (1 + xi0)(1 + eta0)(1 - xi^2)
  //   N_a^eta   = -eta_a/8 (1 + xi0)(1 + eta0)(1 - eta^2)
  //
  // which is eq. 23 written once for all nodes (eq. 23 satisfies the
  // Kronecker conditions as printed). Each lies in the space of eq. 22: the
  // products only create xi^3 eta and xi eta^3 beyond the complete cubics.
  // The derivatives below are those of these expressions; they differ from
  // the paper's eq. 24 in two places, which are misprints there:
  //   N_8,xi  is  -1/8 (1 + xi)(1 + eta)(1 - 3 xi)  (paper: (1 - xi)),
  //   N_11,xi is  -1/8 (1 - xi)(1 + eta)(1 + 3 xi)  (paper: + sign).
  // Eq. 25 is correct. tests/hermite/hermite_tests.cc checks all of this.

  HermiteQuadrilateral::ShapeArray
  HermiteQuadrilateral::reference_values(const double xi, const double eta)
  {
    ShapeArray values;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const double xa = node_xi[a], ea = node_eta[a];
        const double A = 1.0 + xa * xi, B = 1.0 + ea * eta;
        const double C    = 2.0 + xa * xi + ea * eta - xi * xi - eta * eta;
        values[3 * a]     = 0.125 * A * B * C;
        values[3 * a + 1] = -0.125 * xa * A * B * (1.0 - xi * xi);
        values[3 * a + 2] = -0.125 * ea * A * B * (1.0 - eta * eta);
      }
    return values;
  }

  std::array<HermiteQuadrilateral::Vector, 12>
  HermiteQuadrilateral::reference_gradients(const double xi, const double eta)
  {
    std::array<Vector, 12> gradients;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const double xa = node_xi[a], ea = node_eta[a];
        const double A = 1.0 + xa * xi, B = 1.0 + ea * eta;
        const double C    = 2.0 + xa * xi + ea * eta - xi * xi - eta * eta;
        const double C_xi = xa - 2.0 * xi, C_eta = ea - 2.0 * eta;
        const double D = 1.0 - xi * xi, E = 1.0 - eta * eta;

        // value: 1/8 A B C
        gradients[3 * a] = {
          {0.125 * B * (xa * C + A * C_xi), 0.125 * A * (ea * C + B * C_eta)}};
        // xi-derivative function: -xa/8 A B D
        gradients[3 * a + 1] = {{-0.125 * xa * B * (xa * D - 2.0 * xi * A),
                                 -0.125 * xa * A * D * ea}};
        // eta-derivative function: -ea/8 A B E
        gradients[3 * a + 2] = {{-0.125 * ea * xa * B * E,
                                 -0.125 * ea * A * (ea * E - 2.0 * eta * B)}};
      }
    return gradients;
  }

  std::array<std::array<double, 3>, 12>
  HermiteQuadrilateral::reference_hessians(const double xi, const double eta)
  {
    std::array<std::array<double, 3>, 12> hessians;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const double xa = node_xi[a], ea = node_eta[a];
        const double A = 1.0 + xa * xi, B = 1.0 + ea * eta;
        const double C    = 2.0 + xa * xi + ea * eta - xi * xi - eta * eta;
        const double C_xi = xa - 2.0 * xi, C_eta = ea - 2.0 * eta;
        const double D = 1.0 - xi * xi, E = 1.0 - eta * eta;

        // value: A'' = B'' = 0, C'' = -2, C_xieta = 0.
        hessians[3 * a] = {{0.125 * B * (2.0 * xa * C_xi - 2.0 * A),
                            0.125 * (ea * (xa * C + A * C_xi) + B * xa * C_eta),
                            0.125 * A * (2.0 * ea * C_eta - 2.0 * B)}};
        // xi-derivative function: -xa/8 A B D, D' = -2 xi, D'' = -2.
        hessians[3 * a + 1] = {{-0.125 * xa * B * (-4.0 * xa * xi - 2.0 * A),
                                -0.125 * xa * ea * (xa * D - 2.0 * xi * A),
                                0.0}};
        // eta-derivative function: -ea/8 A B E, E' = -2 eta, E'' = -2.
        hessians[3 * a + 2] = {{0.0,
                                -0.125 * ea * xa * (ea * E - 2.0 * eta * B),
                                -0.125 * ea * A * (-4.0 * ea * eta - 2.0 * B)}};
      }
    return hessians;
  }

  // ------------------------------------------------------------------ creation
  HermiteQuadrilateral::HermiteQuadrilateral(
    const std::array<NodeGeometry, 4> &nodes)
    : nodes(nodes)
  {}

  HermiteQuadrilateral
  HermiteQuadrilateral::from_straight_sides(
    const std::array<Vector, 4> &vertices)
  {
    // Along xi the edges are 0-1 (bottom) and 3-2 (top); along eta they are
    // 0-3 (left) and 1-2 (right). Each node takes half the edge vector of
    // the edge it lies on, oriented towards increasing xi (or eta): the
    // derivative of the bilinear map at that node.
    const auto half_difference = [](const Vector &to, const Vector &from) {
      return Vector{{0.5 * (to[0] - from[0]), 0.5 * (to[1] - from[1])}};
    };
    const Vector bottom = half_difference(vertices[1], vertices[0]);
    const Vector top    = half_difference(vertices[2], vertices[3]);
    const Vector left   = half_difference(vertices[3], vertices[0]);
    const Vector right  = half_difference(vertices[2], vertices[1]);

    return HermiteQuadrilateral(
      std::array<NodeGeometry, 4>{{NodeGeometry{vertices[0], bottom, left},
                                   NodeGeometry{vertices[1], bottom, right},
                                   NodeGeometry{vertices[2], top, right},
                                   NodeGeometry{vertices[3], top, left}}});
  }

  HermiteQuadrilateral
  HermiteQuadrilateral::from_parametrization(
    const std::function<ParametrizationValue(double, double)> &parametrization,
    const Vector                                              &p_range,
    const Vector                                              &q_range)
  {
    const double                half_dp = 0.5 * (p_range[1] - p_range[0]);
    const double                half_dq = 0.5 * (q_range[1] - q_range[0]);
    std::array<NodeGeometry, 4> nodes;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const double p = node_xi[a] < 0 ? p_range[0] : p_range[1];
        const double q = node_eta[a] < 0 ? q_range[0] : q_range[1];
        const ParametrizationValue X = parametrization(p, q);
        nodes[a]                     = {X.point,
                                        {{X.d_dp[0] * half_dp, X.d_dp[1] * half_dp}},
                                        {{X.d_dq[0] * half_dq, X.d_dq[1] * half_dq}}};
      }
    return HermiteQuadrilateral(nodes);
  }

  const HermiteQuadrilateral::NodeGeometry &
  HermiteQuadrilateral::node_geometry(const unsigned int node) const
  {
    check_index(node, "HermiteQuadrilateral: node index out of range");
    return nodes[node];
  }

  // ---------------------------------------------------------------- evaluation
  HermiteQuadrilateral::Vector
  HermiteQuadrilateral::geometry_from_reference(
    const ShapeArray &reference) const
  {
    Vector X = {{0.0, 0.0}};
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 2; ++d)
        X[d] += reference[3 * a] * nodes[a].point[d] +
                reference[3 * a + 1] * nodes[a].tangent_xi[d] +
                reference[3 * a + 2] * nodes[a].tangent_eta[d];
    return X;
  }

  HermiteQuadrilateral::ShapeArray
  HermiteQuadrilateral::physical_from_reference(
    const ShapeArray &reference) const
  {
    ShapeArray physical;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const Vector &X_xi = nodes[a].tangent_xi, &X_eta = nodes[a].tangent_eta;
        physical[3 * a] = reference[3 * a];
        physical[3 * a + 1] =
          X_xi[0] * reference[3 * a + 1] + X_eta[0] * reference[3 * a + 2];
        physical[3 * a + 2] =
          X_xi[1] * reference[3 * a + 1] + X_eta[1] * reference[3 * a + 2];
      }
    return physical;
  }

  HermiteQuadrilateral::Vector
  HermiteQuadrilateral::point(const double xi, const double eta) const
  {
    return geometry_from_reference(reference_values(xi, eta));
  }

  HermiteQuadrilateral::Jacobian
  HermiteQuadrilateral::jacobian(const double xi, const double eta) const
  {
    const std::array<Vector, 12> gradients = reference_gradients(xi, eta);
    ShapeArray                   d_xi, d_eta;
    for (unsigned int i = 0; i < 12; ++i)
      {
        d_xi[i]  = gradients[i][0];
        d_eta[i] = gradients[i][1];
      }
    const Vector X_xi  = geometry_from_reference(d_xi);
    const Vector X_eta = geometry_from_reference(d_eta);
    return {{{{X_xi[0], X_eta[0]}}, {{X_xi[1], X_eta[1]}}}};
  }

  HermiteQuadrilateral::PointValues
  HermiteQuadrilateral::evaluate(const double xi, const double eta) const
  {
    PointValues                  result;
    const ShapeArray             values    = reference_values(xi, eta);
    const std::array<Vector, 12> gradients = reference_gradients(xi, eta);
    ShapeArray                   d_xi, d_eta;
    for (unsigned int i = 0; i < 12; ++i)
      {
        d_xi[i]  = gradients[i][0];
        d_eta[i] = gradients[i][1];
      }

    result.point       = geometry_from_reference(values);
    const Vector X_xi  = geometry_from_reference(d_xi);
    const Vector X_eta = geometry_from_reference(d_eta);
    result.jacobian    = {{{{X_xi[0], X_eta[0]}}, {{X_xi[1], X_eta[1]}}}};
    const double det   = X_xi[0] * X_eta[1] - X_eta[0] * X_xi[1];
    result.jacobian_determinant = det;

    result.shape_values      = physical_from_reference(values);
    const ShapeArray phi_xi  = physical_from_reference(d_xi);
    const ShapeArray phi_eta = physical_from_reference(d_eta);

    // grad phi = J^{-T} (dphi/dxi, dphi/deta), with
    // J^{-1} = 1/det [[X_eta[1], -X_eta[0]], [-X_xi[1], X_xi[0]]].
    for (unsigned int i = 0; i < 12; ++i)
      result.shape_gradients[i] = {
        {(X_eta[1] * phi_xi[i] - X_xi[1] * phi_eta[i]) / det,
         (-X_eta[0] * phi_xi[i] + X_xi[0] * phi_eta[i]) / det}};
    return result;
  }

  HermiteQuadrilateral::EdgePoint
  HermiteQuadrilateral::edge_point(const unsigned int edge,
                                   const double       s,
                                   const ShapeArray  &displacement_x_dofs,
                                   const ShapeArray  &displacement_y_dofs) const
  {
    const Vector reference = edge_reference_point(edge, s);
    const Vector t         = edge_reference_direction(edge);

    const ShapeArray values = reference_values(reference[0], reference[1]);
    const std::array<Vector, 12> gradients =
      reference_gradients(reference[0], reference[1]);
    const std::array<std::array<double, 3>, 12> hessians =
      reference_hessians(reference[0], reference[1]);

    // Chain rule along the straight reference edge (t is constant).
    ShapeArray d_ds, d2_ds2;
    for (unsigned int i = 0; i < 12; ++i)
      {
        d_ds[i]   = gradients[i][0] * t[0] + gradients[i][1] * t[1];
        d2_ds2[i] = hessians[i][0] * t[0] * t[0] +
                    2.0 * hessians[i][1] * t[0] * t[1] +
                    hessians[i][2] * t[1] * t[1];
      }

    EdgePoint result;
    result.weights     = physical_from_reference(values);
    result.weights_ds  = physical_from_reference(d_ds);
    result.weights_ds2 = physical_from_reference(d2_ds2);

    result.position           = geometry_from_reference(values);
    result.tangent            = geometry_from_reference(d_ds);
    result.tangent_derivative = geometry_from_reference(d2_ds2);
    for (unsigned int i = 0; i < 12; ++i)
      {
        result.position[0] += result.weights[i] * displacement_x_dofs[i];
        result.position[1] += result.weights[i] * displacement_y_dofs[i];
        result.tangent[0] += result.weights_ds[i] * displacement_x_dofs[i];
        result.tangent[1] += result.weights_ds[i] * displacement_y_dofs[i];
        result.tangent_derivative[0] +=
          result.weights_ds2[i] * displacement_x_dofs[i];
        result.tangent_derivative[1] +=
          result.weights_ds2[i] * displacement_y_dofs[i];
      }
    return result;
  }

  std::array<HermiteQuadrilateral::ShapeArray, 2>
  HermiteQuadrilateral::distribute_force(const EdgePoint &edge_point,
                                         const Vector    &force)
  {
    std::array<ShapeArray, 2> nodal_forces;
    for (unsigned int i = 0; i < 12; ++i)
      {
        nodal_forces[0][i] = edge_point.weights[i] * force[0];
        nodal_forces[1][i] = edge_point.weights[i] * force[1];
      }
    return nodal_forces;
  }
} // namespace glissade
