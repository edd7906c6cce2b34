// The closest-point projection of MasterCurve (see the documentation of
// MasterCurve::project()): kept apart from master_curve.cc because it is the
// part that needs the most care.

#include <glissade/contact/curves/master_curve.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

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
    dot(const Point &a, const Point &b)
    {
      return a[0] * b[0] + a[1] * b[1];
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

    // The inverse of rotate_left: t such that n = e3 x t.
    inline Point
    rotate_right(const Point &n)
    {
      return {{n[1], -n[0]}};
    }


    // One local minimiser of |c(s) - x| on one segment: an end, or a root of
    // f(s) = (c - x) . c'. Stationary means f = 0 (to round-off): a true
    // orthogonal projection, which wins ties against a clamped end.
    struct Candidate
    {
      unsigned int segment    = 0;
      double       s          = 0.;
      double       distance   = std::numeric_limits<double>::infinity();
      unsigned int iterations = 0;
      bool         stationary = false;
    };


    // Safeguarded Newton iteration for f(s) = (c(s) - x) . c'(s) = 0 on the
    // bracket [lo, hi] with f(lo) <= 0 <= f(hi): the sign change from - to +
    // makes the root a local minimum of the distance. This is the classical
    // 'rtsafe' scheme: take the Newton step when it stays inside the bracket
    // and shrinks f at least as fast as bisection would, bisect otherwise;
    // the bracket shrinks at every iteration, so the iteration can neither
    // diverge nor cycle, and the iteration count is capped anyway.
    Candidate
    bracketed_newton(const MasterCurve &curve,
                     const unsigned int segment,
                     const Point       &x,
                     double             lo,
                     const double       f_lo,
                     double             hi,
                     const double       f_hi)
    {
      Candidate result;
      result.segment    = segment;
      result.stationary = true;

      const auto distance_at = [&](const double s) {
        return norm(difference(curve.value(segment, s), x));
      };

      if (f_lo == 0.)
        {
          result.s        = lo;
          result.distance = distance_at(lo);
          return result;
        }
      if (f_hi == 0.)
        {
          result.s        = hi;
          result.distance = distance_at(hi);
          return result;
        }

      const double scale = curve.length_scale();

      // Start from the secant (regula falsi) point: exact for a straight
      // segment, and a good guess on a gently curved one.
      double s = lo - f_lo * (hi - lo) / (f_hi - f_lo);
      if (!(s > lo && s < hi))
        s = 0.5 * (lo + hi);

      double       step_before_last = hi - lo;
      double       last_step        = step_before_last;
      Point        c, d1, d2;
      unsigned int iteration = 0;
      while (iteration < MasterCurve::max_newton_iterations)
        {
          ++iteration;
          curve.evaluate(segment, s, c, d1, d2);
          const Point  r  = difference(c, x);
          const double f  = dot(r, d1);
          const double df = dot(d1, d1) + dot(r, d2);

          if (std::abs(f) <= 1e-15 * norm(d1) * (norm(r) + scale))
            break;

          if (f < 0.)
            lo = s;
          else
            hi = s;

          step_before_last = last_step;
          double s_new     = 0.5 * (lo + hi);
          if (df > 0.)
            {
              const double newton = s - f / df;
              // Newton only if it stays strictly inside the bracket and the
              // step is less than half the step before last (otherwise
              // bisection makes more progress).
              if (newton > lo && newton < hi &&
                  std::abs(2. * f) <= std::abs(step_before_last * df))
                s_new = newton;
            }
          last_step = s_new - s;
          s         = s_new;

          if (std::abs(last_step) <= 1e-14 || hi - lo <= 1e-14)
            break;
        }

      // A root within round-off of an end is that end: it is then the same
      // point as the neighbouring segment's end, and ties resolve cleanly.
      if (s < 1e-13)
        s = 0.;
      else if (s > 1. - 1e-13)
        s = 1.;
      result.s          = s;
      result.distance   = distance_at(s);
      result.iterations = iteration;
      return result;
    }


    // The candidates for the minimiser of |c(s) - x| over s in [0,1] on one
    // segment: the two ends and the bracketed interior minima, appended to
    // candidates.
    void
    minimize_on_segment(const MasterCurve      &curve,
                        const unsigned int      segment,
                        const Point            &x,
                        std::vector<Candidate> &candidates)
    {
      constexpr unsigned int              n_intervals = 4;
      std::array<double, n_intervals + 1> f, distance;
      std::array<bool, n_intervals + 1>   orthogonal;
      Point                               c, d1, d2;
      for (unsigned int k = 0; k <= n_intervals; ++k)
        {
          curve.evaluate(segment, double(k) / n_intervals, c, d1, d2);
          const Point r = difference(c, x);
          f[k]          = dot(r, d1);
          distance[k]   = norm(r);
          orthogonal[k] = std::abs(f[k]) <=
                          norm(d1) * (1e-10 * distance[k] +
                                      1e-14 * (curve.length_scale() + norm(c)));
        }

      for (const unsigned int k : {0u, n_intervals})
        {
          Candidate end;
          end.segment    = segment;
          end.s          = (k == 0 ? 0. : 1.);
          end.distance   = distance[k];
          end.stationary = orthogonal[k];
          candidates.push_back(end);
        }

      for (unsigned int k = 0; k < n_intervals; ++k)
        if ((f[k] < 0. && f[k + 1] >= 0.) || (f[k] <= 0. && f[k + 1] > 0.))
          candidates.push_back(bracketed_newton(curve,
                                                segment,
                                                x,
                                                double(k) / n_intervals,
                                                f[k],
                                                double(k + 1) / n_intervals,
                                                f[k + 1]));
    }

    // The tangent at a convex corner: that of the average of the two
    // adjacent normals (of the outgoing normal if they cancel).
    Point
    corner_tangent(const Point &incoming_tangent, const Point &outgoing_tangent)
    {
      const Point  n_in   = rotate_left(incoming_tangent);
      const Point  n_out  = rotate_left(outgoing_tangent);
      Point        n      = {{n_in[0] + n_out[0], n_in[1] + n_out[1]}};
      const double length = norm(n);
      if (length > 1e-12)
        n = {{n[0] / length, n[1] / length}};
      else
        n = n_out;
      return rotate_right(n);
    }
  } // namespace



  MasterCurve::NodeCase
  MasterCurve::classify_node(const unsigned int node, const Point &x) const
  {
    NodeCase     result;
    const Point  r = difference(x, node_positions[node]);
    const double tolerance =
      1e-10 * norm(r) + 1e-14 * (scale + norm(node_positions[node]));

    result.has_outgoing = (node < n_segments());
    result.outgoing     = node;
    if (node > 0)
      {
        result.has_incoming = true;
        result.incoming     = node - 1;
      }
    else if (is_closed())
      {
        result.has_incoming = true;
        result.incoming     = n_segments() - 1;
      }

    if (result.has_outgoing)
      {
        result.outgoing_tangent = unit_tangent(result.outgoing, 0.);
        result.orthogonal_to_outgoing =
          std::abs(dot(r, result.outgoing_tangent)) <= tolerance;
      }
    if (result.has_incoming)
      {
        result.incoming_tangent = unit_tangent(result.incoming, 1.);
        result.orthogonal_to_incoming =
          std::abs(dot(r, result.incoming_tangent)) <= tolerance;
      }
    return result;
  }



  MasterCurve::Projection
  MasterCurve::project(const Point &x) const
  {
    if (n_segments() == 0 || !std::isfinite(x[0]) || !std::isfinite(x[1]))
      return Projection();

    // Deterministic order on candidates: a segment end s = 1 is the same
    // point as s = 0 of the next segment, so compare in that form.
    const auto canonical_key = [this](const Candidate &c) {
      unsigned int next;
      if (c.s == 1. && next_segment(c.segment, next))
        return std::make_pair(next, 0.);
      return std::make_pair(c.segment, c.s);
    };
    const auto is_better = [&](const Candidate &a, const Candidate &b) {
      const double tie = 1e-13 * (scale + a.distance + b.distance);
      if (a.distance < b.distance - tie)
        return true;
      if (b.distance < a.distance - tie)
        return false;
      if (a.stationary != b.stationary)
        return a.stationary;
      return canonical_key(a) < canonical_key(b);
    };

    std::vector<unsigned int> searched;
    std::vector<Candidate>    candidates;
    searched.reserve(4);
    candidates.reserve(8);
    Candidate  best;
    bool       have_best = false;
    const auto search    = [&](const unsigned int segment) {
      searched.push_back(segment);
      candidates.clear();
      minimize_on_segment(*this, segment, x, candidates);
      for (const Candidate &c : candidates)
        if (!have_best || is_better(c, best))
          {
            best      = c;
            have_best = true;
          }
    };
    const auto was_searched = [&](const unsigned int segment) {
      return std::find(searched.begin(), searched.end(), segment) !=
             searched.end();
    };

    // Steps 1 and 2: the segment leaving the nearest node k (none at the
    // last node of an open curve) and the one entering it (none at the
    // first node of an open curve).
    const unsigned int k = nearest_node(x);
    if (k < n_segments())
      search(k);
    if (k > 0)
      search(k - 1);
    else if (is_closed())
      search(n_segments() - 1);

    // Step 4: walk on while the best candidate sits at a segment end whose
    // neighbour has not been searched.
    while (searched.size() < n_segments())
      {
        unsigned int neighbour;
        bool         found = false;
        if (best.s == 0.)
          found = previous_segment(best.segment, neighbour);
        else if (best.s == 1.)
          found = next_segment(best.segment, neighbour);
        if (!found || was_searched(neighbour))
          break;
        search(neighbour);
      }

    // Step 6: the global check, always or when the local search ended on a
    // node without an orthogonal projection (corner or open end).
    const auto is_orthogonal = [&](const Candidate &c) {
      if (c.s != 0. && c.s != 1.)
        return true;
      const NodeCase node =
        classify_node(segment_nodes(c.segment)[c.s == 0. ? 0 : 1], x);
      return node.orthogonal_to_outgoing || node.orthogonal_to_incoming;
    };
    if (global_search || !is_orthogonal(best))
      {
        // The segments that may hold a closer point are searched nearest
        // box first, so that the best distance drops quickly and prunes
        // the rest. (Distances compared squared: no hypot in the O(N) box
        // loop.)
        const auto reach_squared = [&]() {
          const double reach =
            best.distance + 1e-13 * (scale + 2. * best.distance);
          return reach * reach;
        };
        for (const auto &[box_distance2, segment] :
             boxes_within(x, reach_squared(), searched))
          {
            if (box_distance2 > reach_squared())
              break;
            search(segment);
          }
      }

    return projection_from(best.segment, best.s, best.iterations, x);
  }



  MasterCurve::Projection
  MasterCurve::project_among(
    const Point                                   &x,
    const double                                   reach,
    const std::function<bool(unsigned int)>       &allowed,
    const std::function<bool(const Projection &)> &accept) const
  {
    Projection best;
    if (n_segments() == 0 || !std::isfinite(x[0]) || !std::isfinite(x[1]))
      return best;
    std::vector<Candidate> candidates;
    for (const auto &[box_distance2, segment] :
         boxes_within(x, reach * reach, {}))
      {
        if (best.valid && box_distance2 > best.distance * best.distance)
          break;
        if (!allowed(segment))
          continue;
        candidates.clear();
        minimize_on_segment(*this, segment, x, candidates);
        for (const Candidate &c : candidates)
          {
            if (best.valid && !(c.distance < best.distance))
              continue;
            const Projection p =
              projection_from(c.segment, c.s, c.iterations, x);
            if (p.valid && accept(p))
              best = p;
          }
      }
    return best;
  }



  std::vector<std::pair<double, unsigned int>>
  MasterCurve::boxes_within(const Point                     &x,
                            const double                     reach2,
                            const std::vector<unsigned int> &searched) const
  {
    const bool cached = (segment_boxes.size() == n_segments());
    std::vector<std::pair<double, unsigned int>> close_boxes;
    Point                                        low, high;
    for (unsigned int segment = 0; segment < n_segments(); ++segment)
      {
        if (cached)
          {
            low  = segment_boxes[segment][0];
            high = segment_boxes[segment][1];
          }
        else
          bounding_box(segment, low, high);
        const double dx = std::max(std::max(low[0] - x[0], x[0] - high[0]), 0.);
        const double dy = std::max(std::max(low[1] - x[1], x[1] - high[1]), 0.);
        const double box_distance2 = dx * dx + dy * dy;
        if (box_distance2 <= reach2 &&
            std::find(searched.begin(), searched.end(), segment) ==
              searched.end())
          close_boxes.emplace_back(box_distance2, segment);
      }
    std::sort(close_boxes.begin(), close_boxes.end());
    return close_boxes;
  }



  MasterCurve::Projection
  MasterCurve::projection_from(const unsigned int segment,
                               const double       s,
                               const unsigned int newton_iterations,
                               const Point       &x) const
  {
    Projection result;
    result.valid             = true;
    result.segment           = segment;
    result.s                 = s;
    result.newton_iterations = newton_iterations;

    // At a node: an orthogonal projection on one of its segments (the
    // outgoing first), a convex corner, or an open end.
    Point tangent;
    if (s == 0. || s == 1.)
      {
        const NodeCase node =
          classify_node(segment_nodes(segment)[s == 0. ? 0 : 1], x);
        if (node.has_outgoing && node.orthogonal_to_outgoing)
          {
            result.segment = node.outgoing;
            result.s       = 0.;
            tangent        = node.outgoing_tangent;
          }
        else if (node.has_incoming && node.orthogonal_to_incoming)
          {
            result.segment = node.incoming;
            result.s       = 1.;
            tangent        = node.incoming_tangent;
          }
        else if (node.has_outgoing && node.has_incoming)
          {
            result.on_vertex = true;
            result.segment   = node.outgoing;
            result.s         = 0.;
            tangent =
              corner_tangent(node.incoming_tangent, node.outgoing_tangent);
          }
        else
          {
            // Beyond an open end: the end segment's own normal.
            result.beyond_end = true;
            result.valid      = false;
            result.segment = node.has_outgoing ? node.outgoing : node.incoming;
            result.s       = node.has_outgoing ? 0. : 1.;
            tangent =
              node.has_outgoing ? node.outgoing_tangent : node.incoming_tangent;
          }
        if (result.segment != segment)
          result.newton_iterations = 0;
      }
    else
      tangent = unit_tangent(segment, s);

    result.point    = value(result.segment, result.s);
    result.tangent  = tangent;
    result.normal   = rotate_left(tangent);
    const Point r   = difference(x, result.point);
    result.gap      = dot(r, result.normal);
    result.distance = norm(r);
    return result;
  }
} // namespace glissade
