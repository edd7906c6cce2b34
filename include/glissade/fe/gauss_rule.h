#pragma once

#include <vector>

namespace glissade
{
  /**
   * Gauss-Legendre quadrature on the reference interval [-1, 1] and its
   * tensor product on the reference square [-1, 1]^2 -- the reference cell
   * of the paper's elements (not deal.II's unit cell [0, 1]^2: a deal.II
   * weight is a quarter of ours).
   *
   * The paper (Batailly et al. 2012, section 3.2) integrates the Hermite
   * element with the 3 x 3 rule (`paper_hermite_rule()`); an n-point rule is
   * exact for polynomials of degree 2n - 1 in each variable.
   */
  struct GaussLegendreRule
  {
    std::vector<double> points;
    std::vector<double> weights;
  };

  /** One point of a rule on the reference square. */
  struct QuadraturePoint2D
  {
    double xi;
    double eta;
    double weight;
  };

  /**
   * The n-point Gauss-Legendre rule on [-1, 1], n >= 1, points in increasing
   * order. The points are the roots of the Legendre polynomial P_n, found by
   * Newton's method from Chebyshev-like starting guesses; they are accurate
   * to round-off for any n a finite element code needs.
   */
  GaussLegendreRule
  gauss_legendre_rule(unsigned int n_points);

  /**
   * The n x n tensor-product Gauss rule on [-1, 1]^2, ordered with xi running
   * fastest. The weights sum to 4, the area of the reference square.
   */
  std::vector<QuadraturePoint2D>
  tensor_gauss_rule(unsigned int n_points_per_direction);

  /** The rule the paper uses for the Hermite element: 3 x 3 points. */
  inline std::vector<QuadraturePoint2D>
  paper_hermite_rule()
  {
    return tensor_gauss_rule(3);
  }
} // namespace glissade
