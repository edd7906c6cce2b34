// Tests of the master curves of glissade/contact: faceted, interpolating
// cubic B-spline (paper eq. 13-19) and cubic Hermite, and of the
// closest-point projection they share. Every figure is compared with an
// independent reference: a closed form, a symmetry, a dense solve of the
// paper's own equations, or brute-force sampling.
//
// Built by tests/CMakeLists.txt as surface_tests (one ctest test per group:
// ctest -R surface); run one group with build/tests/surface_tests <group>.

#include <functional>
#include <map>
#include <string>

#include "projection_tests.h"
#include "surface_test_tools.h"

using namespace surface_test_tools;

namespace
{
  using EndCondition = BSplineCurve::EndCondition;

  EndCondition
  end_condition(const bool closed)
  {
    return closed ? EndCondition::periodic : EndCondition::double_vertex;
  }


  // The control points must solve the paper's own (N+2)-unknown system,
  // assembled here row by row from eq. 16 and 18 (open) or 16 and 19
  // (closed, with the repeated data point P_N = P_0), by dense elimination.
  void
  test_against_paper_system()
  {
    std::printf("\nB-spline control points vs a dense solve of eq. 16-19\n");
    Random random(1);
    for (const bool closed : {false, true})
      for (const unsigned int n : {5u, 17u, 200u})
        {
          const auto p =
            closed ? closed_points(n, random) : open_points(n, random);
          BSplineCurve curve(end_condition(closed));
          curve.update(p);

          // Unknowns Q_{-1} .. Q_{m} stored at index i + 1, m data points.
          const unsigned int               m    = closed ? n + 1 : n;
          const unsigned int               size = m + 2;
          std::vector<std::vector<double>> A(size,
                                             std::vector<double>(size, 0.));
          std::vector<std::vector<double>> B(size, std::vector<double>(2, 0.));
          for (unsigned int i = 0; i < m; ++i) // eq. 16
            {
              A[i][i]     = 1. / 6.;
              A[i][i + 1] = 4. / 6.;
              A[i][i + 2] = 1. / 6.;
              B[i]        = {p[i % n][0], p[i % n][1]};
            }
          if (!closed) // eq. 18: Q_{-1} = Q_0, Q_N = Q_{N-1}
            {
              A[m][0] = 1., A[m][1] = -1.;
              A[m + 1][m + 1] = 1., A[m + 1][m] = -1.;
            }
          else // eq. 19: c' and c'' of segment 0 at 0 = segment m-2 at 1
            {
              A[m][0] = -1., A[m][2] = 1., A[m][m - 1] = 1., A[m][m + 1] = -1.;
              A[m + 1][0] = 1., A[m + 1][1] = -2., A[m + 1][2] = 1.;
              A[m + 1][m - 1] = -1., A[m + 1][m] = 2., A[m + 1][m + 1] = -1.;
            }
          dense_solve(A, B);

          double error = 0.;
          for (int i = -1; i <= int(closed ? m : n); ++i)
            error = std::max(error,
                             distance(curve.control_point(i),
                                      Point{{B[i + 1][0], B[i + 1][1]}}));
          check(error < 1e-13,
                "%s N=%3u: max |Q - Q_dense| (ghosts included) = %.2e < 1e-13",
                kind_name(closed),
                n,
                error);

          // The closed-form inverse used by weights() against the dense
          // inverse of the N x N matrix A.
          std::vector<std::vector<double>> An(n, std::vector<double>(n, 0.));
          std::vector<std::vector<double>> inverse(n,
                                                   std::vector<double>(n, 0.));
          for (unsigned int i = 0; i < n; ++i)
            {
              inverse[i][i] = 1.;
              An[i][i] += 4. / 6.;
              if (i > 0)
                An[i][i - 1] += 1. / 6.;
              else
                An[i][closed ? n - 1 : 0] += 1. / 6.;
              if (i + 1 < n)
                An[i][i + 1] += 1. / 6.;
              else
                An[i][closed ? 0 : n - 1] += 1. / 6.;
            }
          dense_solve(An, inverse);
          double inverse_error = 0.;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              inverse_error =
                std::max(inverse_error,
                         std::abs(curve.inverse_entry(i, j) - inverse[i][j]));
          check(inverse_error < 1e-14,
                "%s N=%3u: closed-form A^-1 vs dense inverse: %.2e < 1e-14",
                kind_name(closed),
                n,
                inverse_error);
        }
  }


