// The half-plane / rigid cylinder problem of bipotential_tests.cc: a check
// against Hertz's solution and the timing printout for n = 100, 500, 2000.
// A separate file only to keep bipotential_tests.cc short.

#include "bipotential_hertz_timing.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bipotential_reference.h"
#include "bipotential_test_helpers.h"

namespace test_helpers
{
  // --------------------------------------------------------------------
  void
  test_hertz_and_timing()
  {
    std::printf(
      "\n== Rigid cylinder (R = 1) on an elastic half-plane (E* = 1): "
      "Hertz check and timing\n");
    std::printf("  Hertz 2D: a^2 = 4 P R / (pi E*), p0 = 2 P / (pi a); "
                "target a = 0.5 gives d = (a^2/2R)(ln(2L/a) + 1/2)\n");
    std::printf(
      "       n  case           beta  sweeps  time [s]  ms/sweep  closed  "
      "P/P_hertz  p0/p0_hertz  complementarity\n");
    const double a = 0.5, R = 1., L = 8.;
    const double d        = a * a / (2. * R) * (std::log(2. * L / a) + 0.5);
    const double P_hertz  = M_PI * a * a / (4. * R);
    const double p0_hertz = 2. * P_hertz / (M_PI * a);
    for (const unsigned int n : {100u, 500u, 2000u})
      {
        std::vector<double>    x;
        const ComplianceMatrix W = reference::half_plane(n, x);
        const double           h = 2. / n;
        std::vector<Vector2>   u_free(n);
        for (unsigned int k = 0; k < n; ++k)
          u_free[k] = {{0.01 * (1. + x[k]), x[k] * x[k] / (2. * R) - d}};

        struct Case
        {
          const char *name;
          double      beta;
          double      mu;
          bool        warm_start;
        };
        std::vector<Case> cases = {{"cold", 1., 0., false},
                                   {"warm", 1., 0., true},
                                   {"cold mu=0.3", 1., 0.3, false}};
        if (n <= 500)
          cases.push_back({"cold", 1.9, 0., false});

        std::vector<Vector2> r_previous;
        for (const Case &c : cases)
          {
            BiPotentialSolver::Settings settings;
            settings.beta       = c.beta;
            settings.max_sweeps = 100000;
            // The warm start imitates the next Newton iteration: the
            // reactions of the last solve, the indenter 1% deeper.
            std::vector<Vector2> u_case = u_free;
            std::vector<Vector2> r;
            if (c.warm_start)
              {
                r = r_previous;
                for (auto &u : u_case)
                  u[1] -= 0.01 * d;
              }
            const auto start  = std::chrono::steady_clock::now();
            const auto result = BiPotentialSolver(settings).solve(
              W, u_case, std::vector<double>(n, c.mu), r);
            const double seconds = std::chrono::duration<double>(
                                     std::chrono::steady_clock::now() - start)
                                     .count();
            if (!c.warm_start && c.mu == 0.)
              r_previous = r;
            double       P      = 0.;
            unsigned int closed = 0;
            for (const auto &r_k : r)
              {
                P += r_k[1];
                closed += r_k[1] > 0.;
              }
            const double p0 = 0.5 * (r[n / 2 - 1][1] + r[n / 2][1]) / h;
            std::printf("  %6u  %-12s  %4.1f  %6u  %8.3f  %8.3f  %6u  %9.4f  "
                        "%11.4f  %.1e\n",
                        n,
                        c.name,
                        c.beta,
                        result.sweeps,
                        seconds,
                        1e3 * seconds / result.sweeps,
                        closed,
                        P / P_hertz,
                        p0 / p0_hertz,
                        result.residuals.complementarity);
            check(result.converged, "converged");
            if (!c.warm_start)
              // Friction changes the normal solution only through the
              // (here absent) tangential-normal coupling of W.
              check(std::abs(P / P_hertz - 1.) < 0.03 &&
                      std::abs(p0 / p0_hertz - 1.) < 0.03,
                    "load and peak pressure within 3% of Hertz");
          }
        std::printf("  (W: %.1f MB)\n", W.memory_consumption() / 1048576.);
      }
  }
} // namespace test_helpers
