// A standalone scalar Poisson solve with the Hermite element, to measure its
// convergence rates: -lap u = f, u = u_exact on the boundary, where all three
// dofs of every boundary node (value, du/dx, du/dy) are set from u_exact.
// Assembly with the paper's 3 x 3 Gauss rule, errors with a 6 x 6 rule,
// banded Cholesky on the structured node numbering.
//
// The study itself is in hermite_test_poisson.cc; hermite_tests.cc runs it on
// its mesh families.
#pragma once

#include <glissade/fe/hermite_quadrilateral.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "hermite_test_tools.h"

namespace hermite_tests
{
  using glissade::HermiteQuadrilateral;
  using Vector = HermiteQuadrilateral::Vector;

  /** Elements with their global node numbers; 3 dofs per global node. */
  struct HermiteMesh
  {
    std::vector<Vector>                      node_points;
    std::vector<bool>                        node_on_boundary;
    std::vector<std::array<unsigned int, 4>> element_nodes; // paper order
    std::vector<HermiteQuadrilateral>        elements;
  };

  /**
   * n x n structured mesh of a parameter square [0,1]^2 mapped by vertex_map
   * (straight-sided elements through the mapped vertices). Node (i, j) is
   * number j (n + 1) + i, so the dof bandwidth is about 3 (n + 2).
   */
  HermiteMesh
  straight_sided_mesh(
    const unsigned int                                       n,
    const std::function<Vector(unsigned int, unsigned int)> &vertex);

  /**
   * n x n mesh of the quarter annulus 1 <= r <= 2, 0 <= theta <= pi/2 with
   * curved elements: tangents from the exact polar parametrization
   * (xi radial, eta circumferential).
   */
  HermiteMesh
  quarter_annulus_mesh(const unsigned int n);

  /** u, grad u and -lap u of a manufactured solution. */
  struct ExactSolution
  {
    std::function<double(const Vector &)> value;
    std::function<Vector(const Vector &)> gradient;
    std::function<double(const Vector &)> minus_laplacian;
  };

  /** u = sin(pi x) sin(pi y). */
  ExactSolution
  sine_solution();

  /** u = exp(a x) (1 + x y^2), a = 0.7: no symmetry, not harmonic. */
  ExactSolution
  exp_polynomial_solution();

  /**
   * Runs one mesh family on n = 2, 4, ..., max_n, prints errors and rates and
   * checks the rates of the last refinement against the given windows.
   */
  void
  poisson_convergence_study(
    Checker                                        &check,
    const std::string                              &name,
    const std::function<HermiteMesh(unsigned int)> &make_mesh,
    const ExactSolution                            &exact,
    const unsigned int                              max_n,
    const std::array<double, 2>                    &l2_rate_window,
    const std::array<double, 2>                    &h1_rate_window);
} // namespace hermite_tests
