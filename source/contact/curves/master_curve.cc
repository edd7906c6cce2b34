#include <glissade/contact/curves/master_curve.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace glissade
{
  namespace
  {
    using Point = MasterCurve::Point;

    inline Point
    difference(const Point &a, const Point &b)
    {
      return {{a[0] - b[0], a[1] - b[1]}};
    }

    inline double
    norm(const Point &a)
    {
      return std::hypot(a[0], a[1]);
    }

    // n = e3 x t (paper eq. 27).
    inline Point
    rotate_left(const Point &t)
    {
      return {{-t[1], t[0]}};
    }
  } // namespace



  unsigned int
  MasterCurve::n_nodes() const
  {
    return node_positions.size();
  }



  const std::vector<MasterCurve::Point> &
  MasterCurve::nodes() const
  {
    return node_positions;
  }



  std::array<unsigned int, 2>
  MasterCurve::segment_nodes(const unsigned int segment) const
  {
    assert(segment < n_segments());
    const unsigned int next = segment + 1;
    return {{segment, next == n_nodes() ? 0u : next}};
  }



  double
  MasterCurve::length_scale() const
  {
    return scale;
  }



  void
  MasterCurve::evaluate(const unsigned int segment,
                        const double       s,
                        Point             &value_at_s,
                        Point             &first_derivative,
                        Point             &second_derivative_at_s) const
  {
    value_at_s             = value(segment, s);
    first_derivative       = derivative(segment, s);
    second_derivative_at_s = second_derivative(segment, s);
  }



  void
  MasterCurve::weights(const unsigned int segment,
                       const double       s,
                       NodeWeights       &node_weights) const
  {
    NodeWeightsAndDerivatives both;
    weights_and_derivatives(segment, s, both);
    double largest = 0.;
    for (const auto &w : both)
      largest = std::max(largest, std::abs(w.value));
    node_weights.clear();
    for (const auto &w : both)
      if (std::abs(w.value) > 1e-14 * largest)
        node_weights.emplace_back(w.node, w.value);
  }



  void
  MasterCurve::keep_significant(NodeWeightsAndDerivatives &weights)
  {
    double largest_value = 0., largest_derivative = 0.;
    for (const auto &w : weights)
      {
        largest_value = std::max(largest_value, std::abs(w.value));
        largest_derivative =
          std::max(largest_derivative, std::abs(w.derivative));
      }
    weights.erase(std::remove_if(weights.begin(),
                                 weights.end(),
                                 [&](const WeightAndDerivative &w) {
                                   return !(std::abs(w.value) >
                                              1e-14 * largest_value ||
                                            std::abs(w.derivative) >
                                              1e-14 * largest_derivative);
                                 }),
                  weights.end());
    std::sort(weights.begin(),
              weights.end(),
              [](const WeightAndDerivative &a, const WeightAndDerivative &b) {
                return a.node < b.node;
              });
  }



  std::array<std::pair<unsigned int, double>, 2>
  MasterCurve::underlying_segment_weights(const unsigned int segment,
                                          const double       s) const
  {
    const auto ends = segment_nodes(segment);
    return {{{ends[0], 1. - s}, {ends[1], s}}};
  }



  MasterCurve::Point
  MasterCurve::unit_tangent(const unsigned int segment, const double s) const
  {
    const Point  d      = derivative(segment, s);
    const double length = norm(d);
    if (length > 1e-14 * scale)
      return {{d[0] / length, d[1] / length}};

    // Degenerate parametrisation: look for the nearest nodes, backwards from
    // the start and forwards from the end of the segment, that differ from
    // the segment's start node, and take the direction between them.
    const unsigned int n     = n_nodes();
    const auto         ends  = segment_nodes(segment);
    const Point        here  = node_positions[ends[0]];
    const double       small = 1e-14 * scale;

    Point        before = here, after = here;
    unsigned int i = ends[0];
    for (unsigned int step = 0; step < n; ++step)
      {
        if (norm(difference(node_positions[i], here)) > small)
          {
            before = node_positions[i];
            break;
          }
        if (i == 0 && !is_closed())
          break;
        i = (i == 0 ? n - 1 : i - 1);
      }
    i = ends[1];
    for (unsigned int step = 0; step < n; ++step)
      {
        if (norm(difference(node_positions[i], here)) > small)
          {
            after = node_positions[i];
            break;
          }
        if (i == n - 1 && !is_closed())
          break;
        i = (i == n - 1 ? 0 : i + 1);
      }

    const Point  chord        = difference(after, before);
    const double chord_length = norm(chord);
    if (chord_length > small)
      return {{chord[0] / chord_length, chord[1] / chord_length}};
    return {{1., 0.}};
  }



  MasterCurve::Point
  MasterCurve::unit_normal(const unsigned int segment, const double s) const
  {
    return rotate_left(unit_tangent(segment, s));
  }



  void
  MasterCurve::set_nearest_node_search(const NearestNodeSearch &search)
  {
    nearest_node_search = search;
  }



  unsigned int
  MasterCurve::nearest_node(const Point &x) const
  {
    if (nearest_node_search)
      return nearest_node_search(x);

    unsigned int best          = 0;
    double       best_distance = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < node_positions.size(); ++i)
      {
        const double dx = node_positions[i][0] - x[0];
        const double dy = node_positions[i][1] - x[1];
        const double d2 = dx * dx + dy * dy;
        if (d2 < best_distance)
          {
            best_distance = d2;
            best          = i;
          }
      }
    return best;
  }



  void
  MasterCurve::store_nodes(const std::vector<Point> &nodes,
                           const unsigned int        minimum_number)
  {
    if (nodes.size() < minimum_number)
      throw std::invalid_argument("MasterCurve: this curve needs at least " +
                                  std::to_string(minimum_number) +
                                  " nodes, got " +
                                  std::to_string(nodes.size()));

    node_positions = nodes;
    segment_boxes.clear();

    Point low = nodes[0], high = nodes[0];
    for (const Point &p : nodes)
      for (unsigned int d = 0; d < 2; ++d)
        {
          if (!std::isfinite(p[d]))
            throw std::invalid_argument("MasterCurve: non-finite node");
          low[d]  = std::min(low[d], p[d]);
          high[d] = std::max(high[d], p[d]);
        }
    scale = norm(difference(high, low));
    if (!(scale > 0.))
      scale = 1.;
  }



  void
  MasterCurve::cache_bounding_boxes()
  {
    segment_boxes.resize(n_segments());
    for (unsigned int segment = 0; segment < n_segments(); ++segment)
      bounding_box(segment,
                   segment_boxes[segment][0],
                   segment_boxes[segment][1]);
  }



  bool
  MasterCurve::previous_segment(const unsigned int segment,
                                unsigned int      &previous) const
  {
    if (segment > 0)
      {
        previous = segment - 1;
        return true;
      }
    if (is_closed())
      {
        previous = n_segments() - 1;
        return true;
      }
    return false;
  }



  bool
  MasterCurve::next_segment(const unsigned int segment,
                            unsigned int      &next) const
  {
    if (segment + 1 < n_segments())
      {
        next = segment + 1;
        return true;
      }
    if (is_closed())
      {
        next = 0;
        return true;
      }
    return false;
  }



  void
  MasterCurve::set_global_search(const bool global)
  {
    global_search = global;
  }
} // namespace glissade
