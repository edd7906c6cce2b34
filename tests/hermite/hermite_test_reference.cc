// Tests of the reference shape functions of glissade::HermiteQuadrilateral:
// Kronecker conditions, membership of the 12-term space of eq. 22 (by an
// independent construction and a least-squares fit), agreement with the
// paper's printed eq. 23-25 (and detection of its two misprints), finite
// differences of the gradients and Hessians, partition of unity.

#include "hermite_test_reference.h"

#include <glissade/fe/hermite_quadrilateral.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hermite_test_tools.h"

namespace hermite_tests
{
  using glissade::HermiteQuadrilateral;
  using Vector = HermiteQuadrilateral::Vector;

  namespace
  {
    // The twelve monomials of eq. 22 as exponent pairs (xi^p eta^q).
    constexpr int monomial_exponents[12][2] = {{0, 0},
                                               {1, 0},
                                               {0, 1},
                                               {2, 0},
                                               {1, 1},
                                               {0, 2},
                                               {3, 0},
                                               {2, 1},
                                               {1, 2},
                                               {0, 3},
                                               {3, 1},
                                               {1, 3}};

    double
    power(const double x, const int p)
    {
      return p <= 0 ? 1.0 : std::pow(x, p);
    }

    // Monomial m and its two derivatives at (xi, eta).
    std::array<double, 3>
    monomial(const unsigned int m, const double xi, const double eta)
    {
      const int p = monomial_exponents[m][0], q = monomial_exponents[m][1];
      return {power(xi, p) * power(eta, q),
              p * power(xi, p - 1) * power(eta, q),
              q * power(xi, p) * power(eta, q - 1)};
    }
  } // namespace

  // ------------------------------------------------------------------------
  void
  test_reference_functions(Checker &check, Random &random)
  {
    std::printf("\nReference shape functions\n");

    // Kronecker properties at the four nodes.
    double kronecker_error = 0;
    for (unsigned int a = 0; a < 4; ++a)
      {
        const Vector x  = HermiteQuadrilateral::node_reference_point(a);
        const auto   N  = HermiteQuadrilateral::reference_values(x[0], x[1]);
        const auto   dN = HermiteQuadrilateral::reference_gradients(x[0], x[1]);
        for (unsigned int i = 0; i < 12; ++i)
          {
            const double expected[3] = {i == 3 * a ? 1.0 : 0.0,
                                        i == 3 * a + 1 ? 1.0 : 0.0,
                                        i == 3 * a + 2 ? 1.0 : 0.0};
            kronecker_error = std::max({kronecker_error,
                                        std::abs(N[i] - expected[0]),
                                        std::abs(dN[i][0] - expected[1]),
                                        std::abs(dN[i][1] - expected[2])});
          }
      }
    check.at_most("Kronecker: max |dof_j(N_i) - delta_ij| at the nodes",
                  kronecker_error,
                  1e-15);

    // Independent construction: the 12 x 12 matrix D[j][m] = dof_j(monomial m)
    // inverted column by column gives the basis that the Kronecker conditions
    // define on the space of eq. 22.
    std::vector<std::vector<double>> D(12, std::vector<double>(12));
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int m = 0; m < 12; ++m)
        {
          const Vector x = HermiteQuadrilateral::node_reference_point(a);
          const auto   p = monomial(m, x[0], x[1]);
          for (unsigned int k = 0; k < 3; ++k)
            D[3 * a + k][m] = p[k];
        }
    std::vector<std::vector<double>> coefficients(12); // per shape function
    for (unsigned int i = 0; i < 12; ++i)
      {
        std::vector<double> unit(12, 0.0);
        unit[i]         = 1.0;
        coefficients[i] = solve_dense(D, unit);
      }

