// Unit tests of ComplianceMatrix and BiPotentialSolver (the local problem of
// the bi-potential method, CONTACT_ALGORITHM.md step 4). Each test compares
// with a reference that does not use the solver: closed forms, active-set
// enumeration, Murty's pivoting method, enumeration of Coulomb patterns,
// and Hertz's solution on a half-plane. Prints every figure it checks;
// exits with the number of failed checks.

#include <glissade/contact/local_solvers/bipotential_solver.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "bipotential_hertz_timing.h"
#include "bipotential_reference.h"
#include "bipotential_test_helpers.h"

using namespace glissade;
using Vector2    = BiPotentialSolver::Vector2;
using Outcome    = BiPotentialSolver::Outcome;
using NodeStatus = BiPotentialSolver::NodeStatus;
using Block      = ComplianceMatrix::Block;

namespace
{
  using namespace test_helpers;

  // --------------------------------------------------------------------
  void
  test_single_node_frictionless()
  {
    std::printf(
      "\n== Single node, frictionless: r_n = max(0, -g_free / W_nn)\n");
    const BiPotentialSolver solver = tight_solver();
    for (const double g_free : {-0.3, 0.4, 0.})
      {
        // A tangential-normal coupling W_tn only moves u_t: r_t stays 0.
        const ComplianceMatrix W  = single_node(1.5, 0.25, 2.);
        std::vector<Vector2>   r  = {{{0.7, 0.9}}}; // a poor warm start
        const auto   result       = solver.solve(W, {{{0.1, g_free}}}, {0.}, r);
        const double expected_r_n = std::max(0., -g_free / 2.);
        const double expected_gap = g_free + 2. * expected_r_n;
        std::printf(
          "  g_free %+.2f: r = (%g, %.15g), gap %.3g, %u sweeps, %s\n",
          g_free,
          r[0][0],
          r[0][1],
          result.displacement[0][1],
          result.sweeps,
          name(result.status[0]));
        check(result.converged, "converged");
        check(r[0][0] == 0., "r_t = 0 exactly");
        check(std::abs(r[0][1] - expected_r_n) <= 1e-14,
              format("r_n = %.15g (closed form %.15g)", r[0][1], expected_r_n));
        check(std::abs(result.displacement[0][1] - expected_gap) <= 1e-14,
              format("gap %.3g (closed form %.3g)",
                     result.displacement[0][1],
                     expected_gap));
        check(std::abs(result.displacement[0][0] -
                       (0.1 + 0.25 * expected_r_n)) <= 1e-14,
              "u_t = u_t_free + W_tn r_n");
        check(result.status[0] ==
                (g_free < 0. ? NodeStatus::slip : NodeStatus::open),
              "status: closed frictionless = slip, else open");
      }
  }

  // --------------------------------------------------------------------
  void
  test_coupled_frictionless()
  {
    std::printf(
      "\n== Coupled random SPD W, frictionless, vs Murty and enumeration\n");
    const BiPotentialSolver solver;
    for (const unsigned int n : {2u, 3u, 5u, 8u, 20u, 50u})
      for (unsigned int seed = 1; seed <= 3; ++seed)
        {
          const ComplianceMatrix W = reference::random_spd(n, 100 * n + seed);
          std::mt19937           generator(seed);
          std::uniform_real_distribution<double> uniform(-1., 1.);
          std::vector<Vector2>                   u_free(n);
          for (auto &u : u_free)
            u = {{uniform(generator), uniform(generator)}};
          const std::vector<double> mu(n, 0.);
          std::vector<Vector2>      r;
          const auto                result = solver.solve(W, u_free, mu, r);

          // The reference solves the LCP on the normal components only.
          const reference::DenseMatrix dense = reference::to_dense(W);
          const reference::DenseMatrix M     = reference::normal_part(dense);
          std::vector<double>          q(n), z;
          for (unsigned int k = 0; k < n; ++k)
            q[k] = u_free[k][1];
          const int    pivots     = reference::murty_lcp(M, q, z);
          double       difference = 0., largest = 0.;
          unsigned int n_closed = 0;
          for (unsigned int k = 0; k < n; ++k)
            {
              difference = std::max(difference, std::abs(r[k][1] - z[k]));
              largest    = std::max(largest, std::abs(z[k]));
              n_closed += z[k] > 0.;
            }
          // The gaps, reaction signs and products, computed here.
          const std::vector<Vector2> u =
            reference::displacement(dense, u_free, r);
          double min_gap = 0., min_r = 0., max_product = 0.;
          for (unsigned int k = 0; k < n; ++k)
            {
              min_gap     = std::min(min_gap, u[k][1]);
              min_r       = std::min(min_r, r[k][1]);
              max_product = std::max(max_product, std::abs(u[k][1] * r[k][1]));
            }
          std::printf("  n %2u seed %u: %2u closed, %4u sweeps, |r - r_Murty| "
                      "%.1e (Murty pivots %d), min g %.1e, max |g r_n| %.1e\n",
                      n,
                      seed,
                      n_closed,
                      result.sweeps,
                      difference,
                      pivots,
                      min_gap,
                      max_product);
          check(result.converged && pivots >= 0, "both converged");
          check(difference <= 1e-8 * largest, "r matches Murty to 1e-8");
          check(min_gap >= -1e-10 && min_r >= 0. && max_product <= 1e-10,
                "g >= -1e-10, r_n >= 0, |g r_n| <= 1e-10");
          if (n <= 8)
            {
              const auto solutions = reference::enumerate_lcp(M, q);
              double     enumeration_difference = 1e300;
              if (solutions.size() == 1)
                {
                  enumeration_difference = 0.;
                  for (unsigned int k = 0; k < n; ++k)
                    enumeration_difference =
                      std::max(enumeration_difference,
                               std::abs(r[k][1] - solutions[0][k]));
                }
              check(solutions.size() == 1 &&
                      enumeration_difference <= 1e-8 * largest,
                    format("unique enumerated solution (%g found), "
                           "|r - r_enum| %.1e",
                           solutions.size(),
                           enumeration_difference));
            }
          const auto residuals =
            compute_contact_residuals(W, u_free, mu, r, 0.);
          check(residuals.complementarity <= 1e-10 && residuals.friction == 0.,
                format("independent residuals: complementarity %.1e, "
                       "friction %.1e",
                       residuals.complementarity,
                       residuals.friction));
        }
  }

