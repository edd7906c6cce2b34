// The scalar Poisson solve with the Hermite element of hermite_test_poisson.h
// and its convergence study.

#include "hermite_test_poisson.h"

#include <glissade/fe/gauss_rule.h>
#include <glissade/fe/hermite_quadrilateral.h>

#include <cmath>
#include <functional>
#include <vector>

#include "hermite_test_tools.h"

namespace hermite_tests
{
  HermiteMesh
  straight_sided_mesh(
    const unsigned int                                       n,
    const std::function<Vector(unsigned int, unsigned int)> &vertex)
  {
    HermiteMesh mesh;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        {
          mesh.node_points.push_back(vertex(i, j));
          mesh.node_on_boundary.push_back(i == 0 || j == 0 || i == n || j == n);
        }
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int                v0    = j * (n + 1) + i;
          const std::array<unsigned int, 4> nodes = {v0,
                                                     v0 + 1,
                                                     v0 + n + 2,
                                                     v0 + n + 1};
          mesh.element_nodes.push_back(nodes);
          mesh.elements.push_back(HermiteQuadrilateral::from_straight_sides(
            {mesh.node_points[nodes[0]],
             mesh.node_points[nodes[1]],
             mesh.node_points[nodes[2]],
             mesh.node_points[nodes[3]]}));
        }
    return mesh;
  }

  HermiteMesh
  quarter_annulus_mesh(const unsigned int n)
  {
    const double pi    = std::acos(-1.0);
    const auto   polar = [](const double r, const double theta) {
      return HermiteQuadrilateral::ParametrizationValue{
        {r * std::cos(theta), r * std::sin(theta)},
        {std::cos(theta), std::sin(theta)},
        {-r * std::sin(theta), r * std::cos(theta)}};
    };
    const auto r_of     = [n](unsigned int i) { return 1.0 + double(i) / n; };
    const auto theta_of = [n, pi](unsigned int j) { return 0.5 * pi * j / n; };

    HermiteMesh mesh =
      straight_sided_mesh(n, [&](unsigned int i, unsigned int j) {
        return polar(r_of(i), theta_of(j)).point;
      });
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        mesh.elements[j * n + i] = HermiteQuadrilateral::from_parametrization(
          polar, {r_of(i), r_of(i + 1)}, {theta_of(j), theta_of(j + 1)});
    return mesh;
  }

  ExactSolution
  sine_solution()
  {
    const double pi = std::acos(-1.0);
    return {[pi](const Vector &x) {
              return std::sin(pi * x[0]) * std::sin(pi * x[1]);
            },
            [pi](const Vector &x) {
              return Vector{pi * std::cos(pi * x[0]) * std::sin(pi * x[1]),
                            pi * std::sin(pi * x[0]) * std::cos(pi * x[1])};
            },
            [pi](const Vector &x) {
              return 2 * pi * pi * std::sin(pi * x[0]) * std::sin(pi * x[1]);
            }};
  }

  ExactSolution
  exp_polynomial_solution()
  {
    const double a = 0.7;
    return {[a](const Vector &x) {
              return std::exp(a * x[0]) * (1 + x[0] * x[1] * x[1]);
            },
            [a](const Vector &x) {
              const double E = std::exp(a * x[0]);
              return Vector{E * (a * (1 + x[0] * x[1] * x[1]) + x[1] * x[1]),
                            E * 2 * x[0] * x[1]};
            },
            [a](const Vector &x) {
              const double E = std::exp(a * x[0]);
              return -E * (a * a * (1 + x[0] * x[1] * x[1]) +
                           2 * a * x[1] * x[1] + 2 * x[0]);
            }};
  }

  namespace
  {
    /** Symmetric positive definite band matrix, lower band stored by row. */
    class BandMatrix
    {
    public:
      BandMatrix(const std::size_t size, const std::size_t half_bandwidth)
        : n(size)
        , bandwidth(half_bandwidth)
        , data(size * (half_bandwidth + 1), 0.0)
      {}

      /** Entry (i, j) with j <= i <= j + bandwidth. */
      double &
      operator()(const std::size_t i, const std::size_t j)
      {
        return data[i * (bandwidth + 1) + (bandwidth - (i - j))];
      }

      /** In-place Cholesky factorization, then solution of A x = b. */
      std::vector<double>
      solve(std::vector<double> b)
      {
        BandMatrix &L = *this;
        for (std::size_t j = 0; j < n; ++j)
          {
            const std::size_t first    = j > bandwidth ? j - bandwidth : 0;
            double            diagonal = L(j, j);
            for (std::size_t k = first; k < j; ++k)
              diagonal -= L(j, k) * L(j, k);
            if (!(diagonal > 0))
              throw std::runtime_error("BandMatrix: not positive definite");
            L(j, j) = std::sqrt(diagonal);
            for (std::size_t i = j + 1; i <= std::min(n - 1, j + bandwidth);
                 ++i)
              {
                const std::size_t first_i = i > bandwidth ? i - bandwidth : 0;
                double            sum     = L(i, j);
                for (std::size_t k = std::max(first, first_i); k < j; ++k)
                  sum -= L(i, k) * L(j, k);
                L(i, j) = sum / L(j, j);
              }
          }
        for (std::size_t i = 0; i < n; ++i) // L y = b
          {
            for (std::size_t k = (i > bandwidth ? i - bandwidth : 0); k < i;
                 ++k)
              b[i] -= L(i, k) * b[k];
            b[i] /= L(i, i);
          }
        for (std::size_t i = n; i-- > 0;) // L^T x = y
          {
            b[i] /= L(i, i);
            for (std::size_t k = (i > bandwidth ? i - bandwidth : 0); k < i;
                 ++k)
              b[k] -= L(i, k) * b[i];
          }
        return b;
      }

    private:
      std::size_t         n, bandwidth;
      std::vector<double> data;
    };

    struct PoissonErrors
    {
      double l2;
      double h1_seminorm;
    };

    /** Assembles, imposes the boundary dofs, solves and measures the errors. */
    PoissonErrors
    solve_poisson(const HermiteMesh &mesh, const ExactSolution &exact)
    {
      const std::size_t n_dofs    = 3 * mesh.node_points.size();
      std::size_t       bandwidth = 0;
      for (const auto &nodes : mesh.element_nodes)
        for (unsigned int a : nodes)
          for (unsigned int b : nodes)
            bandwidth =
              std::max<std::size_t>(bandwidth, 3 * (a > b ? a - b : b - a) + 2);

      BandMatrix          K(n_dofs, bandwidth);
      std::vector<double> rhs(n_dofs, 0.0);
      const auto          rule = glissade::paper_hermite_rule();
      for (std::size_t e = 0; e < mesh.elements.size(); ++e)
        {
          std::array<std::size_t, 12> global;
          for (unsigned int i = 0; i < 12; ++i)
            global[i] = 3 * mesh.element_nodes[e][i / 3] + i % 3;
          for (const auto &q : rule)
            {
              const auto   v  = mesh.elements[e].evaluate(q.xi, q.eta);
              const double dx = q.weight * v.jacobian_determinant;
              const double f  = exact.minus_laplacian(v.point);
              for (unsigned int i = 0; i < 12; ++i)
                {
                  rhs[global[i]] += f * v.shape_values[i] * dx;
                  for (unsigned int j = 0; j < 12; ++j)
                    if (global[i] >= global[j])
                      K(global[i], global[j]) +=
                        (v.shape_gradients[i][0] * v.shape_gradients[j][0] +
                         v.shape_gradients[i][1] * v.shape_gradients[j][1]) *
                        dx;
                }
            }
        }

      // Boundary dofs: the exact value and gradient at the node. Eliminated
      // symmetrically so that the matrix stays positive definite.
      std::vector<bool>   fixed(n_dofs, false);
      std::vector<double> boundary_value(n_dofs, 0.0);
      for (std::size_t a = 0; a < mesh.node_points.size(); ++a)
        if (mesh.node_on_boundary[a])
          {
            const Vector g            = exact.gradient(mesh.node_points[a]);
            boundary_value[3 * a]     = exact.value(mesh.node_points[a]);
            boundary_value[3 * a + 1] = g[0];
            boundary_value[3 * a + 2] = g[1];
            fixed[3 * a] = fixed[3 * a + 1] = fixed[3 * a + 2] = true;
          }
      for (std::size_t i = 0; i < n_dofs; ++i)
        for (std::size_t j = (i > bandwidth ? i - bandwidth : 0); j <= i; ++j)
          if (fixed[i] != fixed[j])
            {
              if (fixed[j])
                rhs[i] -= K(i, j) * boundary_value[j];
              else
                rhs[j] -= K(i, j) * boundary_value[i];
              K(i, j) = 0.0;
            }
      for (std::size_t i = 0; i < n_dofs; ++i)
        if (fixed[i])
          {
            for (std::size_t j = (i > bandwidth ? i - bandwidth : 0); j < i;
                 ++j)
              K(i, j) = 0.0;
            K(i, i) = 1.0;
            rhs[i]  = boundary_value[i];
          }
      const std::vector<double> solution = K.solve(rhs);

      PoissonErrors errors    = {0.0, 0.0};
      const auto    fine_rule = glissade::tensor_gauss_rule(6);
      for (std::size_t e = 0; e < mesh.elements.size(); ++e)
        for (const auto &q : fine_rule)
          {
            const auto v      = mesh.elements[e].evaluate(q.xi, q.eta);
            double     u      = 0;
            Vector     grad_u = {0, 0};
            for (unsigned int i = 0; i < 12; ++i)
              {
                const double U =
                  solution[3 * mesh.element_nodes[e][i / 3] + i % 3];
                u += U * v.shape_values[i];
                grad_u[0] += U * v.shape_gradients[i][0];
                grad_u[1] += U * v.shape_gradients[i][1];
              }
            const Vector g  = exact.gradient(v.point);
            const double dx = q.weight * v.jacobian_determinant;
            errors.l2 += std::pow(u - exact.value(v.point), 2) * dx;
            errors.h1_seminorm +=
              (std::pow(grad_u[0] - g[0], 2) + std::pow(grad_u[1] - g[1], 2)) *
              dx;
          }
      errors.l2          = std::sqrt(errors.l2);
      errors.h1_seminorm = std::sqrt(errors.h1_seminorm);
      return errors;
    }
  } // namespace


  void
  poisson_convergence_study(
    Checker                                        &check,
    const std::string                              &name,
    const std::function<HermiteMesh(unsigned int)> &make_mesh,
    const ExactSolution                            &exact,
    const unsigned int                              max_n,
    const std::array<double, 2>                    &l2_rate_window,
    const std::array<double, 2>                    &h1_rate_window)
  {
    std::printf("\n  Poisson, %s\n  %6s %8s %12s %7s %12s %7s\n",
                name.c_str(),
                "n x n",
                "dofs",
                "L2 error",
                "rate",
                "H1 error",
                "rate");
    PoissonErrors previous = {0, 0};
    double        l2_rate = 0, h1_rate = 0;
    for (unsigned int n = 2; n <= max_n; n *= 2)
      {
        const HermiteMesh   mesh   = make_mesh(n);
        const PoissonErrors errors = solve_poisson(mesh, exact);
        if (n > 2)
          {
            l2_rate = rate(previous.l2, errors.l2);
            h1_rate = rate(previous.h1_seminorm, errors.h1_seminorm);
            std::printf("  %6u %8zu %12.4e %7.3f %12.4e %7.3f\n",
                        n,
                        3 * mesh.node_points.size(),
                        errors.l2,
                        l2_rate,
                        errors.h1_seminorm,
                        h1_rate);
          }
        else
          std::printf("  %6u %8zu %12.4e %7s %12.4e %7s\n",
                      n,
                      3 * mesh.node_points.size(),
                      errors.l2,
                      "",
                      errors.h1_seminorm,
                      "");
        previous = errors;
      }
    check.between(name + ": L2 rate, last refinement",
                  l2_rate,
                  l2_rate_window[0],
                  l2_rate_window[1]);
    check.between(name + ": H1 rate, last refinement",
                  h1_rate,
                  h1_rate_window[0],
                  h1_rate_window[1]);
  }
} // namespace hermite_tests