  // Interpolation of the data points and C2 continuity at every joint,
  // the seam of a closed curve included.
  void
  test_interpolation_and_continuity()
  {
    std::printf("\nB-spline interpolation and C2 continuity\n");
    Random random(2);
    for (const bool closed : {false, true})
      for (const unsigned int n : {5u, 17u, 200u})
        {
          const auto p =
            closed ? closed_points(n, random) : open_points(n, random);
          BSplineCurve curve(end_condition(closed));
          curve.update(p);
          const unsigned int n_seg = curve.n_segments();

          double interpolation = 0.;
          for (unsigned int i = 0; i < n_seg; ++i)
            {
              interpolation =
                std::max(interpolation, distance(curve.value(i, 0.), p[i]));
              interpolation =
                std::max(interpolation,
                         distance(curve.value(i, 1.), p[(i + 1) % n]));
            }
          check(interpolation < 1e-14,
                "%s N=%3u: max |c(node) - P| = %.2e < 1e-14",
                kind_name(closed),
                n,
                interpolation);

          double jump[3] = {0., 0., 0.}, seam[3] = {0., 0., 0.};
          for (unsigned int i = 0; i < n_seg; ++i)
            {
              if (i + 1 == n_seg && !closed)
                break;
              const unsigned int j    = (i + 1) % n_seg;
              const double       d[3] = {
                      distance(curve.value(i, 1.), curve.value(j, 0.)),
                      distance(curve.derivative(i, 1.), curve.derivative(j, 0.)),
                      distance(curve.second_derivative(i, 1.),
                         curve.second_derivative(j, 0.))};
              for (unsigned int k = 0; k < 3; ++k)
                {
                  jump[k] = std::max(jump[k], d[k]);
                  if (j == 0)
                    seam[k] = d[k];
                }
            }
          check(jump[0] < 1e-14 && jump[1] < 1e-13 && jump[2] < 1e-13,
                "%s N=%3u: max jump at joints of c, c', c'' = %.1e %.1e %.1e",
                kind_name(closed),
                n,
                jump[0],
                jump[1],
                jump[2]);
          if (closed)
            check(seam[0] < 1e-14 && seam[1] < 1e-13 && seam[2] < 1e-13,
                  "closed N=%3u: jump at the seam of c, c', c'' = %.1e %.1e "
                  "%.1e",
                  n,
                  seam[0],
                  seam[1],
                  seam[2]);
        }
  }


  // Data points on a line give a curve on that line, for every kind; the
  // closed curve goes out and back along it.
  void
  test_straight_line()
  {
    std::printf("\nStraight line reproduction\n");
    Random       random(3);
    const Point  origin    = {{0.3, -0.2}};
    const Point  direction = {{0.6, 0.8}};
    const double length    = 2.;
    for (const CurveKind &kind : curve_kinds)
      for (const bool closed : {false, true})
        {
          std::vector<double> t;
          const unsigned int  n_out = 12;
          for (unsigned int i = 0; i < n_out; ++i)
            t.push_back(length * (i + 0.3 * random.uniform(-1, 1)) / n_out);
          if (closed) // back again, through other points
            for (unsigned int i = n_out - 2; i > 0; --i)
              t.push_back(length * (i + 0.5 + 0.2 * random.uniform(-1, 1)) /
                          n_out);
          std::vector<Point> p;
          for (double ti : t)
            p.push_back(
              {{origin[0] + ti * direction[0], origin[1] + ti * direction[1]}});
          const auto curve = make_curve(kind, closed, p);

          double off_line = 0.;
          for (unsigned int i = 0; i < curve->n_segments(); ++i)
            for (unsigned int k = 0; k <= 20; ++k)
              {
                const Point c = curve->value(i, k / 20.);
                off_line =
                  std::max(off_line,
                           std::abs((c[0] - origin[0]) * direction[1] -
                                    (c[1] - origin[1]) * direction[0]));
              }
          check(off_line < 1e-14 * length,
                "%-7s %-6s: max distance of the curve to the line = %.1e",
                kind.name.c_str(),
                kind_name(closed),
                off_line);
        }
  }