  // --------------------------------------------------------------------
  // W = H K^-1 G^T is not symmetric when the reaction is handed to other
  // master nodes than those that measure the displacement (the paper's
  // underlying-Q4 variant). With a positive definite symmetric part, W is
  // still a P-matrix, the LCP has one solution, and Murty's method finds it.
  void
  test_nonsymmetric_frictionless()
  {
    std::printf(
      "\n== Non-symmetric W (SPD + skew part), frictionless, vs Murty\n");
    const unsigned int                     n = 20;
    ComplianceMatrix                       W = reference::random_spd(n, 77);
    std::mt19937                           generator(8);
    std::uniform_real_distribution<double> uniform(-0.05, 0.05);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = k + 1; l < n; ++l)
        {
          const double skew = uniform(generator);
          W.add_block(k, l, {{{{0., 0.}}, {{0., skew}}}});
          W.add_block(l, k, {{{{0., 0.}}, {{0., -skew}}}});
        }
    std::vector<Vector2> u_free(n);
    for (auto &u : u_free)
      u = {{0., 2. * uniform(generator) * 10.}};
    std::vector<Vector2> r;
    const auto           result =
      BiPotentialSolver().solve(W, u_free, std::vector<double>(n, 0.), r);
    const reference::DenseMatrix M =
      reference::normal_part(reference::to_dense(W));
    std::vector<double> q(n), z;
    for (unsigned int k = 0; k < n; ++k)
      q[k] = u_free[k][1];
    reference::murty_lcp(M, q, z);
    double difference = 0., largest = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        difference = std::max(difference, std::abs(r[k][1] - z[k]));
        largest    = std::max(largest, std::abs(z[k]));
      }
    std::printf("  asymmetry %.2e, %u sweeps, |r - r_Murty| %.1e\n",
                W.max_asymmetry(),
                result.sweeps,
                difference);
    check(result.converged && difference <= 1e-8 * largest,
          "converges to the LCP solution");
  }

  // --------------------------------------------------------------------
  void
  test_single_node_coulomb()
  {
    std::printf("\n== Single node, Coulomb, decoupled W = diag(1.5, 1), "
                "g_free = -1, mu = 0.4\n");
    const double            w_tt = 1.5, w_nn = 1., mu = 0.4, g_free = -1.;
    const ComplianceMatrix  W         = single_node(w_tt, 0., w_nn);
    const BiPotentialSolver solver    = tight_solver();
    const double            r_n       = -g_free / w_nn;
    const double            threshold = mu * r_n * w_tt; // stick limit on u_t

    std::printf("  ramp of u_t_free (saturation at mu r_n W_tt = %g):\n",
                threshold);
    std::printf(
      "    u_t_free      r_t   closed form   r_n   u_t  status sweeps\n");
    std::vector<Vector2> r_warm;
    bool                 ramp_ok = true;
    for (unsigned int step = 0; step <= 12; ++step)
      {
        const double u_t_free = -0.1 + 0.1 * step; // crosses zero, then past
        const double expected_r_t = std::abs(u_t_free) <= threshold ?
                                      -u_t_free / w_tt :
                                      -std::copysign(mu * r_n, u_t_free);
        const auto   result =
          solver.solve(W, {{{u_t_free, g_free}}}, {mu}, r_warm);
        std::printf("    %8.3f %8.4f %10.4f %8.4f %6.3f  %-6s %u\n",
                    u_t_free,
                    r_warm[0][0],
                    expected_r_t,
                    r_warm[0][1],
                    result.displacement[0][0],
                    name(result.status[0]),
                    result.sweeps);
        ramp_ok = ramp_ok && result.converged &&
                  std::abs(r_warm[0][0] - expected_r_t) <= 1e-12 &&
                  std::abs(r_warm[0][1] - r_n) <= 1e-12;
        if (std::abs(u_t_free) > threshold * 1.01)
          ramp_ok = ramp_ok && result.status[0] == NodeStatus::slip &&
                    r_warm[0][0] * result.displacement[0][0] < 0.;
        else if (std::abs(u_t_free) < threshold * 0.99 && u_t_free != 0.)
          ramp_ok = ramp_ok && result.status[0] == NodeStatus::stick &&
                    std::abs(result.displacement[0][0]) <= 1e-12;
      }
    check(ramp_ok,
          "r_t = -u_t_free / W_tt up to mu r_n, then -mu r_n sign(u_t), "
          "u_t = 0 in stick, r_t opposite to u_t in slip (warm started)");

    std::printf("  coupled block W = [[1.2, 0.3], [0.3, 1.0]], g_free = -1, "
                "mu = 0.3:\n");
    const ComplianceMatrix W_coupled = single_node(1.2, 0.3, 1.);
    {
      // Stick: W r = -u_free, solved by Cramer's rule.
      const double         u_t_free = 0.05, det = 1.2 * 1. - 0.3 * 0.3;
      const double         r_t       = -(1. * u_t_free - 0.3 * g_free) / det;
      const double         r_n_stick = -(1.2 * g_free - 0.3 * u_t_free) / det;
      std::vector<Vector2> r;
      const auto           result =
        solver.solve(W_coupled, {{{u_t_free, g_free}}}, {0.3}, r);
      std::printf("    stick: r = (%.12f, %.12f), closed form (%.12f, %.12f), "
                  "|r_t|/(mu r_n) = %.3f\n",
                  r[0][0],
                  r[0][1],
                  r_t,
                  r_n_stick,
                  std::abs(r_t) / (0.3 * r_n_stick));
      check(result.converged && result.status[0] == NodeStatus::stick &&
              std::abs(r[0][0] - r_t) <= 1e-12 &&
              std::abs(r[0][1] - r_n_stick) <= 1e-12,
            "coupled stick matches Cramer's rule");
    }
    {
      // Slip in +t: r_t = -mu r_n and g = 0 give r_n = -g_free /
      // (W_nn - mu W_nt); consistent if the final u_t is still positive.
      const double u_t_free = 2.;
      const double r_n_slip = -g_free / (1. - 0.3 * 0.3);
      const double u_t      = u_t_free - 1.2 * 0.3 * r_n_slip + 0.3 * r_n_slip;
      std::vector<Vector2> r;
      const auto           result =
        solver.solve(W_coupled, {{{u_t_free, g_free}}}, {0.3}, r);
      std::printf("    slip:  r = (%.12f, %.12f), closed form (%.12f, %.12f), "
                  "u_t %.6f (closed form %.6f), %u sweeps\n",
                  r[0][0],
                  r[0][1],
                  -0.3 * r_n_slip,
                  r_n_slip,
                  result.displacement[0][0],
                  u_t,
                  result.sweeps);
      check(result.converged && result.status[0] == NodeStatus::slip &&
              std::abs(r[0][1] - r_n_slip) <= 1e-12 &&
              std::abs(r[0][0] + 0.3 * r_n_slip) <= 1e-12 &&
              std::abs(result.displacement[0][0] - u_t) <= 1e-12 &&
              std::abs(result.displacement[0][1]) <= 1e-12,
            "coupled slip: |r_t| = mu r_n, r_t opposite to u_t, g = 0");
    }
  }

  // --------------------------------------------------------------------
  void
  test_coupled_coulomb()
  {
    std::printf("\n== Coupled random SPD W with friction (mu = 0.3), vs "
                "enumeration of open/stick/slip patterns\n");
    const BiPotentialSolver solver;
    for (const unsigned int n : {2u, 3u, 4u})
      for (unsigned int seed = 1; seed <= 4; ++seed)
        {
          const ComplianceMatrix W =
            reference::random_spd(n, 7 * n + seed, 0.5);
          std::mt19937                           generator(50 + seed);
          std::uniform_real_distribution<double> uniform(-1., 1.);
          std::vector<Vector2>                   u_free(n);
          for (auto &u : u_free)
            u = {{0.5 * uniform(generator), uniform(generator) - 0.3}};
          const std::vector<double> mu(n, 0.3);
          std::vector<Vector2>      r;
          const auto                result = solver.solve(W, u_free, mu, r);
          const auto                solutions =
            reference::enumerate_coulomb(reference::to_dense(W), u_free, mu);
          const double difference =
            solutions.size() == 1 ? max_difference(r, solutions[0]) : 1e300;
          std::string statuses;
          for (const auto status : result.status)
            statuses += std::string(name(status)) + " ";
          std::printf("  n %u seed %u: %4u sweeps, %zu reference solution(s), "
                      "|r - r_ref| %.1e, residuals %.1e %.1e, %s\n",
                      n,
                      seed,
                      result.sweeps,
                      solutions.size(),
                      difference,
                      result.residuals.complementarity,
                      result.residuals.friction,
                      statuses.c_str());
          check(result.converged && solutions.size() == 1 &&
                  difference <= 1e-8 * (1. + max_abs(r)),
                "converged to the unique enumerated solution");
        }
  }

  // --------------------------------------------------------------------
  void
  beta_study(const std::string          &title,
             const ComplianceMatrix     &W,
             const std::vector<Vector2> &u_free,
             const std::vector<double>  &mu)
  {
    std::printf("  %s\n    beta  sweeps  |r - r(beta=1)|\n", title.c_str());
    BiPotentialSolver::Settings settings;
    settings.max_sweeps = 200000;
    std::vector<Vector2> r_reference;
    BiPotentialSolver(settings).solve(W, u_free, mu, r_reference);
    bool all_ok = true;
    for (const double beta : {0.1, 0.5, 1., 1.5, 1.9})
      {
        settings.beta = beta;
        std::vector<Vector2> r;
        const auto result = BiPotentialSolver(settings).solve(W, u_free, mu, r);
        const double difference = max_difference(r, r_reference);
        std::printf("    %4.1f  %6u  %.1e\n", beta, result.sweeps, difference);
        all_ok = all_ok && result.converged &&
                 difference <= 1e-7 * max_abs(r_reference);
      }
    check(all_ok, "all beta converge to the same reactions (1e-7 relative)");
  }

  void
  test_beta()
  {
    std::printf("\n== Convergence across beta in (0, 2)\n");
    {
      const unsigned int                     n = 30;
      const ComplianceMatrix                 W = reference::random_spd(n, 4242);
      std::mt19937                           generator(3);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      std::vector<Vector2>                   u_free(n);
      for (auto &u : u_free)
        u = {{uniform(generator), uniform(generator)}};
      beta_study("random SPD, n = 30, frictionless",
                 W,
                 u_free,
                 std::vector<double>(n, 0.));
      beta_study("same W and u_free, mu = 0.2",
                 W,
                 u_free,
                 std::vector<double>(n, 0.2));
    }
    {
      std::vector<double>    x;
      const unsigned int     n = 100;
      const ComplianceMatrix W = reference::half_plane(n, x);
      std::vector<Vector2>   u_free(n);
      for (unsigned int k = 0; k < n; ++k)
        u_free[k] = {{0.01 * (1. + x[k]), 0.5 * x[k] * x[k] - 0.1}};
      beta_study("half-plane + rigid cylinder, n = 100, frictionless",
                 W,
                 u_free,
                 std::vector<double>(n, 0.));
      beta_study("same, mu = 0.3 with a tangential free slip",
                 W,
                 u_free,
                 std::vector<double>(n, 0.3));
    }
  }

  // --------------------------------------------------------------------
  void
  test_degenerate_input()
  {
    std::printf("\n== Degenerate input\n");
    const BiPotentialSolver solver;
    const unsigned int      n = 20;
    const ComplianceMatrix  W = reference::random_spd(n, 99);
    std::vector<Vector2>    u_free(n);
    for (unsigned int k = 0; k < n; ++k)
      u_free[k] = {{0.1 * k, 0.1 + 0.05 * k}};
    const std::vector<double> mu(n, 0.3);
    {
      std::vector<Vector2> r;
      const auto           result = solver.solve(W, u_free, mu, r);
      std::printf("  all open: %u sweep(s), max |r| %g, %s\n",
                  result.sweeps,
                  max_abs(r),
                  result.message.c_str());
      check(result.converged && result.sweeps == 1 && max_abs(r) == 0. &&
              max_difference(result.displacement, u_free) == 0.,
            "all open: zero reactions in one sweep, u = u_free");
    }
    {
      std::vector<Vector2> r(n, Vector2{{0.2, 0.5}});
      const auto           result = solver.solve(W, u_free, mu, r);
      std::printf(
        "  all open, warm start r = (0.2, 0.5): %u sweeps, max |r| %g\n",
        result.sweeps,
        max_abs(r));
      check(result.converged && max_abs(r) == 0., "stale warm start released");
    }
    {
      ComplianceMatrix W_rigid = W;
      for (unsigned int l = 0; l < n; ++l) // node 7 between two rigid bodies
        {
          W_rigid.set_block(7, l, {{{{0., 0.}}, {{0., 0.}}}});
          W_rigid.set_block(l, 7, {{{{0., 0.}}, {{0., 0.}}}});
        }
      std::vector<Vector2> r(n, Vector2{{0., 1.}});
      const auto           result = solver.solve(W_rigid, u_free, mu, r);
      std::printf("  W_77 = 0: %s\n", result.message.c_str());
      check(result.outcome == Outcome::singular_node &&
              result.singular_nodes == std::vector<unsigned int>{7} &&
              r[0][1] == 1.,
            "W_nn = 0 reported with the node number, r untouched");
    }
    const double nan     = std::numeric_limits<double>::quiet_NaN();
    const double inf     = std::numeric_limits<double>::infinity();
    const auto   refused = [&](const std::string       &what,
                             const BiPotentialSolver &s,
                             const ComplianceMatrix  &W_,
                             std::vector<Vector2>     u_,
                             std::vector<double>      mu_,
                             std::vector<Vector2>     r_) {
      const std::vector<Vector2> r_before = r_;
      const auto                 result   = s.solve(W_, u_, mu_, r_);
      std::printf("  %s: %s\n", what.c_str(), result.message.c_str());
      bool unchanged = r_.size() == r_before.size();
      for (std::size_t k = 0; unchanged && k < r_.size(); ++k)
        unchanged = (r_[k] == r_before[k]) ||
                    (std::isnan(r_[k][0]) && std::isnan(r_before[k][0]));
      check(result.outcome == Outcome::invalid_input && unchanged,
            what + " refused, r untouched");
    };
    std::vector<Vector2> bad_u = u_free;
    bad_u[3][1]                = nan;
    refused("NaN gap", solver, W, bad_u, mu, {});
    std::vector<double> bad_mu = mu;
    bad_mu[5]                  = -0.1;
    refused("negative mu", solver, W, u_free, bad_mu, {});
    std::vector<Vector2> bad_r(n, Vector2{{0., 0.}});
    bad_r[2][0] = nan;
    refused("NaN warm start", solver, W, u_free, mu, bad_r);
    ComplianceMatrix W_bad = W;
    W_bad.set_block(4, 9, {{{{inf, 0.}}, {{0., 0.}}}});
    refused("Inf in W", solver, W_bad, u_free, mu, {});
    refused("size mismatch", solver, W, std::vector<Vector2>(n - 1), mu, {});
    BiPotentialSolver::Settings settings;
    settings.beta = 2.;
    refused("beta = 2", BiPotentialSolver(settings), W, u_free, mu, {});

    {
      // Not positive semi-definite: two nodes that push each other in. PSOR
      // then runs away; the solver must notice and give back the start.
      ComplianceMatrix W_indefinite(2);
      W_indefinite.set_block(0, 0, {{{{1., 0.}}, {{0., 1.}}}});
      W_indefinite.set_block(1, 1, {{{{1., 0.}}, {{0., 1.}}}});
      W_indefinite.set_block(0, 1, {{{{0., 0.}}, {{0., -2.}}}});
      W_indefinite.set_block(1, 0, {{{{0., 0.}}, {{0., -2.}}}});
      std::vector<Vector2> r = {{{0., 0.1}}, {{0., 0.2}}};
      const auto           result =
        solver.solve(W_indefinite, {{{0., -1.}}, {{0., -1.}}}, {0., 0.}, r);
      std::printf("  indefinite W: %s; r = (%g, %g), (%g, %g)\n",
                  result.message.c_str(),
                  r[0][0],
                  r[0][1],
                  r[1][0],
                  r[1][1]);
      check(result.outcome == Outcome::diverged && r[0][1] == 0.1 &&
              r[1][1] == 0.2 && std::isfinite(result.residuals.complementarity),
            "divergence detected, starting reactions returned, no NaN");
    }

    std::printf("  stick node with W_tt = 3 W_nn (rho W_tt = 3 beta > 2):\n");
    const ComplianceMatrix W_soft_t = single_node(3., 0., 1.);
    for (const auto choice :
         {BiPotentialSolver::RhoChoice::normal_compliance,
          BiPotentialSolver::RhoChoice::largest_diagonal_compliance})
      {
        settings            = tight_solver().get_settings();
        settings.beta       = 1.;
        settings.rho_choice = choice;
        settings.max_sweeps = 500;
        std::vector<Vector2> r;
        const auto           result =
          BiPotentialSolver(settings).solve(W_soft_t, {{{0.1, -1.}}}, {0.5}, r);
        const bool normal =
          choice == BiPotentialSolver::RhoChoice::normal_compliance;
        std::printf("    %s: %s; r = (%g, %g)\n",
                    normal ? "rho = beta / W_nn" : "rho = beta / lambda_max",
                    result.message.c_str(),
                    r[0][0],
                    r[0][1]);
        check(std::isfinite(r[0][0]) && std::isfinite(r[0][1]) &&
                std::isfinite(result.residuals.friction),
              "no NaN");
        if (!normal)
          check(result.converged && std::abs(r[0][0] + 0.1 / 3.) <= 1e-12 &&
                  std::abs(r[0][1] - 1.) <= 1e-12,
                "largest_diagonal_compliance converges to r = (-u_t/W_tt, 1)");
      }
  }

  // --------------------------------------------------------------------
  void
  test_block_sparse_storage()
  {
    std::printf("\n== Block-sparse storage: two independent contact pairs\n");
    const unsigned int n = 40, half = n / 2;
    const auto         first  = reference::random_spd(half, 11);
    const auto         second = reference::random_spd(half, 12);
    ComplianceMatrix   dense(n),
      sparse(n, ComplianceMatrix::Storage::block_sparse);
    for (unsigned int k = 0; k < half; ++k)
      for (unsigned int l = 0; l < half; ++l)
        {
          dense.add_block(k, l, first.block(k, l));
          dense.add_block(half + k, half + l, second.block(k, l));
          // Scattered insertion order exercises the sorted insert.
          sparse.add_block(half + l, half + k, second.block(l, k));
          sparse.add_block(k, l, first.block(k, l));
        }
    std::mt19937                           generator(5);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    std::vector<Vector2>                   u_free(n);
    for (auto &u : u_free)
      u = {{uniform(generator), uniform(generator)}};
    const std::vector<double> mu(n, 0.2);
    std::vector<Vector2>      r_dense, r_sparse;
    const BiPotentialSolver   solver;
    const auto result_dense  = solver.solve(dense, u_free, mu, r_dense);
    const auto result_sparse = solver.solve(sparse, u_free, mu, r_sparse);
    std::printf("  blocks stored: dense %zu, sparse %zu; memory %zu vs %zu "
                "bytes; sweeps %u vs %u; |r_dense - r_sparse| %.1e\n",
                dense.n_stored_blocks(),
                sparse.n_stored_blocks(),
                dense.memory_consumption(),
                sparse.memory_consumption(),
                result_dense.sweeps,
                result_sparse.sweeps,
                max_difference(r_dense, r_sparse));
    check(sparse.n_stored_blocks() == 2 * half * half &&
            sparse.max_asymmetry() == 0. && dense.max_asymmetry() == 0.,
          "sparse stores only the two pair blocks; both symmetric");
    check(result_dense.converged && result_sparse.converged &&
            max_difference(r_dense, r_sparse) <= 1e-12 * max_abs(r_dense),
          "same reactions from both storages");
  }


  // --------------------------------------------------------------------
  // Two nodes whose compliances are almost equal (a stiff slave on a soft
  // master): W = [[1, 1 - e], [1 - e, 1]] in the normal direction. Projected
  // Gauss-Seidel contracts by about (1 - e) per sweep, so it cannot reach
  // the tolerance in the sweeps allowed; the active-set polish must, and
  // give the closed form r_n = 1 / (2 - e) for g_free = -1 at both nodes.
  void
  test_ill_conditioned_polish()
  {
    std::printf("\n== Ill-conditioned W: the active-set polish\n");
    for (const double e : {1e-3, 1e-6})
      {
        ComplianceMatrix W(2);
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            W.set_block(
              k, l, {{{{k == l ? 1. : 0., 0.}}, {{0., k == l ? 1. : 1. - e}}}});
        BiPotentialSolver::Settings settings;
        settings.max_sweeps = 1000;
        for (const unsigned int period : {0u, 100u})
          {
            settings.polish_period = period;
            std::vector<Vector2> r;
            // Unequal free gaps, so that the iteration has to split the load.
            const auto result = BiPotentialSolver(settings).solve(
              W, {{{0., -1.}}, {{0., -1. - 0.5 * e}}}, {0., 0.}, r);
            // Closed form of W r = -g_free on the two closed nodes.
            const double det = 1. - (1. - e) * (1. - e);
            const double r0  = (1. - (1. - e) * (1. + 0.5 * e)) / det;
            const double r1  = ((1. + 0.5 * e) - (1. - e)) / det;
            const double error =
              std::max(std::abs(r[0][1] - r0), std::abs(r[1][1] - r1));
            std::printf(
              "  e = %g, polish period %u: %s after %u sweeps%s, |r - exact| = %.3g\n",
              e,
              period,
              result.converged ? "converged" : "not converged",
              result.sweeps,
              result.polished ? " (polished)" : "",
              error);
            if (period == 0)
              check(
                !result.converged || e > 1e-4,
                "plain Gauss-Seidel should not converge in 1000 sweeps at e = 1e-6");
            else
              check(result.converged && result.polished &&
                      error <= 1e-9 * std::max(r0, r1),
                    "the polish gives the exact reactions");
          }
      }
  }

  // Two closed nodes whose gaps are one gap (a node on a node, each the
  // other's counterpart, as two passes of a pair make them): W = [[1, 1],
  // [1, 1]] in the normal direction, g_free = -1 at both. Only the sum of
  // the reactions is fixed, r_0 + r_1 = 1; the linear law of the closed
  // statuses is singular, and the active-set iteration, which solves it at
  // every update, used to find nothing. Its answer of least norm, r = (0.5,
  // 0.5), closes both gaps; Gauss-Seidel's (any split) closes them too.
  void
  test_redundant_constraints()
  {
    std::printf("\n== Redundant constraints: a node on a node, both ways\n");
    ComplianceMatrix W(2);
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int l = 0; l < 2; ++l)
        W.set_block(k, l, {{{{k == l ? 1. : 0., 0.}}, {{0., 1.}}}});
    const std::vector<Vector2>  u_free = {{{0., -1.}}, {{0., -1.}}};
    BiPotentialSolver::Settings settings;
    settings.max_sweeps = 1000;
    const BiPotentialSolver solver(settings);
    for (const bool active_set : {true, false})
      {
        std::vector<Vector2> r;
        const auto           result =
          active_set ? solver.solve_by_active_set(W, u_free, {0., 0.}, r) :
                                 solver.solve(W, u_free, {0., 0.}, r);
        const double gap = -1. + r[0][1] + r[1][1];
        std::printf("  %s: %s after %u %s, r_n = (%.12g, %.12g), gap %.3g\n",
                    active_set ? "active set" : "Gauss-Seidel",
                    result.converged ? "converged" : "not converged",
                    result.sweeps,
                    active_set ? "updates" : "sweeps",
                    r[0][1],
                    r[1][1],
                    gap);
        check(result.converged, "the redundant law is solved");
        check(std::abs(gap) <= 1e-12 && r[0][1] >= 0. && r[1][1] >= 0.,
              "the shared gap is closed by reactions that push");
        if (active_set)
          check(std::abs(r[0][1] - 0.5) <= 1e-12 &&
                  std::abs(r[1][1] - 0.5) <= 1e-12,
                "the least-norm answer shares the force equally");
      }
  }
} // namespace

