// Tests of glissade::HermiteQuadrilateral against independent references:
// the Kronecker conditions on the space of eq. 22 (solved here from scratch),
// the paper's printed eq. 23-25, finite differences, exact geometry and exact
// solutions. Prints every figure; exits non-zero if any check fails.
//
// Build (from the directory holding include/, source/ and tests/):
//   g++ -std=c++17 -O2 -Wall -Wextra -I include
//       source/fe/hermite_quadrilateral.cc source/fe/gauss_rule.cc
//       tests/hermite/*.cc -o /tmp/hermite_tests && /tmp/hermite_tests <group>

#include <glissade/fe/gauss_rule.h>
#include <glissade/fe/hermite_quadrilateral.h>

#include <functional>
#include <map>
#include <string>

#include "hermite_test_poisson.h"
#include "hermite_test_reference.h"
#include "hermite_test_tools.h"

using namespace hermite_tests;
using ShapeArray = HermiteQuadrilateral::ShapeArray;

namespace
{
  const double pi = std::acos(-1.0);

  // The polar parametrization of a ring: p = r (xi radial), q = theta.
  HermiteQuadrilateral::ParametrizationValue
  polar(const double r, const double theta)
  {
    return {{r * std::cos(theta), r * std::sin(theta)},
            {std::cos(theta), std::sin(theta)},
            {-r * std::sin(theta), r * std::cos(theta)}};
  }

  HermiteQuadrilateral
  ring_element(const double r0,
               const double r1,
               const double t0,
               const double t1)
  {
    return HermiteQuadrilateral::from_parametrization(polar,
                                                      {r0, r1},
                                                      {t0, t1});
  }

  // A distorted, counterclockwise straight-sided quadrilateral.
  const std::array<Vector, 4> distorted_vertices = {
    {{0.1, -0.2}, {1.3, 0.1}, {1.1, 1.4}, {-0.3, 0.9}}};