    // Least-squares fit of each implemented function on 40 random points by
    // the 12 monomials: a zero residual shows it lies in the space, equal
    // coefficients that it is the Kronecker basis.
    const unsigned int                 n_samples = 40;
    std::vector<std::array<double, 2>> samples(n_samples);
    for (auto &x : samples)
      x = {random.uniform(), random.uniform()};
    std::vector<std::vector<double>> normal_matrix(12,
                                                   std::vector<double>(12,
                                                                       0.0));
    for (const auto &x : samples)
      for (unsigned int m = 0; m < 12; ++m)
        for (unsigned int l = 0; l < 12; ++l)
          normal_matrix[m][l] +=
            monomial(m, x[0], x[1])[0] * monomial(l, x[0], x[1])[0];
    double fit_residual = 0, fit_coefficient_error = 0, derivative_error = 0;
    for (unsigned int i = 0; i < 12; ++i)
      {
        std::vector<double> right_hand_side(12, 0.0);
        for (const auto &x : samples)
          {
            const double Ni =
              HermiteQuadrilateral::reference_values(x[0], x[1])[i];
            for (unsigned int m = 0; m < 12; ++m)
              right_hand_side[m] += monomial(m, x[0], x[1])[0] * Ni;
          }
        const std::vector<double> fit =
          solve_dense(normal_matrix, right_hand_side);
        for (unsigned int m = 0; m < 12; ++m)
          fit_coefficient_error =
            std::max(fit_coefficient_error,
                     std::abs(fit[m] - coefficients[i][m]));
        for (const auto &x : samples)
          {
            double fitted = 0, kronecker[3] = {0, 0, 0};
            for (unsigned int m = 0; m < 12; ++m)
              {
                const auto p = monomial(m, x[0], x[1]);
                fitted += fit[m] * p[0];
                for (unsigned int k = 0; k < 3; ++k)
                  kronecker[k] += coefficients[i][m] * p[k];
              }
            const double Ni =
              HermiteQuadrilateral::reference_values(x[0], x[1])[i];
            const Vector dNi =
              HermiteQuadrilateral::reference_gradients(x[0], x[1])[i];
            fit_residual     = std::max(fit_residual, std::abs(fitted - Ni));
            derivative_error = std::max({derivative_error,
                                         std::abs(kronecker[0] - Ni),
                                         std::abs(kronecker[1] - dNi[0]),
                                         std::abs(kronecker[2] - dNi[1])});
          }
      }
    check.at_most("span: max residual of the monomial fit at 40 points",
                  fit_residual,
                  1e-13);
    check.at_most("span: max |fitted - Kronecker-derived coefficient|",
                  fit_coefficient_error,
                  1e-12);
    check.at_most(
      "Kronecker-derived basis vs implemented (value, d/dxi, d/deta)",
      derivative_error,
      1e-14);

    // The paper's printed formulas (0-based index i = paper index - 1).
    // clang-format off
    const auto paper = [](const double x, const double e) {
      const double r = 0.125;
      const std::array<double, 12> N = {
        r*(1-x)*(1-e)*(2-x*x-e*e-x-e), r*(1-x)*(1-e)*(1-x*x), r*(1-x)*(1-e)*(1-e*e),
        r*(1+x)*(1-e)*(2-x*x-e*e+x-e), -r*(1+x)*(1-e)*(1-x*x), r*(1+x)*(1-e)*(1-e*e),
        r*(1+x)*(1+e)*(2-x*x-e*e+x+e), -r*(1+x)*(1+e)*(1-x*x), -r*(1+x)*(1+e)*(1-e*e),
        r*(1-x)*(1+e)*(2-x*x-e*e-x+e), r*(1-x)*(1+e)*(1-x*x), -r*(1-x)*(1+e)*(1-e*e)};
      const std::array<double, 12> N_xi = { // eq. 24 as printed
        r*(1-e)*(-3+3*x*x+e*e+e), -r*(1-x)*(1-e)*(1+3*x), r*(-1+e)*(1-e*e),
        r*(1-e)*(3-3*x*x-e*e-e), -r*(1+x)*(1-e)*(1-3*x), r*(1-e)*(1-e*e),
        r*(1+e)*(3-3*x*x-e*e+e), -r*(1-x)*(1+e)*(1-3*x), -r*(1+e)*(1-e*e),
        r*(1+e)*(-3+3*x*x+e*e-e), r*(1-x)*(1+e)*(1+3*x), r*(1+e)*(1-e*e)};
      const std::array<double, 12> N_eta = { // eq. 25 as printed
        r*(1-x)*(-3+x*x+3*e*e+x), r*(-1+x)*(1-x*x), -r*(1-x)*(1-e)*(1+3*e),
        r*(1+x)*(-3+x*x+3*e*e-x), r*(1+x)*(1-x*x), -r*(1+x)*(1-e)*(1+3*e),
        r*(1+x)*(3-x*x-3*e*e+x), r*(-1-x)*(1-x*x), -r*(1+x)*(1+e)*(1-3*e),
        r*(1-x)*(3-x*x-3*e*e-x), r*(1-x)*(1-x*x), -r*(1-x)*(1+e)*(1-3*e)};
      return std::array<std::array<double, 12>, 3>{N, N_xi, N_eta};
    };
    // clang-format on
    std::array<std::array<double, 12>, 3> paper_error = {};
    for (const auto &x : samples)
      {
        const auto P  = paper(x[0], x[1]);
        const auto N  = HermiteQuadrilateral::reference_values(x[0], x[1]);
        const auto dN = HermiteQuadrilateral::reference_gradients(x[0], x[1]);
        for (unsigned int i = 0; i < 12; ++i)
          {
            paper_error[0][i] =
              std::max(paper_error[0][i], std::abs(P[0][i] - N[i]));
            paper_error[1][i] =
              std::max(paper_error[1][i], std::abs(P[1][i] - dN[i][0]));
            paper_error[2][i] =
              std::max(paper_error[2][i], std::abs(P[2][i] - dN[i][1]));
          }
      }
    double eq23 = 0, eq24_others = 0, eq25 = 0;
    for (unsigned int i = 0; i < 12; ++i)
      {
        eq23 = std::max(eq23, paper_error[0][i]);
        eq25 = std::max(eq25, paper_error[2][i]);
        if (i != 7 && i != 10)
          eq24_others = std::max(eq24_others, paper_error[1][i]);
      }
    check.at_most("paper eq. 23 (N_1..N_12) as printed vs implemented",
                  eq23,
                  1e-15);
    check.at_most("paper eq. 25 (d/deta) as printed vs implemented",
                  eq25,
                  1e-15);
    check.at_most("paper eq. 24 (d/dxi) as printed, all but N_8 and N_11",
                  eq24_others,
                  1e-15);
    // The two misprints must show up, or the test is not testing anything.
    check.between("paper eq. 24 N_8,xi misprint ((1-xi) for (1+xi)), max dev.",
                  paper_error[1][7],
                  0.1,
                  10);
    check.between("paper eq. 24 N_11,xi misprint (sign), max deviation",
                  paper_error[1][10],
                  0.1,
                  10);

