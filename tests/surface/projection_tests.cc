// The projection tests of surface_tests.cc: global optimality against
// brute-force sampling, convergence on a circle, and the awkward cases.

#include "projection_tests.h"

#include <stdexcept>

#include "surface_test_tools.h"

namespace surface_test_tools
{
  namespace
  {
    // Closest distance to the curve by dense sampling: an upper bound on the
    // true distance, independent of project().
    double
    sampled_distance(const MasterCurve &curve, const Point &x)
    {
      double best = 1e300;
      for (unsigned int i = 0; i < curve.n_segments(); ++i)
        for (unsigned int k = 0; k <= 400; ++k)
          best = std::min(best, distance(curve.value(i, k / 400.), x));
      return best;
    }
  } // namespace


  // The projection is at least as close as any sampled curve point, and is
  // an orthogonal projection unless flagged otherwise.
  void
  test_projection_is_closest()
  {
    std::printf("\nProjection vs brute-force sampling (wavy closed curve, "
                "N = 40)\n");
    Random             random(6);
    const unsigned int n = 40;
    std::vector<Point> p(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = -2. * pi * i / n;
        const double r = 1. + 0.25 * std::sin(5. * t);
        p[i]           = {{r * std::cos(t), r * std::sin(t)}};
      }
    for (const CurveKind &kind : curve_kinds)
      {
        const auto curve = make_curve(kind, true, p);
        for (const unsigned int mode : {0u, 1u, 2u})
          {
            // mode 0: points within 0.1 of the curve, default search;
            // mode 1: anywhere in the box, default search (local minima
            // possible, reported only); mode 2: anywhere, global search.
            curve->set_global_search(mode == 2);
            unsigned int not_closest = 0, not_orthogonal = 0, iterations = 0;
            double       excess = 0.;
            for (unsigned int trial = 0; trial < 300; ++trial)
              {
                Point x;
                if (mode == 0)
                  {
                    const double t = random.uniform(0., 2. * pi);
                    const double r =
                      1. + 0.25 * std::sin(5. * t) + random.uniform(-0.1, 0.1);
                    x = {{r * std::cos(t), r * std::sin(t)}};
                  }
                else
                  x = {{random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5)}};
                const auto   pr      = curve->project(x);
                const double sampled = sampled_distance(*curve, x);
                iterations = std::max(iterations, pr.newton_iterations);
                if (pr.distance > sampled + 1e-12)
                  {
                    ++not_closest;
                    excess = std::max(excess, pr.distance - sampled);
                  }
                const Point r = {{x[0] - pr.point[0], x[1] - pr.point[1]}};
                if (!pr.on_vertex &&
                    std::abs(r[0] * pr.tangent[0] + r[1] * pr.tangent[1]) >
                      1e-9 * (pr.distance + 1.))
                  ++not_orthogonal;
              }
            const char *what[3] = {"near the curve, default search ",
                                   "anywhere,       default search ",
                                   "anywhere,       global search  "};
            if (mode == 1)
              std::printf("  [info] %-7s %s: %u of 300 are a local, not the "
                          "global, minimum (worst by %.2e)\n",
                          kind.name.c_str(),
                          what[mode],
                          not_closest,
                          excess);
            else
              check(not_closest == 0 && not_orthogonal == 0 &&
                      iterations < MasterCurve::max_newton_iterations,
                    "%-7s %s: %u of 300 farther than sampling, %u not "
                    "orthogonal, <= %u Newton iterations",
                    kind.name.c_str(),
                    what[mode],
                    not_closest,
                    not_orthogonal,
                    iterations);
          }
        curve->set_global_search(false);
      }
  }


  namespace
  {
    struct CircleErrors
    {
      double foot_on  = 0.; // |c* - x| for x on the circle
      double gap      = 0.; // |g - (|x| - R)| for x off the circle
      double foot_off = 0.; // |c* - R x/|x|| for x off the circle
      double normal   = 0.; // |n - x/|x||     for x off the circle
    };

    // Errors of the projection on an N-node approximation of the circle of
    // radius R, against the exact projection R x/|x|, over 97 directions and
    // the radii R (on the circle), 0.9 R and 1.1 R.
    CircleErrors
    circle_errors(const CurveKind &kind, const unsigned int n, const double R)
    {
      const auto points   = circle_points(n, R);
      const auto tangents = circle_tangents(n, R);
      const auto curve    = make_curve(kind, true, points, &tangents);

      CircleErrors e;
      for (unsigned int m = 0; m < 97; ++m)
        {
          const double phi   = 2. * pi * (m + 0.618) / 97.;
          const Point  dir   = {{std::cos(phi), std::sin(phi)}};
          const Point  exact = {{R * dir[0], R * dir[1]}};
          for (const double radius : {1., 0.9, 1.1})
            {
              const Point x  = {{radius * R * dir[0], radius * R * dir[1]}};
              const auto  pr = curve->project(x);
              if (radius == 1.)
                e.foot_on = std::max(e.foot_on, distance(pr.point, exact));
              else
                {
                  e.foot_off = std::max(e.foot_off, distance(pr.point, exact));
                  e.normal   = std::max(e.normal, distance(pr.normal, dir));
                }
              e.gap = std::max(e.gap, std::abs(pr.gap - (radius - 1.) * R));
            }
        }
      return e;
    }
  } // namespace


  void
  test_circle_convergence()
  {
    std::printf("\nProjection on an N-node circle (R = 2) against R x/|x|\n");
    const double                    R = 2.;
    const std::vector<unsigned int> sizes{16, 32, 64, 128};
    for (const CurveKind &kind : curve_kinds)
      {
        std::vector<CircleErrors> e;
        for (unsigned int n : sizes)
          e.push_back(circle_errors(kind, n, R));
        std::printf("  %-7s      N  foot(on)  gap      foot(off) normal\n",
                    kind.name.c_str());
        for (unsigned int i = 0; i < sizes.size(); ++i)
          std::printf("  %-7s %6u  %.2e  %.2e  %.2e  %.2e\n",
                      "",
                      sizes[i],
                      e[i].foot_on,
                      e[i].gap,
                      e[i].foot_off,
                      e[i].normal);
        const auto order = [&](double CircleErrors::*member, unsigned int i) {
          return std::log2(e[i].*member / e[i + 1].*member);
        };
        double low[4] = {1e9, 1e9, 1e9, 1e9};
        for (unsigned int i = 0; i + 1 < sizes.size(); ++i)
          {
            std::printf("  %-7s %3u->%-3u orders %.2f      %.2f      %.2f      "
                        "%.2f\n",
                        "",
                        sizes[i],
                        sizes[i + 1],
                        order(&CircleErrors::foot_on, i),
                        order(&CircleErrors::gap, i),
                        order(&CircleErrors::foot_off, i),
                        order(&CircleErrors::normal, i));
            if (i == 0)
              continue; // the asymptotic range starts at N = 32
            low[0] = std::min(low[0], order(&CircleErrors::foot_on, i));
            low[1] = std::min(low[1], order(&CircleErrors::gap, i));
            low[2] = std::min(low[2], order(&CircleErrors::foot_off, i));
            low[3] = std::min(low[3], order(&CircleErrors::normal, i));
          }
        // Interpolation order p of the kind (curve_kinds: 2 faceted, 4
        // cubic): the distance to the curve is 1-Lipschitz in the curve's
        // position error, so the foot of an on-curve point and the gap
        // converge like h^p. Off the curve the foot moves along the curve by
        // (distance) x (normal error), and the normal error is one order
        // lower, h^(p-1).
        const double p = kind.order;
        check(low[0] > p - 0.2 && low[1] > p - 0.2,
              "%-7s: order of foot (on the circle) %.2f and gap %.2f, "
              "expected %.0f",
              kind.name.c_str(),
              low[0],
              low[1],
              p);
        check(low[2] > p - 1.2 && low[3] > p - 1.2,
              "%-7s: order of foot (off the circle) %.2f and normal %.2f, "
              "expected %.0f",
              kind.name.c_str(),
              low[2],
              low[3],
              p - 1.);
      }

    // The open B-spline with double-vertex ends, on a half circle: the end
    // condition is only O(h^2) accurate, but its effect decays like 0.268
    // per node, so the middle of the arc converges at order 4.
    std::printf("  open B-spline on a half circle: gap error\n");
    double middle[4], whole[4];
    for (unsigned int i = 0; i < sizes.size(); ++i)
      {
        const unsigned int n = sizes[i] / 2 + 1;
        std::vector<Point> p(n);
        for (unsigned int k = 0; k < n; ++k)
          {
            const double t = pi - pi * k / (n - 1); // left to right, on top
            p[k]           = {{R * std::cos(t), R * std::sin(t)}};
          }
        const auto curve = make_curve("bspline", false, p);
        middle[i] = whole[i] = 0.;
        for (unsigned int m = 0; m <= 100; ++m)
          {
            const double phi = pi * (0.02 + 0.96 * (m + 0.618) / 101.);
            const Point  x   = {
                 {1.1 * R * std::cos(phi), 1.1 * R * std::sin(phi)}};
            const double e = std::abs(curve->project(x).gap - 0.1 * R);
            whole[i]       = std::max(whole[i], e);
            if (phi > pi / 4 && phi < 3 * pi / 4)
              middle[i] = std::max(middle[i], e);
          }
        std::printf("  %-7s %6u  middle %.2e  whole arc %.2e\n",
                    "",
                    sizes[i],
                    middle[i],
                    whole[i]);
      }
    const double middle_order = std::log2(middle[2] / middle[3]);
    const double whole_order  = std::log2(whole[2] / whole[3]);
    check(middle_order > 3.8,
          "open B-spline, middle of the arc: order %.2f (64->128), expected 4; "
          "whole arc (ends included): %.2f",
          middle_order,
          whole_order);
  }

  // The awkward cases: no NaN, flags as documented, bounded iterations.
  void
  test_projection_robustness()
  {
    std::printf("\nProjection: awkward cases\n");
    const unsigned int cap  = MasterCurve::max_newton_iterations;
    const auto         sane = [cap](const MasterCurve::Projection &pr) {
      return finite(pr) && pr.newton_iterations <= cap;
    };

    // A closed B-spline circle, R = 1, 24 nodes.
    const auto  circle = make_curve("bspline", true, circle_points(24, 1.));
    const auto &nodes  = circle->nodes();
    {
      const auto pr = circle->project(nodes[5]);
      check(sane(pr) && pr.valid && pr.segment == 5 && pr.s == 0. &&
              pr.distance == 0. && !pr.on_vertex,
            "exactly on node 5: segment %u, s = %g, gap %.1e, on_vertex %d",
            pr.segment,
            pr.s,
            pr.gap,
            pr.on_vertex);
    }
    {
      const auto pr = circle->project(nodes[0]);
      check(sane(pr) && pr.valid && pr.segment == 0 && pr.s == 0.,
            "exactly on the seam node 0: segment %u, s = %g (documented: "
            "s = 0 of segment 0)",
            pr.segment,
            pr.s);
      const Point off   = {{1.3, 0.}};
      const auto  pr2   = circle->project(off);
      const auto  below = circle->project(Point{{1.3, -1e-9}});
      const auto  above = circle->project(Point{{1.3, 1e-9}});
      check(sane(pr2) && pr2.segment == 0 && pr2.s < 1e-12 &&
              std::abs(pr2.gap - 0.3) < 1e-12 && below.segment == 0 &&
              above.segment == 23 && above.s > 0.999 &&
              std::abs(below.gap - above.gap) < 1e-12,
            "off the seam: segment %u s = %.1e; just below: %u s = %.2e; just "
            "above: %u s = %.10f; gap jump %.1e",
            pr2.segment,
            pr2.s,
            below.segment,
            below.s,
            above.segment,
            above.s,
            std::abs(below.gap - above.gap));
    }
    {
      const auto pr  = circle->project(Point{{0., 0.}});
      const auto pr2 = circle->project(Point{{0., 0.}});
      check(sane(pr) && pr.valid && std::abs(pr.distance - 1.) < 1e-3 &&
              pr.segment == pr2.segment && pr.s == pr2.s,
            "centre of the circle: valid, segment %u s = %.3f, distance "
            "%.6f, gap %.6f, repeatable",
            pr.segment,
            pr.s,
            pr.distance,
            pr.gap);
    }
    {
      // Spline errors for N = 24 (see the convergence table): position
      // ~2e-5, normal ~2e-4, so the foot of a far point moves by ~2e-4 R.
      const Point  x    = {{1e6, 3e5}};
      const auto   pr   = circle->project(x);
      const double r    = std::hypot(x[0], x[1]);
      const double foot = distance(pr.point, Point{{x[0] / r, x[1] / r}});
      check(sane(pr) && pr.valid && foot < 1e-3 &&
              std::abs(pr.gap - (r - 1.)) < 1e-4,
            "far away point (1e6, 3e5): valid, |c* - x/|x|| = %.1e, gap error "
            "%.1e, %u iterations",
            foot,
            std::abs(pr.gap - (r - 1.)),
            pr.newton_iterations);
    }

    // Open curves along the x axis, from (0,0) to (3,0): n = (0,1).
    std::vector<Point> line;
    for (unsigned int i = 0; i <= 6; ++i)
      line.push_back({{0.5 * i, 0.1 * std::sin(double(i))}});
    for (const CurveKind &kind : curve_kinds)
      {
        const auto curve = make_curve(kind, false, line);
        const auto last  = curve->project(line.back());
        const auto first = curve->project(line.front());
        check(sane(last) && last.valid && !last.beyond_end &&
                last.segment == 5 && last.s == 1. && sane(first) &&
                first.valid && first.segment == 0 && first.s == 0.,
              "%-7s on the open ends: last node -> segment %u s = %g, first "
              "node -> segment %u s = %g",
              kind.name.c_str(),
              last.segment,
              last.s,
              first.segment,
              first.s);

        // Beyond the first node: back along the end tangent and up.
        const Point t0 = curve->unit_tangent(0, 0.);
        const Point n0 = curve->unit_normal(0, 0.);
        const Point x  = {{line[0][0] - 0.4 * t0[0] + 0.2 * n0[0],
                           line[0][1] - 0.4 * t0[1] + 0.2 * n0[1]}};
        const auto  pr = curve->project(x);
        check(sane(pr) && !pr.valid && pr.beyond_end && pr.segment == 0 &&
                pr.s == 0. && distance(pr.normal, n0) < 1e-15 &&
                std::abs(pr.gap - 0.2) < 1e-14,
              "%-7s beyond the open end: valid %d, beyond_end %d, gap %.15f "
              "(0.2), normal = end normal",
              kind.name.c_str(),
              pr.valid,
              pr.beyond_end,
              pr.gap);
      }

    // A faceted square, clockwise: (0,0) (0,1) (1,1) (1,0).
    const std::vector<Point> square = {{{0., 0.}},
                                       {{0., 1.}},
                                       {{1., 1.}},
                                       {{1., 0.}}};
    FacetedCurve             box(true);
    box.update(square);
    {
      const auto   pr = box.project(Point{{1.3, 1.2}});
      const double h  = std::sqrt(0.5);
      check(sane(pr) && pr.valid && pr.on_vertex && pr.segment == 2 &&
              pr.s == 0. && distance(pr.normal, Point{{h, h}}) < 1e-15 &&
              std::abs(pr.gap - 0.5 * h) < 1e-15 &&
              std::abs(pr.distance - std::sqrt(0.13)) < 1e-15,
            "convex corner of the square: on_vertex %d, segment %u s = %g, "
            "normal (%.4f, %.4f), gap %.6f",
            pr.on_vertex,
            pr.segment,
            pr.s,
            pr.normal[0],
            pr.normal[1],
            pr.gap);
      const auto inside = box.project(Point{{0.9, 0.8}});
      const auto axis   = box.project(Point{{0.9, 0.9}});
      check(inside.segment == 2 && std::abs(inside.gap + 0.1) < 1e-15 &&
              !inside.on_vertex && axis.segment == 1 &&
              std::abs(axis.s - 0.9) < 1e-15 &&
              std::abs(axis.gap + 0.1) < 1e-15,
            "inside the corner: segment %u gap %.3f; on the bisector (tie): "
            "segment %u (lower index) s = %.3f",
            inside.segment,
            inside.gap,
            axis.segment,
            axis.s);
    }

    // Two coincident data points (a degenerate segment).
    std::vector<Point> doubled = circle_points(12, 1.);
    doubled.insert(doubled.begin() + 4, doubled[4]);
    for (const CurveKind &kind : curve_kinds)
      for (const bool closed : {false, true})
        {
          const auto curve = make_curve(kind, closed, doubled);
          bool       ok    = true;
          for (const Point &x :
               {doubled[4],
                Point{{1.2 * doubled[4][0], 1.2 * doubled[4][1]}},
                Point{{0.8 * doubled[4][0], 0.8 * doubled[4][1]}},
                Point{{1.1 * doubled[3][0], 1.1 * doubled[3][1]}}})
            {
              const auto pr = curve->project(x);
              ok &= sane(pr) && pr.valid;
            }
          for (unsigned int i = 0; i < curve->n_segments(); ++i)
            for (double s : {0., 0.5, 1.})
              {
                const Point t = curve->unit_tangent(i, s);
                ok &= std::isfinite(t[0]) && std::isfinite(t[1]) &&
                      std::abs(std::hypot(t[0], t[1]) - 1.) < 1e-14;
              }
          check(ok,
                "%-7s %-6s with two coincident nodes: finite, valid results "
                "and unit tangents",
                kind.name.c_str(),
                kind_name(closed));
        }

    // All nodes at one point, and a Hermite curve without tangents.
    {
      FacetedCurve collapsed(true);
      collapsed.update(std::vector<Point>(5, Point{{0.5, 0.5}}));
      const auto pr = collapsed.project(Point{{1., 2.}});
      check(sane(pr) && pr.valid && pr.segment == 0 && pr.s == 0. &&
              std::abs(pr.distance - std::hypot(0.5, 1.5)) < 1e-15,
            "all nodes coincide: finite, segment %u s = %g, distance %.4f",
            pr.segment,
            pr.s,
            pr.distance);
      HermiteCurve no_tangents(false);
      no_tangents.update(line);
      bool thrown = false;
      try
        {
          no_tangents.project(Point{{1., 1.}});
        }
      catch (const std::logic_error &)
        {
          thrown = true;
        }
      check(thrown, "Hermite curve without tangents: std::logic_error thrown");
    }

    // The nearest node is not on the closest segment: the end of a branch
    // next to the middle of a long segment.
    FacetedCurve hook(false);
    hook.update({{{0., 0.}}, {{10., 0.}}, {{10., 2.}}, {{5.2, 2.}}});
    const auto pr = hook.project(Point{{5., 0.9}});
    check(sane(pr) && pr.valid && pr.segment == 0 &&
            std::abs(pr.s - 0.5) < 1e-15 && std::abs(pr.distance - 0.9) < 1e-15,
          "closest segment not adjacent to the nearest node: segment %u s = "
          "%.3f distance %.3f (found by the global check)",
          pr.segment,
          pr.s,
          pr.distance);

    // Same, but the nearest node's segment holds an orthogonal projection
    // (a local minimum): the documented limitation of the default search,
    // lifted by set_global_search(true).
    FacetedCurve hook2(false);
    hook2.update(
      {{{0., 0.}}, {{10., 0.}}, {{10., 1.}}, {{4., 1.}}, {{4., 0.2}}});
    const Point x2    = {{6., 0.45}};
    const auto  local = hook2.project(x2);
    hook2.set_global_search(true);
    const auto global = hook2.project(x2);
    check(sane(local) && local.segment == 3 &&
            std::abs(local.distance - 2.) < 1e-15 && global.segment == 0 &&
            std::abs(global.distance - 0.45) < 1e-15,
          "local minimum near the nearest node: default search -> segment %u "
          "at distance %.2f (documented), global search -> segment %u at %.2f",
          local.segment,
          local.distance,
          global.segment,
          global.distance);
  }
} // namespace surface_test_tools