// Each group is a ctest test of its own ("contact_local_<group>"); the
// Hertz check also prints timings.
// Each is a ctest test of its own ("contact_local_<name>",
// tests/harness.h); the Hertz timing is printed by the benchmark target.
namespace
{
  // --------------------------------------------------------------------
  // A yielding layer's law (BiPotentialSolver::solve with caps): r_n in
  // [0, cap], g >= 0 where open, g = 0 below the cap, g <= 0 at it.
  void
  test_capped_normal_law()
  {
    std::printf("\n== Capped normal reactions (a yielding layer)\n");
    const BiPotentialSolver solver = tight_solver();
    // One node, frictionless: r_n = min(cap, max(0, -g_free / W_nn)).
    for (const double cap : {0.1, 0.2, std::numeric_limits<double>::infinity()})
      {
        const ComplianceMatrix W = single_node(1., 0., 2.);
        std::vector<Vector2>   r;
        const auto   result   = solver.solve(W, {{{0., -0.3}}}, {0.}, r, {cap});
        const double expected = std::min(cap, 0.15);
        std::printf("  cap %g: r_n %.15g (closed form %g), gap %.3g\n",
                    cap,
                    r[0][1],
                    expected,
                    result.displacement[0][1]);
        check(result.converged, "converged");
        check(std::abs(r[0][1] - expected) <= 1e-14, "r_n = min(cap, 0.15)");
        check(std::abs(result.displacement[0][1] - (-0.3 + 2. * expected)) <=
                1e-14,
              "the gap: g_free + W r_n (behind the master at the cap)");
      }
    // One node, mu = 0.5, slipping at the cap: r = (-mu cap, cap).
    {
      const ComplianceMatrix W = single_node(1., 0., 2.);
      std::vector<Vector2>   r;
      const auto result = solver.solve(W, {{{0.2, -0.3}}}, {0.5}, r, {0.1});
      std::printf("  mu 0.5, cap 0.1: r = (%.15g, %.15g), u = (%.3g, %.3g)\n",
                  r[0][0],
                  r[0][1],
                  result.displacement[0][0],
                  result.displacement[0][1]);
      check(result.converged, "converged with friction");
      check(std::abs(r[0][1] - 0.1) <= 1e-14 &&
              std::abs(r[0][0] + 0.05) <= 1e-14,
            "slipping at the cap: r = (-mu cap, cap)");
    }
    // Coupled random SPD W, frictionless, caps drawn at random: against
    // the enumeration of every node's state (open, closed, at its cap).
    unsigned int total_at_cap = 0;
    for (const unsigned int n : {2u, 3u, 5u})
      for (unsigned int seed = 1; seed <= 4; ++seed)
        {
          const ComplianceMatrix W = reference::random_spd(n, 300 * n + seed);
          const reference::DenseMatrix M =
            reference::normal_part(reference::to_dense(W));
          std::mt19937                           generator(seed);
          std::uniform_real_distribution<double> uniform(-1., 1.);
          std::vector<Vector2>                   u_free(n);
          std::vector<double>                    cap(n);
          for (unsigned int k = 0; k < n; ++k)
            {
              u_free[k] = {{0., uniform(generator)}};
              cap[k]    = 0.2 + 1.5 * (1. + uniform(generator));
            }
          std::vector<Vector2> r;
          const auto           result =
            solver.solve(W, u_free, std::vector<double>(n, 0.), r, cap);
          // Enumeration: state 0 open, 1 closed (g = 0), 2 at the cap.
          unsigned int states = 1;
          for (unsigned int k = 0; k < n; ++k)
            states *= 3;
          unsigned int        found = 0;
          std::vector<double> reference_r;
          for (unsigned int code = 0; code < states; ++code)
            {
              std::vector<unsigned int> state(n);
              for (unsigned int k = 0, c = code; k < n; ++k, c /= 3)
                state[k] = c % 3;
              // r of the closed nodes from g = 0, the others fixed
              std::vector<double> z(n, 0.);
              std::vector<int>    closed;
              for (unsigned int k = 0; k < n; ++k)
                if (state[k] == 2)
                  z[k] = cap[k];
                else if (state[k] == 1)
                  closed.push_back(k);
              const unsigned int  m = closed.size();
              std::vector<double> A(m * m), b(m);
              for (unsigned int i = 0; i < m; ++i)
                {
                  b[i] = -u_free[closed[i]][1];
                  for (unsigned int k = 0; k < n; ++k)
                    if (state[k] == 2)
                      b[i] -= M(closed[i], k) * z[k];
                  for (unsigned int j = 0; j < m; ++j)
                    A[i * m + j] = M(closed[i], closed[j]);
                }
              // Gauss elimination (small, SPD)
              bool regular = true;
              for (unsigned int i = 0; i < m && regular; ++i)
                {
                  regular = std::abs(A[i * m + i]) > 1e-14;
                  for (unsigned int j = i + 1; j < m && regular; ++j)
                    {
                      const double f = A[j * m + i] / A[i * m + i];
                      for (unsigned int c = i; c < m; ++c)
                        A[j * m + c] -= f * A[i * m + c];
                      b[j] -= f * b[i];
                    }
                }
              if (!regular)
                continue;
              for (int i = int(m) - 1; i >= 0; --i)
                {
                  double v = b[i];
                  for (unsigned int c = i + 1; c < m; ++c)
                    v -= A[i * m + c] * b[c];
                  b[i] = v / A[i * m + i];
                }
              for (unsigned int i = 0; i < m; ++i)
                z[closed[i]] = b[i];
              bool admissible = true;
              for (unsigned int k = 0; k < n; ++k)
                {
                  double g = u_free[k][1];
                  for (unsigned int l = 0; l < n; ++l)
                    g += M(k, l) * z[l];
                  const double tolerance = 1e-12;
                  admissible             = admissible &&
                               (state[k] == 0 ? g >= -tolerance :
                                state[k] == 1 ? z[k] >= -tolerance &&
                                                  z[k] <= cap[k] + tolerance :
                                                g <= tolerance);
                }
              if (admissible)
                {
                  ++found;
                  reference_r = z;
                }
            }
          double       difference = 0.;
          unsigned int at_cap = 0, closed = 0;
          for (unsigned int k = 0; k < n && found > 0; ++k)
            {
              difference =
                std::max(difference, std::abs(r[k][1] - reference_r[k]));
              at_cap += r[k][1] >= cap[k] * (1. - 1e-12);
              closed += r[k][1] > 0. && r[k][1] < cap[k] * (1. - 1e-12);
            }
          total_at_cap += at_cap;
          std::printf("  n %u seed %u: %u closed, %u at their caps; %u "
                      "admissible state patterns, %u sweeps, |r - "
                      "r_enumerated| %.1e\n",
                      n,
                      seed,
                      closed,
                      at_cap,
                      found,
                      result.sweeps,
                      difference);
          check(result.converged, "converged");
          check(found >= 1, "the enumeration found the solution");
          check(difference <= 1e-9, "r matches the enumeration to 1e-9");
        }
    check(total_at_cap > 0, "some nodes of the random problems are at caps");
  }
} // namespace

static const glissade_tests::Registrations tests = {
  {{"single_node_frictionless", test_single_node_frictionless},
   {"coupled_frictionless", test_coupled_frictionless},
   {"nonsymmetric_frictionless", test_nonsymmetric_frictionless},
   {"single_node_coulomb", test_single_node_coulomb},
   {"coupled_coulomb", test_coupled_coulomb},
   {"beta_range", test_beta},
   {"degenerate_input", test_degenerate_input},
   {"block_sparse_storage", test_block_sparse_storage},
   {"ill_conditioned_polish", test_ill_conditioned_polish},
   {"redundant_constraints", test_redundant_constraints},
   {"capped_normal_law", test_capped_normal_law}}};
static const glissade_tests::Registrations benchmarks =
  {{{"hertz_and_timing", test_hertz_and_timing}}, false};
