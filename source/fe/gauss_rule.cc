#include <glissade/fe/gauss_rule.h>

#include <cmath>
#include <stdexcept>

namespace glissade
{
  GaussLegendreRule
  gauss_legendre_rule(const unsigned int n_points)
  {
    if (n_points == 0)
      throw std::invalid_argument("gauss_legendre_rule: need at least 1 point");

    // Closed forms for the small rules, the paper's 3-point one included:
    // exact to the last bit, which Newton's method is not always.
    if (n_points == 1)
      return {{0.0}, {2.0}};
    if (n_points == 2)
      return {{-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}, {1.0, 1.0}};
    if (n_points == 3)
      return {{-std::sqrt(0.6), 0.0, std::sqrt(0.6)},
              {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};

    const double      pi = std::acos(-1.0);
    GaussLegendreRule rule;
    rule.points.resize(n_points);
    rule.weights.resize(n_points);

    // The roots are symmetric about 0, so compute the upper half and mirror.
    const unsigned int n_half = (n_points + 1) / 2;
    for (unsigned int i = 0; i < n_half; ++i)
      {
        // Starting guess close to the i-th largest root.
        double x          = std::cos(pi * (i + 0.75) / (n_points + 0.5));
        double derivative = 0;
        for (unsigned int iteration = 0; iteration < 100; ++iteration)
          {
            // Evaluate P_n(x) and P_{n-1}(x) by the three-term recurrence.
            double p_current = 1.0, p_previous = 0.0;
            for (unsigned int k = 1; k <= n_points; ++k)
              {
                const double p_next =
                  ((2.0 * k - 1.0) * x * p_current - (k - 1.0) * p_previous) /
                  k;
                p_previous = p_current;
                p_current  = p_next;
              }
            derivative =
              n_points * (x * p_current - p_previous) / (x * x - 1.0);
            const double step = p_current / derivative;
            x -= step;
            if (std::abs(step) < 1e-16)
              break;
          }
        // Recompute the derivative at the converged root for the weight.
        double p_current = 1.0, p_previous = 0.0;
        for (unsigned int k = 1; k <= n_points; ++k)
          {
            const double p_next =
              ((2.0 * k - 1.0) * x * p_current - (k - 1.0) * p_previous) / k;
            p_previous = p_current;
            p_current  = p_next;
          }
        derivative = n_points * (x * p_current - p_previous) / (x * x - 1.0);
        const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);

        rule.points[n_points - 1 - i]  = x;
        rule.points[i]                 = -x;
        rule.weights[n_points - 1 - i] = weight;
        rule.weights[i]                = weight;
      }
    // The middle point of an odd rule is exactly 0.
    if (n_points % 2 == 1)
      rule.points[n_points / 2] = 0.0;
    return rule;
  }

  std::vector<QuadraturePoint2D>
  tensor_gauss_rule(const unsigned int n_points_per_direction)
  {
    const GaussLegendreRule rule_1d =
      gauss_legendre_rule(n_points_per_direction);
    std::vector<QuadraturePoint2D> rule;
    rule.reserve(n_points_per_direction * n_points_per_direction);
    for (unsigned int j = 0; j < n_points_per_direction; ++j)
      for (unsigned int i = 0; i < n_points_per_direction; ++i)
        rule.push_back({rule_1d.points[i],
                        rule_1d.points[j],
                        rule_1d.weights[i] * rule_1d.weights[j]});
    return rule;
  }
} // namespace glissade