  // Physical dofs (value, d/dx, d/dy per node) of u = c0 + c . X.
  ShapeArray
  linear_field_dofs(const HermiteQuadrilateral &element,
                    const double                c0,
                    const Vector               &c)
  {
    ShapeArray dofs;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const Vector &X = element.node_geometry(a).point;
        dofs[3 * a]     = c0 + c[0] * X[0] + c[1] * X[1];
        dofs[3 * a + 1] = c[0];
        dofs[3 * a + 2] = c[1];
      }
    return dofs;
  }

  double
  dot(const ShapeArray &a, const ShapeArray &b)
  {
    double sum = 0;
    for (unsigned int i = 0; i < 12; ++i)
      sum += a[i] * b[i];
    return sum;
  }

  double
  distance(const Vector &a, const Vector &b)
  {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
  }

  // ------------------------------------------------------------------------
  // The conversions to deal.II's numbering, against deal.II's own tables
  // (GeometryInfo<2>::unit_cell_vertex and face_to_cell_vertices, copied).
  void
  test_numbering(Checker &check)
  {
    std::printf("\nNode and edge numbering vs deal.II\n");
    const double       unit_vertex[4][2]   = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    const unsigned int face_vertices[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
    unsigned int       mismatches          = 0;
    for (unsigned int v = 0; v < 4; ++v)
      {
        const unsigned int node =
          HermiteQuadrilateral::node_from_dealii_vertex(v);
        const Vector x = HermiteQuadrilateral::node_reference_point(node);
        mismatches +=
          (x[0] != 2 * unit_vertex[v][0] - 1) +
          (x[1] != 2 * unit_vertex[v][1] - 1) +
          (HermiteQuadrilateral::dealii_vertex_from_node(node) != v);
      }
    for (unsigned int f = 0; f < 4; ++f)
      {
        const auto edge  = HermiteQuadrilateral::edge_from_dealii_face(f);
        const auto nodes = HermiteQuadrilateral::edge_nodes(edge.edge);
        const unsigned int first = edge.reversed ? nodes[1] : nodes[0];
        const unsigned int last  = edge.reversed ? nodes[0] : nodes[1];
        mismatches +=
          (first !=
           HermiteQuadrilateral::node_from_dealii_vertex(face_vertices[f][0])) +
          (last !=
           HermiteQuadrilateral::node_from_dealii_vertex(face_vertices[f][1]));
        // The edge's reference points run from its first to its last node.
        for (const double s : {-1.0, 1.0})
          {
            const Vector x =
              HermiteQuadrilateral::edge_reference_point(edge.edge, s);
            const Vector n =
              HermiteQuadrilateral::node_reference_point(nodes[s < 0 ? 0 : 1]);
            mismatches += (x[0] != n[0]) + (x[1] != n[1]);
          }
      }
    check.at_most("vertex, face and edge-end mismatches with deal.II tables",
                  mismatches,
                  0);
  }

  // ------------------------------------------------------------------------
  void
  test_geometry_and_linear_fields(Checker &check, Random &random)
  {
    std::printf("\nGeometry, physical Kronecker, linear reproduction\n");

    // Straight sides with half edge vectors: exactly the bilinear map.
    const auto straight =
      HermiteQuadrilateral::from_straight_sides(distorted_vertices);
    double bilinear_point = 0, bilinear_jacobian = 0;
    for (unsigned int k = 0; k < 50; ++k)
      {
        const double x = random.uniform(), e = random.uniform();
        const double w[4]   = {(1 - x) * (1 - e) / 4,
                               (1 + x) * (1 - e) / 4,
                               (1 + x) * (1 + e) / 4,
                               (1 - x) * (1 + e) / 4};
        const double w_x[4] = {-(1 - e) / 4,
                               (1 - e) / 4,
                               (1 + e) / 4,
                               -(1 + e) / 4};
        const double w_e[4] = {-(1 - x) / 4,
                               -(1 + x) / 4,
                               (1 + x) / 4,
                               (1 - x) / 4};
        Vector       X = {0, 0}, X_xi = {0, 0}, X_eta = {0, 0};
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 2; ++d)
            {
              X[d] += w[a] * distorted_vertices[a][d];
              X_xi[d] += w_x[a] * distorted_vertices[a][d];
              X_eta[d] += w_e[a] * distorted_vertices[a][d];
            }
        const auto J = straight.jacobian(x, e);
        bilinear_point =
          std::max(bilinear_point, distance(straight.point(x, e), X));
        for (unsigned int d = 0; d < 2; ++d)
          bilinear_jacobian = std::max({bilinear_jacobian,
                                        std::abs(J[d][0] - X_xi[d]),
                                        std::abs(J[d][1] - X_eta[d])});
      }
    check.at_most("straight sides: |X - bilinear map| at 50 random points",
                  bilinear_point,
                  1e-15);
    check.at_most("straight sides: |J - bilinear Jacobian|",
                  bilinear_jacobian,
                  1e-15);

    const auto ring = ring_element(0.5, 2.0, 0.3, 0.5);
    const std::pair<const char *, const HermiteQuadrilateral *> elements[2] = {
      {"distorted quad", &straight}, {"ring element", &ring}};
    for (const auto &[name, element] : elements)
      {
        // Physical Kronecker: at node a, phi_a^x has gradient (1, 0) etc.
        double physical_kronecker = 0;
        for (unsigned int a = 0; a < 4; ++a)
          {
            const Vector x = HermiteQuadrilateral::node_reference_point(a);
            const auto   v = element->evaluate(x[0], x[1]);
            physical_kronecker =
              std::max(physical_kronecker,
                       distance(v.point, element->node_geometry(a).point));
            for (unsigned int i = 0; i < 12; ++i)
              {
                const double expected[3] = {i == 3 * a ? 1.0 : 0.0,
                                            i == 3 * a + 1 ? 1.0 : 0.0,
                                            i == 3 * a + 2 ? 1.0 : 0.0};
                physical_kronecker =
                  std::max({physical_kronecker,
                            std::abs(v.shape_values[i] - expected[0]),
                            std::abs(v.shape_gradients[i][0] - expected[1]),
                            std::abs(v.shape_gradients[i][1] - expected[2])});
              }
          }
        check.at_most(std::string(name) +
                        ": physical Kronecker (value, d/dx, d/dy)",
                      physical_kronecker,
                      1e-13);

        // Linear fields are reproduced exactly (isoparametric + unity).
        double value_error = 0, gradient_error = 0, unity = 0, min_det = 1e300;
        for (unsigned int k = 0; k < 50; ++k)
          {
            const double     c0   = random.uniform();
            const Vector     c    = {random.uniform(), random.uniform()};
            const ShapeArray dofs = linear_field_dofs(*element, c0, c);
            const auto       v =
              element->evaluate(random.uniform(), random.uniform());
            double sum  = 0;
            Vector grad = {0, 0};
            for (unsigned int i = 0; i < 12; ++i)
              {
                grad[0] += dofs[i] * v.shape_gradients[i][0];
                grad[1] += dofs[i] * v.shape_gradients[i][1];
              }
            for (unsigned int a = 0; a < 4; ++a)
              sum += v.shape_values[3 * a];
            unity   = std::max(unity, std::abs(sum - 1));
            min_det = std::min(min_det, v.jacobian_determinant);
            value_error =
              std::max(value_error,
                       std::abs(dot(dofs, v.shape_values) -
                                (c0 + c[0] * v.point[0] + c[1] * v.point[1])));
            gradient_error = std::max(gradient_error, distance(grad, c));
          }
        check.at_most(std::string(name) + ": partition of unity (physical)",
                      unity,
                      1e-15);
        check.at_most(std::string(name) + ": linear field, max value error",
                      value_error,
                      1e-14);
        check.at_most(std::string(name) + ": linear field, max gradient error",
                      gradient_error,
                      1e-13);
        check.between(std::string(name) + ": min det J > 0",
                      min_det,
                      1e-3,
                      1e3);
      }

    // The ring element's geometry: its arcs interpolate the circle. Print the
    // largest radial deviation on the outer arc.
    double radial = 0;
    for (unsigned int k = 0; k <= 100; ++k)
      {
        const Vector X = ring.point(1.0, -1.0 + 2.0 * k / 100);
        radial = std::max(radial, std::abs(std::hypot(X[0], X[1]) - 2.0));
      }
    check.at_most("ring [0.5,2]x[0.3,0.5]: max |r - 2| along the outer arc",
                  radial,
                  1e-5);
  }

  // ------------------------------------------------------------------------
  // Random physical dofs for the nodes of a small mesh.
  std::vector<Vector>
  random_nodal_data(Random &random, const std::size_t n_nodes)
  {
    std::vector<Vector> data(3 * n_nodes);
    for (auto &d : data)
      d = {random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2)};
    return data;
  }

  // The element dof vectors of both displacement components.
  std::array<ShapeArray, 2>
  gather(const std::vector<Vector>         &data,
         const std::array<unsigned int, 4> &nodes)
  {
    std::array<ShapeArray, 2> dofs;
    for (unsigned int i = 0; i < 12; ++i)
      for (unsigned int c = 0; c < 2; ++c)
        dofs[c][i] = data[3 * nodes[i / 3] + i % 3][c];
    return dofs;
  }

  void
  test_edges(Checker &check, Random &random)
  {
    std::printf("\nShared edges: conformity and the C1 boundary\n");

    // Two straight-sided elements sharing the edge between global nodes 1
    // and 2; element A's edge 1 (s up) is element B's edge 3 (s down).
    const std::array<Vector, 6> P = {
      {{0, 0}, {1.1, 0.2}, {0.9, 1.2}, {-0.1, 0.8}, {2.0, -0.1}, {2.2, 1.1}}};
    const auto straight_a =
      HermiteQuadrilateral::from_straight_sides({P[0], P[1], P[2], P[3]});
    const auto straight_b =
      HermiteQuadrilateral::from_straight_sides({P[1], P[4], P[5], P[2]});
    // Two ring elements sharing the radial edge theta = 0.4, with different
    // angular widths; A's edge 2 (from r1 to r0) is B's edge 0 (r0 to r1).
    const auto ring_a = ring_element(1.0, 1.5, 0.3, 0.4);
    const auto ring_b = ring_element(1.0, 1.5, 0.4, 0.55);

    struct Pair
    {
      const char                 *name;
      const HermiteQuadrilateral *a, *b;
      std::array<unsigned int, 4> nodes_a, nodes_b;
      unsigned int                edge_a, edge_b;
    };
    const Pair pairs[2] = {
      {"straight pair",
       &straight_a,
       &straight_b,
       {0, 1, 2, 3},
       {1, 4, 5, 2},
       1,
       3},
      {"ring pair", &ring_a, &ring_b, {0, 1, 2, 3}, {3, 2, 4, 5}, 2, 0}};
    for (const Pair &pair : pairs)
      {
        double trace = 0, weights = 0, edge_fd = 0;
        for (unsigned int trial = 0; trial < 5; ++trial)
          {
            const auto data = random_nodal_data(random, 6);
            const auto da   = gather(data, pair.nodes_a),
                       db   = gather(data, pair.nodes_b);
            for (unsigned int k = 0; k <= 20; ++k)
              {
                const double s = -1.0 + 2.0 * k / 20;
                const auto   pa =
                  pair.a->edge_point(pair.edge_a, s, da[0], da[1]);
                const auto pb =
                  pair.b->edge_point(pair.edge_b, -s, db[0], db[1]);
                trace = std::max(trace, distance(pa.position, pb.position));
                // Weights of the same global dof agree; off-edge ones vanish.
                std::vector<double> wa(18, 0.0), wb(18, 0.0);
                for (unsigned int i = 0; i < 12; ++i)
                  {
                    wa[3 * pair.nodes_a[i / 3] + i % 3] += pa.weights[i];
                    wb[3 * pair.nodes_b[i / 3] + i % 3] += pb.weights[i];
                  }
                for (unsigned int g = 0; g < 18; ++g)
                  weights = std::max(weights, std::abs(wa[g] - wb[g]));
                // The edge tangent and its derivative against differences.
                const double h = 1e-5;
                const auto   pp =
                  pair.a->edge_point(pair.edge_a, s + h, da[0], da[1]);
                const auto pm =
                  pair.a->edge_point(pair.edge_a, s - h, da[0], da[1]);
                for (unsigned int d = 0; d < 2; ++d)
                  edge_fd = std::max(
                    {edge_fd,
                     std::abs((pp.position[d] - pm.position[d]) / (2 * h) -
                              pa.tangent[d]),
                     std::abs((pp.tangent[d] - pm.tangent[d]) / (2 * h) -
                              pa.tangent_derivative[d])});
              }
          }
        check.at_most(std::string(pair.name) +
                        ": max |trace A - trace B| (deformed)",
                      trace,
                      1e-14);
        check.at_most(std::string(pair.name) +
                        ": max |weight A - weight B| per dof",
                      weights,
                      1e-14);
        check.at_most(std::string(pair.name) +
                        ": edge tangent, d tangent/ds vs diff.",
                      edge_fd,
                      1e-8);
      }

    // C1 boundary: the outer arc r = 1.5 is edge 1 of both ring elements;
    // the shared node is A's node 2 (s = 1) and B's node 1 (s = -1).
    double ring_kink = 0, straight_kink = 0;
    for (unsigned int trial = 0; trial < 20; ++trial)
      {
        const auto data = random_nodal_data(random, 6);
        const auto da   = gather(data, pairs[1].nodes_a),
                   db   = gather(data, pairs[1].nodes_b);
        const Vector ta = ring_a.edge_point(1, 1.0, da[0], da[1]).tangent;
        const Vector tb = ring_b.edge_point(1, -1.0, db[0], db[1]).tangent;
        ring_kink =
          std::max(ring_kink,
                   std::abs(std::atan2(ta[0] * tb[1] - ta[1] * tb[0],
                                       ta[0] * tb[0] + ta[1] * tb[1])));
        // Contrast: the straight pair's bottom boundary (edges 0) keeps its
        // kink at node 1 -- the C1 property needs parallel reference tangents.
        const auto sa   = gather(data, pairs[0].nodes_a),
                   sb   = gather(data, pairs[0].nodes_b);
        const Vector ua = straight_a.edge_point(0, 1.0, sa[0], sa[1]).tangent;
        const Vector ub = straight_b.edge_point(0, -1.0, sb[0], sb[1]).tangent;
        straight_kink =
          std::max(straight_kink,
                   std::abs(std::atan2(ua[0] * ub[1] - ua[1] * ub[0],
                                       ua[0] * ub[0] + ua[1] * ub[1])));
      }
    check.at_most(
      "ring pair, outer arc: max angle between deformed tangents (rad)",
      ring_kink,
      1e-14);
    std::printf(
      "  (contrast) straight pair, bottom edges: max kink angle %.3f rad\n",
      straight_kink);

    // Eq. 29: the nodal forces do the same virtual work as F at the point.
    const auto   data   = random_nodal_data(random, 4);
    const auto   d      = gather(data, {0, 1, 2, 3});
    const auto   p      = ring_a.edge_point(1, 0.3, d[0], d[1]);
    const auto   p0     = ring_a.edge_point(1, 0.3, ShapeArray{}, ShapeArray{});
    const Vector F      = {0.7, -1.3};
    const auto   forces = HermiteQuadrilateral::distribute_force(p, F);
    const double work   = dot(forces[0], d[0]) + dot(forces[1], d[1]);
    check.at_most("eq. 29: |sum F^e . U - F . u(s)|",
                  std::abs(work - (F[0] * (p.position[0] - p0.position[0]) +
                                   F[1] * (p.position[1] - p0.position[1]))),
                  1e-15);
  }

  // ------------------------------------------------------------------------
  void
  test_integration(Checker &check)
  {
    std::printf("\nIntegration with the paper's 3 x 3 Gauss rule\n");
    const auto rule       = glissade::paper_hermite_rule();
    double     weight_sum = 0;
    for (const auto &q : rule)
      weight_sum += q.weight;
    check.at_most("3 x 3 rule: |sum of weights - 4|",
                  std::abs(weight_sum - 4),
                  1e-14);

    std::printf("  ring element around r = 1.25, theta = 0.4, shrinking:\n"
                "  %10s %10s %14s %7s\n",
                "dr",
                "dtheta",
                "rel. area error",
                "rate");
    double previous = 0, last_rate = 0;
    for (unsigned int level = 0; level <= 5; ++level)
      {
        const double dr = 0.5 / (1 << level), dt = 0.4 / (1 << level);
        const auto   element = ring_element(1.25 - dr / 2,
                                          1.25 + dr / 2,
                                          0.4 - dt / 2,
                                          0.4 + dt / 2);
        double       area    = 0;
        for (const auto &q : rule)
          area += q.weight * element.evaluate(q.xi, q.eta).jacobian_determinant;
        const double exact =
          dt / 2 * (std::pow(1.25 + dr / 2, 2) - std::pow(1.25 - dr / 2, 2));
        const double error = std::abs(area - exact) / exact;
        if (level > 0)
          last_rate = rate(previous, error);
        std::printf("  %10.5f %10.5f %14.4e %7.3f\n",
                    dr,
                    dt,
                    error,
                    level > 0 ? last_rate : 0.0);
        previous = error;
      }
    check.between("ring area: relative error rate (last halving)",
                  last_rate,
                  3.8,
                  4.3);

    // Spurious zero-energy modes: rank of element stiffness matrices.
    const auto ring = ring_element(0.5, 2.0, 0.3, 0.5);
    const auto straight =
      HermiteQuadrilateral::from_straight_sides(distorted_vertices);
    for (unsigned int n_points : {2u, 3u})
      for (const auto *element : {&straight, &ring})
        {
          std::vector<std::vector<double>> laplace(12,
                                                   std::vector<double>(12,
                                                                       0.0));
          std::vector<std::vector<double>> elastic(24,
                                                   std::vector<double>(24,
                                                                       0.0));
          for (const auto &q : glissade::tensor_gauss_rule(n_points))
            {
              const auto   v  = element->evaluate(q.xi, q.eta);
              const double dx = q.weight * v.jacobian_determinant;
              // Plane strain, lambda = mu = 1; dofs (u_x 0..11, u_y 12..23).
              std::array<std::array<double, 24>, 3> B = {};
              for (unsigned int i = 0; i < 12; ++i)
                {
                  const Vector &g = v.shape_gradients[i];
                  B[0][i] = g[0], B[1][12 + i] = g[1];
                  B[2][i] = g[1], B[2][12 + i] = g[0];
                }
              const double C[3][3] = {{3, 1, 0}, {1, 3, 0}, {0, 0, 1}};
              for (unsigned int i = 0; i < 24; ++i)
                for (unsigned int j = 0; j < 24; ++j)
                  for (unsigned int k = 0; k < 3; ++k)
                    for (unsigned int l = 0; l < 3; ++l)
                      elastic[i][j] += B[k][i] * C[k][l] * B[l][j] * dx;
              for (unsigned int i = 0; i < 12; ++i)
                for (unsigned int j = 0; j < 12; ++j)
                  laplace[i][j] +=
                    (v.shape_gradients[i][0] * v.shape_gradients[j][0] +
                     v.shape_gradients[i][1] * v.shape_gradients[j][1]) *
                    dx;
            }
          const std::string name =
            std::to_string(n_points) + "x" + std::to_string(n_points) +
            " rule, " + (element == &ring ? "ring" : "distorted quad");
          const unsigned int rank_laplace = numerical_rank(laplace, 1e-12);
          const unsigned int rank_elastic = numerical_rank(elastic, 1e-12);
          if (n_points == 3)
            {
              check.between(name + ": rank of Laplace matrix (full = 11)",
                            rank_laplace,
                            11,
                            11);
              check.between(name + ": rank of elasticity matrix (full = 21)",
                            rank_elastic,
                            21,
                            21);
            }
          else
            std::printf("  (contrast) %s: ranks %u (Laplace, full 11), "
                        "%u (elasticity, full 21)\n",
                        name.c_str(),
                        rank_laplace,
                        rank_elastic);
        }
  }

  // ------------------------------------------------------------------------
  void
  test_poisson(Checker &check)
  {
    std::printf("\nPoisson convergence (3 x 3 Gauss assembly, boundary nodes: "
                "all 3 dofs exact)\n");
    const unsigned int max_n       = 32;
    const auto         unit_square = [](unsigned int n) {
      return straight_sided_mesh(n, [n](unsigned int i, unsigned int j) {
        return Vector{double(i) / n, double(j) / n};
      });
    };
    // Vertices moved by a smooth map of the square onto itself: elements
    // become parallelograms as h -> 0.
    const auto smooth = [](unsigned int n) {
      return straight_sided_mesh(n, [n](unsigned int i, unsigned int j) {
        const double x = double(i) / n, y = double(j) / n;
        return Vector{x + 0.1 * std::sin(pi * x) * std::sin(2 * pi * y),
                      y + 0.1 * std::sin(2 * pi * x) * std::sin(pi * y)};
      });
    };
    // Trapezoids at every level (interior nodes moved by +-0.2 h in y,
    // alternating): never parallelograms.
    const auto trapezoids = [](unsigned int n) {
      return straight_sided_mesh(n, [n](unsigned int i, unsigned int j) {
        const double shift =
          (j == 0 || j == n) ? 0.0 : ((i + j) % 2 ? 0.2 : -0.2);
        return Vector{double(i) / n, (j + shift) / n};
      });
    };

    poisson_convergence_study(check,
                              "unit square, u = sin(pi x) sin(pi y)",
                              unit_square,
                              sine_solution(),
                              max_n,
                              {3.8, 4.2},
                              {2.8, 3.2});
    poisson_convergence_study(check,
                              "unit square, u = exp(0.7 x)(1 + x y^2)",
                              unit_square,
                              exp_polynomial_solution(),
                              max_n,
                              {3.8, 4.2},
                              {2.8, 3.2});
    poisson_convergence_study(check,
                              "smoothly distorted square, sine",
                              smooth,
                              sine_solution(),
                              max_n,
                              {3.7, 4.3},
                              {2.7, 3.3});
    poisson_convergence_study(check,
                              "quarter annulus 1<r<2, curved, sine",
                              quarter_annulus_mesh,
                              sine_solution(),
                              max_n,
                              {3.7, 4.3},
                              {2.7, 3.3});
    // On quadrilaterals that stay non-parallelogram under refinement, the
    // 12-term (cubic serendipity) space composed with the bilinear map no
    // longer contains all physical quadratics (Arnold, Boffi, Falk, Math.
    // Comp. 2002: serendipity of degree 3 gives O(h^2) in L2, O(h) in H1).
    // The windows document that expected loss; the paper's ring meshes are
    // asymptotically affine and keep the full rates (quarter annulus above).
    poisson_convergence_study(check,
                              "trapezoidal mesh (non-affine at all h), sine",
                              trapezoids,
                              sine_solution(),
                              max_n,
                              {1.8, 2.6},
                              {0.8, 1.4});
  }
} // namespace

// Each group is a ctest test of its own ("elements_hermite_<group>").
// Each is a ctest test of its own ("elements_hermite_<name>",
// tests/harness.h).
static const glissade_tests::Registrations tests = {
  {{"reference_functions",
    [] {
      Checker check;
      Random  random;
      test_reference_functions(check, random);
    }},
   {"numbering",
    [] {
      Checker check;
      test_numbering(check);
    }},
   {"geometry_linear_fields",
    [] {
      Checker check;
      Random  random;
      test_geometry_and_linear_fields(check, random);
    }},
   {"edges_c1",
    [] {
      Checker check;
      Random  random;
      test_edges(check, random);
    }},
   {"integration",
    [] {
      Checker check;
      test_integration(check);
    }},
   {"poisson_convergence", [] {
      Checker check;
      test_poisson(check);
    }}}};