    // Finite-difference check of the gradients and the Hessians.
    double       gradient_fd = 0, hessian_fd = 0;
    const double h = 1e-5;
    for (unsigned int k = 0; k < 10; ++k)
      {
        const double x = samples[k][0], e = samples[k][1];
        const auto   Np  = HermiteQuadrilateral::reference_values(x + h, e);
        const auto   Nm  = HermiteQuadrilateral::reference_values(x - h, e);
        const auto   Nq  = HermiteQuadrilateral::reference_values(x, e + h);
        const auto   Nr  = HermiteQuadrilateral::reference_values(x, e - h);
        const auto   dN  = HermiteQuadrilateral::reference_gradients(x, e);
        const auto   dNp = HermiteQuadrilateral::reference_gradients(x + h, e);
        const auto   dNm = HermiteQuadrilateral::reference_gradients(x - h, e);
        const auto   dNq = HermiteQuadrilateral::reference_gradients(x, e + h);
        const auto   dNr = HermiteQuadrilateral::reference_gradients(x, e - h);
        const auto   H   = HermiteQuadrilateral::reference_hessians(x, e);
        for (unsigned int i = 0; i < 12; ++i)
          {
            gradient_fd =
              std::max({gradient_fd,
                        std::abs((Np[i] - Nm[i]) / (2 * h) - dN[i][0]),
                        std::abs((Nq[i] - Nr[i]) / (2 * h) - dN[i][1])});
            hessian_fd =
              std::max({hessian_fd,
                        std::abs((dNp[i][0] - dNm[i][0]) / (2 * h) - H[i][0]),
                        std::abs((dNq[i][0] - dNr[i][0]) / (2 * h) - H[i][1]),
                        std::abs((dNp[i][1] - dNm[i][1]) / (2 * h) - H[i][1]),
                        std::abs((dNq[i][1] - dNr[i][1]) / (2 * h) - H[i][2])});
          }
      }
    check.at_most("gradients vs central differences (h = 1e-5)",
                  gradient_fd,
                  1e-9);
    check.at_most("Hessians vs central differences of the gradients",
                  hessian_fd,
                  1e-9);

    double unity = 0;
    for (const auto &x : samples)
      {
        const auto N = HermiteQuadrilateral::reference_values(x[0], x[1]);
        unity = std::max(unity, std::abs(N[0] + N[3] + N[6] + N[9] - 1.0));
      }
    check.at_most("partition of unity: max |sum_a N_a^value - 1|",
                  unity,
                  1e-15);
  }
} // namespace hermite_tests
