#include <glissade/contact/curves/lagrange_edge_curve.h>

#include <algorithm>
#include <stdexcept>

namespace glissade
{
  LagrangeEdgeCurve::LagrangeEdgeCurve(const unsigned int degree,
                                       const bool         closed)
    : degree(degree)
    , closed(closed)
  {
    if (degree < 1 || degree > 3)
      throw std::invalid_argument("LagrangeEdgeCurve: degree 1, 2 or 3");
  }



  void
  LagrangeEdgeCurve::update(const std::vector<Point> &vertices)
  {
    update(vertices, edge_nodes);
  }



  void
  LagrangeEdgeCurve::update(const std::vector<Point> &vertices,
                            const std::vector<Point> &new_edge_nodes)
  {
    store_nodes(vertices, closed ? 3 : 2);
    if (new_edge_nodes.size() != n_segments() * (degree - 1))
      throw std::invalid_argument(
        "LagrangeEdgeCurve::update: need degree - 1 edge nodes per segment");
    edge_nodes = new_edge_nodes;
    cache_bounding_boxes();
  }



  unsigned int
  LagrangeEdgeCurve::n_segments() const
  {
    const unsigned int n = n_nodes();
    if (n == 0)
      return 0;
    return closed ? n : n - 1;
  }



  bool
  LagrangeEdgeCurve::is_closed() const
  {
    return closed;
  }



  std::vector<MasterCurve::Point>
  LagrangeEdgeCurve::segment_points(const unsigned int segment) const
  {
    const auto         ends = segment_nodes(segment);
    std::vector<Point> points;
    points.push_back(nodes()[ends[0]]);
    for (unsigned int j = 0; j + 1 < degree; ++j)
      points.push_back(edge_nodes[segment * (degree - 1) + j]);
    points.push_back(nodes()[ends[1]]);
    return points;
  }



  void
  LagrangeEdgeCurve::basis(const double         s,
                           std::vector<double> &value,
                           std::vector<double> &first,
                           std::vector<double> &second) const
  {
    // l_j(s) = prod_{m != j} (s - s_m)/(s_j - s_m) on s_m = m/p, with its
    // derivatives by the product rule (p <= 3, so this is cheap and exact).
    const unsigned int n = degree + 1;
    value.assign(n, 0.);
    first.assign(n, 0.);
    second.assign(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double sj          = double(j) / degree;
        double       denominator = 1.;
        for (unsigned int m = 0; m < n; ++m)
          if (m != j)
            denominator *= sj - double(m) / degree;
        std::vector<double> factors;
        for (unsigned int m = 0; m < n; ++m)
          if (m != j)
            factors.push_back(s - double(m) / degree);
        double v = 1., d1 = 0., d2 = 0.;
        for (unsigned int a = 0; a < factors.size(); ++a)
          {
            v *= factors[a];
            double p1 = 1.;
            for (unsigned int b = 0; b < factors.size(); ++b)
              if (b != a)
                p1 *= factors[b];
            d1 += p1;
            for (unsigned int b = 0; b < factors.size(); ++b)
              if (b != a)
                {
                  double p2 = 1.;
                  for (unsigned int c = 0; c < factors.size(); ++c)
                    if (c != a && c != b)
                      p2 *= factors[c];
                  d2 += p2;
                }
          }
        value[j]  = v / denominator;
        first[j]  = d1 / denominator;
        second[j] = d2 / denominator;
      }
  }



  MasterCurve::Point
  LagrangeEdgeCurve::combine(const unsigned int segment,
                             const double       s,
                             const unsigned int order) const
  {
    std::vector<double> v, d1, d2;
    basis(s, v, d1, d2);
    const std::vector<double> &w      = order == 0 ? v : (order == 1 ? d1 : d2);
    const auto                 points = segment_points(segment);
    Point                      result = {{0., 0.}};
    for (unsigned int j = 0; j < points.size(); ++j)
      for (unsigned int d = 0; d < 2; ++d)
        result[d] += w[j] * points[j][d];
    return result;
  }



  MasterCurve::Point
  LagrangeEdgeCurve::value(const unsigned int segment, const double s) const
  {
    return combine(segment, s, 0);
  }



  MasterCurve::Point
  LagrangeEdgeCurve::derivative(const unsigned int segment,
                                const double       s) const
  {
    return combine(segment, s, 1);
  }



  MasterCurve::Point
  LagrangeEdgeCurve::second_derivative(const unsigned int segment,
                                       const double       s) const
  {
    return combine(segment, s, 2);
  }



  void
  LagrangeEdgeCurve::bounding_box(const unsigned int segment,
                                  Point             &low,
                                  Point             &high) const
  {
    // A Lagrange curve can leave the box of its nodes, its Bezier control
    // polygon cannot: convert to Bernstein form (p <= 3) and box that.
    const auto         P       = segment_points(segment);
    std::vector<Point> control = P;
    if (degree == 2)
      for (unsigned int d = 0; d < 2; ++d)
        control[1][d] = 2. * P[1][d] - 0.5 * (P[0][d] + P[2][d]);
    else if (degree == 3)
      for (unsigned int d = 0; d < 2; ++d)
        {
          control[1][d] =
            (-5. * P[0][d] + 18. * P[1][d] - 9. * P[2][d] + 2. * P[3][d]) / 6.;
          control[2][d] =
            (2. * P[0][d] - 9. * P[1][d] + 18. * P[2][d] - 5. * P[3][d]) / 6.;
        }
    low = high = control[0];
    for (const auto &c : control)
      for (unsigned int d = 0; d < 2; ++d)
        {
          low[d]  = std::min(low[d], c[d]);
          high[d] = std::max(high[d], c[d]);
        }
  }



  void
  LagrangeEdgeCurve::weights_and_derivatives(
    const unsigned int         segment,
    const double               s,
    NodeWeightsAndDerivatives &weights) const
  {
    std::vector<double> v, d1, d2;
    basis(s, v, d1, d2);
    const auto ends = segment_nodes(segment);
    weights.clear();
    weights.push_back({ends[0], v[0], d1[0]});
    for (unsigned int j = 0; j + 1 < degree; ++j)
      weights.push_back(
        {n_nodes() + segment * (degree - 1) + j, v[j + 1], d1[j + 1]});
    weights.push_back({ends[1], v[degree], d1[degree]});
    keep_significant(weights);
  }
} // namespace glissade