  // sum_j phi_j node_j = c(segment, s) and sum_j phi_j = 1.
  void
  test_weights()
  {
    std::printf("\nWeights: reproduction of c(s) and partition of unity\n");
    Random random(4);
    for (const CurveKind &kind : curve_kinds)
      for (const bool closed : {false, true})
        for (const unsigned int n : {5u, 17u, 200u, 2000u})
          {
            if (n == 2000 && kind.name != "bspline")
              continue;
            const auto p =
              closed ? closed_points(n, random) : open_points(n, random);
            const auto curve        = make_curve(kind, closed, p);
            double     reproduction = 0., unity = 0., hat = 0., derivative = 0.;
            std::size_t              widest = 0;
            MasterCurve::NodeWeights w;
            for (unsigned int trial = 0; trial < 40; ++trial)
              {
                const unsigned int segment =
                  std::min(curve->n_segments() - 1,
                           unsigned(random.uniform() * curve->n_segments()));
                const double s = (trial < 2 ? double(trial) : random.uniform());
                curve->weights(segment, s, w);
                widest       = std::max(widest, w.size());
                Point  sum   = {{0., 0.}};
                double total = 0.;
                for (const auto &[j, phi] : w)
                  {
                    sum[0] += phi * p[j][0];
                    sum[1] += phi * p[j][1];
                    total += phi;
                  }
                if (kind.name == "hermite")
                  {
                    const auto *h =
                      dynamic_cast<const HermiteCurve *>(curve.get());
                    const auto  tw = h->tangent_weights(segment, s);
                    const auto &d  = h->segment_tangents(segment);
                    for (unsigned int k = 0; k < 2; ++k)
                      {
                        sum[0] += tw[k] * d[k][0];
                        sum[1] += tw[k] * d[k][1];
                      }
                  }
                reproduction =
                  std::max(reproduction,
                           distance(sum, curve->value(segment, s)));
                unity = std::max(unity, std::abs(total - 1.));

                // The derivatives: sum_j phi_j' node_j = c'(s), the curve's
                // own derivative (for the B-spline from its control points,
                // the weights from the closed-form inverse).
                MasterCurve::NodeWeightsAndDerivatives wd;
                curve->weights_and_derivatives(segment, s, wd);
                Point slope = {{0., 0.}};
                for (const auto &e : wd)
                  {
                    slope[0] += e.derivative * p[e.node][0];
                    slope[1] += e.derivative * p[e.node][1];
                  }
                if (kind.name == "hermite")
                  {
                    const auto *h =
                      dynamic_cast<const HermiteCurve *>(curve.get());
                    const auto tw =
                      h->tangent_weights_and_derivatives(segment, s);
                    const auto &d = h->segment_tangents(segment);
                    for (unsigned int k = 0; k < 2; ++k)
                      {
                        slope[0] += tw[2 + k] * d[k][0];
                        slope[1] += tw[2 + k] * d[k][1];
                      }
                  }
                const Point dc = curve->derivative(segment, s);
                derivative     = std::max(derivative,
                                      distance(slope, dc) /
                                        std::max(1., std::hypot(dc[0], dc[1])));

                const auto  u = curve->underlying_segment_weights(segment, s);
                const auto  ends  = curve->segment_nodes(segment);
                const Point chord = {
                  {(1 - s) * p[ends[0]][0] + s * p[ends[1]][0],
                   (1 - s) * p[ends[0]][1] + s * p[ends[1]][1]}};
                const Point from_hats = {{u[0].second * p[u[0].first][0] +
                                            u[1].second * p[u[1].first][0],
                                          u[0].second * p[u[0].first][1] +
                                            u[1].second * p[u[1].first][1]}};
                hat = std::max(hat, distance(chord, from_hats));
              }
            check(reproduction < 1e-13 && unity < 1e-13 && hat < 1e-15 &&
                    derivative < 1e-12,
                  "%-7s %-6s N=%4u: |sum phi P - c| = %.1e, |sum phi - 1| = "
                  "%.1e, hats %.0e, |sum phi' P - c'| = %.1e, at most %zu "
                  "weights",
                  kind.name.c_str(),
                  kind_name(closed),
                  n,
                  reproduction,
                  unity,
                  hat,
                  derivative,
                  widest);
            if (kind.name == "bspline")
              check(widest <= 2 * 30 + 4,
                    "  B-spline weights stay banded: %zu <= 64",
                    widest);
          }
  }


  // Points on the curve project on themselves.
  void
  test_projection_of_curve_points()
  {
    std::printf("\nProjection of points that lie on the curve\n");
    Random random(5);
    for (const CurveKind &kind : curve_kinds)
      for (const bool closed : {false, true})
        {
          const auto p =
            closed ? closed_points(17, random) : open_points(17, random);
          const auto curve       = make_curve(kind, closed, p);
          double     point_error = 0., s_error = 0., gap = 0.;
          bool       all_recovered   = true;
          unsigned   most_iterations = 0;
          for (unsigned int trial = 0; trial < 200; ++trial)
            {
              const unsigned int segment =
                std::min(curve->n_segments() - 1,
                         unsigned(random.uniform() * curve->n_segments()));
              const double s  = random.uniform(0.02, 0.98);
              const Point  x  = curve->value(segment, s);
              const auto   pr = curve->project(x);
              point_error     = std::max(point_error, distance(pr.point, x));
              s_error         = std::max(s_error, std::abs(pr.s - s));
              gap             = std::max(gap, std::abs(pr.gap));
              most_iterations = std::max(most_iterations, pr.newton_iterations);
              all_recovered &= (pr.valid && pr.segment == segment &&
                                !pr.on_vertex && !pr.beyond_end);
            }
          check(all_recovered && point_error < 1e-13 && s_error < 1e-10 &&
                  gap < 1e-13,
                "%-7s %-6s: segment recovered, |dx| = %.1e, |ds| = %.1e, "
                "|gap| = %.1e, <= %u Newton iterations",
                kind.name.c_str(),
                kind_name(closed),
                point_error,
                s_error,
                gap,
                most_iterations);
        }
  }


  // Not a test: how long update() and project() take at the paper's scale.
  void
  print_timings()
  {
    std::printf("\nTimings (closed B-spline, N = 2000)\n");
    using clock          = std::chrono::steady_clock;
    const unsigned int n = 2000;
    const auto         p = circle_points(n, 1.);
    BSplineCurve       curve(EndCondition::periodic);
    curve.update(p); // first call: also builds the factorisation for N

    std::vector<Point> moved     = p;
    const unsigned int n_updates = 200;
    auto               start     = clock::now();
    for (unsigned int k = 0; k < n_updates; ++k)
      {
        moved[k % n][0] += 1e-6;
        curve.update(moved);
      }
    const double update_time =
      std::chrono::duration<double>(clock::now() - start).count() / n_updates;

    Random             random(7);
    std::vector<Point> x(n);
    for (auto &xi : x)
      {
        const double t = random.uniform(0., 2. * pi);
        const double r = random.uniform(0.95, 1.05);
        xi             = {{r * std::cos(t), r * std::sin(t)}};
      }
    start                        = clock::now();
    double              checksum = 0.;
    std::vector<double> gaps;
    for (const auto &xi : x)
      {
        const double gap = curve.project(xi).gap;
        checksum += gap;
        gaps.push_back(gap);
      }
    const double project_time =
      std::chrono::duration<double>(clock::now() - start).count();

    curve.set_global_search(true);
    double difference = 0.;
    start             = clock::now();
    for (const auto &xi : x)
      difference =
        std::max(difference,
                 std::abs(curve.project(xi).gap - gaps[&xi - &x[0]]));
    const double global_time =
      std::chrono::duration<double>(clock::now() - start).count();
    curve.set_global_search(false);

    MasterCurve::NodeWeights w;
    start = clock::now();
    for (unsigned int k = 0; k < n; ++k)
      curve.weights(k, 0.37, w);
    const double weights_time =
      std::chrono::duration<double>(clock::now() - start).count();

    std::printf("  update(), N = 2000:                     %8.1f us\n",
                1e6 * update_time);
    std::printf("  project() of 2000 points (brute-force nearest node): "
                "%8.2f ms total, %.2f us each (checksum %.3e)\n",
                1e3 * project_time,
                1e6 * project_time / n,
                checksum);
    std::printf("  the same with set_global_search(true):  %8.2f ms total "
                "(largest gap difference %.1e)\n",
                1e3 * global_time,
                difference);
    std::printf("  weights() at 2000 points:               %8.2f ms total\n",
                1e3 * weights_time);
  }
} // namespace


// Each is a ctest test of its own ("surface_<name>", tests/harness.h); the
// timings are printed by the benchmark target, not by a test.
static const glissade_tests::Registrations tests = {
  {{"bspline_paper_system", test_against_paper_system},
   {"interpolation_continuity", test_interpolation_and_continuity},
   {"straight_line", test_straight_line},
   {"weights", test_weights},
   {"projection_on_curve", test_projection_of_curve_points},
   {"projection_is_closest", test_projection_is_closest},
   {"projection_circle_convergence", test_circle_convergence},
   {"projection_robustness", test_projection_robustness}}};
static const glissade_tests::Registrations benchmarks = {{{"timings",
                                                           print_timings}},
                                                         false};
