#include <glissade/contact/local_solvers/bipotential_solver.h>
#include <glissade/lac/lapack.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace glissade
{
  namespace
  {
    using Vector2    = BiPotentialSolver::Vector2;
    using Residuals  = BiPotentialSolver::Residuals;
    using Outcome    = BiPotentialSolver::Outcome;
    using NodeStatus = BiPotentialSolver::NodeStatus;

    constexpr unsigned int t = ComplianceMatrix::tangential;
    constexpr unsigned int n = ComplianceMatrix::normal;

    // Sweeps between two recomputations of u = u_free + W r from scratch,
    // so that the round-off of the incremental updates cannot pile up.
    constexpr unsigned int refresh_period = 128;

    // A diagonal entry below this fraction of the largest one is round-off
    // of an assembly in which both bodies are rigid.
    constexpr double singular_fraction = 1e-14;

    // Sweeps with unchanged statuses after which the linear law on the
    // closed nodes is solved (the polish), then four times as many again
    // while they stay unchanged.
    constexpr unsigned int first_polish_after_stable_sweeps = 5;

    // Restarts of Gauss-Seidel from a projected polish at most, per solve.
    constexpr unsigned int max_polish_restarts = 20;

    // Reactions this many times larger than the problem's own force scale
    // mean that the fixed-point iteration is running away.
    constexpr double divergence_factor = 1e30;

    inline double
    norm(const Vector2 &v)
    {
      return std::sqrt(v[0] * v[0] + v[1] * v[1]);
    }

    inline bool
    is_finite(const Vector2 &v)
    {
      return std::isfinite(v[0]) && std::isfinite(v[1]);
    }

    double
    max_norm(const std::vector<Vector2> &vectors)
    {
      double result = 0.;
      for (const Vector2 &v : vectors)
        result = std::max(result, norm(v));
      return result;
    }

    // u = u_free + W r.
    void
    compute_displacement(const ComplianceMatrix     &W,
                         const std::vector<Vector2> &u_free,
                         const std::vector<Vector2> &r,
                         std::vector<Vector2>       &u)
    {
      u = u_free;
      W.add_product(r, u);
    }

    // The residuals of the contact law at each node, from a consistent pair
    // (u, r). See BiPotentialSolver::Residuals for what each one means.
    // The cap on node k's normal reaction (none: infinity).
    double
    cap_of(const std::vector<double> &cap, const std::size_t k)
    {
      return cap.empty() ? std::numeric_limits<double>::infinity() : cap[k];
    }

    // The residuals of the contact law at each node, from a consistent pair
    // (u, r). See BiPotentialSolver::Residuals for what each one means.
    // Where a node's normal reaction is capped (a yielding layer), its
    // normal law is r_n in [0, cap], g >= 0 where r_n = 0, g = 0 where 0 <
    // r_n < cap, g <= 0 where r_n = cap.
    Residuals
    residuals_of(const std::vector<Vector2> &u,
                 const std::vector<Vector2> &r,
                 const std::vector<double>  &mu,
                 const double                scale,
                 const std::vector<double>  &cap = {})
    {
      Residuals result;
      for (std::size_t k = 0; k < u.size(); ++k)
        {
          const double gap   = u[k][n];
          const double cap_k = cap_of(cap, k);
          const bool   yielding =
            std::isfinite(cap_k) && r[k][n] >= cap_k * (1. - 1e-12);
          result.complementarity = std::max(
            result.complementarity,
            std::isfinite(cap_k) ?
              std::abs(
                scale * r[k][n] -
                std::max(0., std::min(scale * cap_k, scale * r[k][n] - gap))) :
              std::abs(std::min(gap, scale * r[k][n])));
          if (!yielding)
            result.max_penetration = std::max(result.max_penetration, -gap);

          // Coulomb's law for the tangential part, at the given normal
          // reaction: s r_t must be the projection of s r_t - u_t onto
          // [-mu s r_n, mu s r_n]. Inside the interval this says u_t = 0
          // (stick); at the end -mu s r_n it says u_t >= 0, i.e. the slave
          // slips in +t and friction pulls it back (and symmetrically).
          const double half_width = mu[k] * scale * std::max(r[k][n], 0.);
          const double scaled_r_t = scale * r[k][t];
          const double trial      = scaled_r_t - u[k][t];
          const double projected =
            std::max(-half_width, std::min(half_width, trial));
          result.friction =
            std::max(result.friction, std::abs(scaled_r_t - projected));
          result.max_cone_violation =
            std::max(result.max_cone_violation,
                     scale * (std::abs(r[k][t]) - mu[k] * r[k][n]));
        }
      return result;
    }

    // Below this estimate of the reciprocal condition number (LAPACK's
    // dgecon, 1-norm) the closed nodes' law is taken as redundant. Low:
    // where LU still answers (two passes' near-redundant constraints), its
    // answer is the law's; on GetFEM's multi-body demo with two passes the
    // run stopped at step 147, 153 and 178 with 1e-6, 1e-10 and 1e-13
    // (doc/contact.md).
    constexpr double redundant_below_rcond = 1e-13;

    // Solves the dense system A x = b (A column major, m x m) in place;
    // false if LAPACK fails or the answer is not finite. By LU with partial
    // pivoting, unless A is singular or nearly so: then some closed
    // constraints are one constraint twice (a node on a node, each the
    // other's counterpart: two passes of a contact pair), only the sum of
    // their reactions is fixed, and LU's answer would be two huge reactions
    // of opposite signs, which no status check accepts. The answer of least
    // norm (LAPACK's dgelsy: QR with column pivoting, the directions below
    // redundant_below_rcond left out) shares such a sum equally; where b is
    // not in A's range its residual is what the caller's law check sees.
    bool
    solve_dense(std::vector<double> &A,
                std::vector<double> &b,
                const std::size_t    m)
    {
      const int                 size = m, one = 1;
      int                       info    = 0;
      const std::vector<double> A_given = A;
      std::vector<int>          pivots(m);
      std::vector<double>       work(4 * m);
      std::vector<int>          iwork(m);
      const double              a_norm =
        dlange_("1", &size, &size, A.data(), &size, work.data());
      dgetrf_(&size, &size, A.data(), &size, pivots.data(), &info);
      double rcond = 0.;
      if (info == 0)
        dgecon_("1",
                &size,
                A.data(),
                &size,
                &a_norm,
                &rcond,
                work.data(),
                iwork.data(),
                &info);
      if (info == 0 && rcond >= redundant_below_rcond)
        dgetrs_("N",
                &size,
                &one,
                A.data(),
                &size,
                pivots.data(),
                b.data(),
                &size,
                &info);
      else
        {
          A = A_given;
          std::vector<int> column_pivots(m, 0);
          int              rank = 0;
          // (called twice: first for the size of its work array)
          const auto least_norm = [&](double *work_array, const int lwork) {
            dgelsy_(&size,
                    &size,
                    &one,
                    A.data(),
                    &size,
                    b.data(),
                    &size,
                    column_pivots.data(),
                    &redundant_below_rcond,
                    &rank,
                    work_array,
                    &lwork,
                    &info);
          };
          double best_lwork = 0.;
          least_norm(&best_lwork, -1);
          work.resize(std::max(1, int(best_lwork)));
          least_norm(work.data(), work.size());
        }
      if (info != 0)
        return false;
      for (std::size_t c = 0; c < m; ++c)
        if (!std::isfinite(b[c]))
          return false;
      return true;
    }

    // Active-set polish: with the statuses of the current iterate fixed
    // (BiPotentialSolver::solve_for_statuses, the slip sign taken from the
    // iterate's r_t), the contact law is a linear system in the closed
    // nodes' reactions. Its solution is the exact answer if the statuses
    // were right, which the caller checks with the residuals of the law.
    // Returns false if nothing is closed (solve_dense: a redundant law
    // gets its answer of least norm).
    bool
    polish(const ComplianceMatrix     &W,
           const std::vector<Vector2> &u_free,
           const std::vector<double>  &mu,
           const std::vector<Vector2> &r,
           std::vector<Vector2>       &polished)
    {
      std::vector<NodeStatus> status(r.size());
      std::vector<double>     slip_sign(r.size(), 0.);
      for (std::size_t k = 0; k < r.size(); ++k)
        {
          status[k] = BiPotentialSolver::classify(r[k], mu[k]);
          if (status[k] == NodeStatus::slip && mu[k] > 0.)
            slip_sign[k] = r[k][t] >= 0. ? 1. : -1.;
        }
      return BiPotentialSolver::solve_for_statuses(
        W, u_free, mu, status, slip_sign, polished);
    }

    double
    natural_scale(const ComplianceMatrix &W)
    {
      double scale = 0.;
      for (unsigned int k = 0; k < W.n_nodes(); ++k)
        scale = std::max(scale, W.normal_compliance(k));
      return scale;
    }

    // Largest eigenvalue of the symmetric part of a 2x2 block.
    double
    largest_eigenvalue(const ComplianceMatrix::Block &w)
    {
      const double mean      = 0.5 * (w[t][t] + w[n][n]);
      const double half_diff = 0.5 * (w[t][t] - w[n][n]);
      const double off_diag  = 0.5 * (w[t][n] + w[n][t]);
      return mean + std::sqrt(half_diff * half_diff + off_diag * off_diag);
    }

    std::string
    invalid_input_message(const BiPotentialSolver::Settings &settings,
                          const ComplianceMatrix            &W,
                          const std::vector<Vector2>        &u_free,
                          const std::vector<double>         &mu,
                          const std::vector<Vector2>        &r)
    {
      const std::size_t  n_nodes = W.n_nodes();
      std::ostringstream problem;
      if (!(settings.beta > 0. && settings.beta < 2.))
        problem << "beta = " << settings.beta << " is not in (0, 2). ";
      if (!(settings.change_tolerance >= 0.) ||
          !(settings.residual_tolerance >= 0.) ||
          !(settings.reaction_floor >= 0.) || !(settings.length_floor >= 0.) ||
          !std::isfinite(settings.force_to_length_scale) ||
          !std::isfinite(settings.reaction_floor) ||
          !std::isfinite(settings.length_floor))
        problem << "tolerances and floors must be finite and >= 0. ";
      if (settings.max_sweeps == 0)
        problem << "max_sweeps must be at least 1. ";
      if (u_free.size() != n_nodes || mu.size() != n_nodes ||
          (!r.empty() && r.size() != n_nodes))
        {
          problem << "size mismatch: W has " << n_nodes << " nodes, u_free "
                  << u_free.size() << ", mu " << mu.size() << ", r " << r.size()
                  << ". ";
          return problem.str();
        }
      for (std::size_t k = 0; k < n_nodes; ++k)
        {
          if (!is_finite(u_free[k]))
            {
              problem << "u_free of node " << k << " is not finite. ";
              break;
            }
          if (!(mu[k] >= 0.) || !std::isfinite(mu[k]))
            {
              problem << "mu of node " << k << " is " << mu[k]
                      << " (must be finite and >= 0). ";
              break;
            }
          if (!r.empty() && !is_finite(r[k]))
            {
              problem << "the starting reaction of node " << k
                      << " is not finite. ";
              break;
            }
        }
      if (!W.all_entries_finite())
        problem << "W has non-finite entries. ";
      else
        for (unsigned int k = 0; k < n_nodes; ++k)
          // A frictionless node never uses its tangential compliance (with
          // the contact tangent it may be negative: a node on a locally
          // convex master is in unstable tangential equilibrium).
          if (mu[k] > 0. && W.diagonal_block(k)[t][t] < 0.)
            {
              problem << "W_kk[t][t] < 0 at node " << k
                      << ": W is not positive semi-definite. ";
              break;
            }
      return problem.str();
    }

    // The nodes whose normal compliance is zero, negative, or round-off
    // below the largest one: a gap that no reaction can change (both
    // bodies rigid at the node), which no iteration can solve.
    std::vector<unsigned int>
    singular_nodes_of(const ComplianceMatrix &W,
                      const double            max_normal_compliance)
    {
      std::vector<unsigned int> singular;
      for (unsigned int k = 0; k < W.n_nodes(); ++k)
        {
          const double w_nn = W.normal_compliance(k);
          if (!(w_nn > singular_fraction * max_normal_compliance) || w_nn <= 0.)
            singular.push_back(k);
        }
      return singular;
    }

    std::string
    singular_nodes_message(const std::vector<unsigned int> &singular)
    {
      std::ostringstream message;
      message << "BiPotentialSolver: " << singular.size()
              << " node(s) with W_kk[n][n] <= 0 (or below 1e-14 of the "
                 "largest), i.e. a gap that no reaction can change (both "
                 "bodies rigid at the node?): ";
      for (std::size_t i = 0; i < singular.size() && i < 10; ++i)
        message << singular[i] << ' ';
      if (singular.size() > 10)
        message << "...";
      return message.str();
    }

    // rho_k of each node (BiPotentialSolver::RhoChoice): beta over the
    // normal compliance, or over the largest eigenvalue of W_kk for a
    // node with friction if the settings ask for the safe choice.
    std::vector<double>
    step_lengths(const BiPotentialSolver::Settings &settings,
                 const ComplianceMatrix            &W,
                 const std::vector<double>         &mu)
    {
      std::vector<double> rho(W.n_nodes());
      for (unsigned int k = 0; k < W.n_nodes(); ++k)
        {
          const ComplianceMatrix::Block w_kk = W.diagonal_block(k);
          const bool                    use_largest =
            settings.rho_choice ==
              BiPotentialSolver::RhoChoice::largest_diagonal_compliance &&
            mu[k] > 0.;
          rho[k] = settings.beta /
                   (use_largest ? largest_eigenvalue(w_kk) : w_kk[n][n]);
        }
      return rho;
    }

    // The new reaction of one node in a Gauss-Seidel sweep, from its
    // reaction r_k and displacement u_k with the latest reactions of all
    // the others.
    Vector2
    gauss_seidel_update(const Vector2 &r_k,
                        const Vector2 &u_k,
                        const double   rho_k,
                        const double   mu_k,
                        const double   cap_k)
    {
      if (mu_k == 0.)
        // Frictionless: projected SOR on the normal LCP (box-constrained
        // below a cap).
        return {{0., std::min(cap_k, std::max(0., r_k[n] - rho_k * u_k[n]))}};
      // Bi-potential step: the normal argument is the modified gap
      // g + mu |u_t|, which couples Signorini and Coulomb so that a single
      // projection on K_mu enforces both.
      const Vector2 trial = {
        {r_k[t] - rho_k * u_k[t],
         r_k[n] - rho_k * (u_k[n] + mu_k * std::abs(u_k[t]))}};
      return BiPotentialSolver::project_on_capped_cone(trial, mu_k, cap_k);
    }

    // When to polish. Gauss-Seidel finds the statuses (open, stick, slip)
    // long before the values; once they have not changed for a few sweeps,
    // the law is linear and can be solved directly. The watch counts the
    // sweeps over which the statuses stayed the same, and says when that
    // count first reaches 5, then 20, 80, ... (a polish that failed is not
    // repeated at every sweep while nothing changes).
    class StatusWatch
    {
    public:
      explicit StatusWatch(const unsigned int n_nodes)
        : statuses(n_nodes)
      {}

      // Called once per sweep with its reactions: true if the statuses have
      // now been unchanged for the number of sweeps after which to polish.
      bool
      settled(const std::vector<Vector2> &r, const std::vector<double> &mu)
      {
        for (unsigned int k = 0; k < statuses.size(); ++k)
          statuses[k] = BiPotentialSolver::classify(r[k], mu[k]);
        if (statuses == previous_statuses)
          ++stable_sweeps;
        else
          {
            stable_sweeps     = 0;
            polish_after      = first_polish_after_stable_sweeps;
            previous_statuses = statuses;
          }
        const bool result = stable_sweeps == polish_after;
        if (result)
          polish_after *= 4;
        return result;
      }

    private:
      std::vector<NodeStatus> statuses, previous_statuses;
      unsigned int            stable_sweeps = 0;
      unsigned int            polish_after  = first_polish_after_stable_sweeps;
    };

    // The iterate of BiPotentialSolver::solve(): the reactions r and the
    // displacements u = u_free + W r, with the problem they belong to. u
    // is kept up to date incrementally as r changes (one column of W per
    // changed node) and recomputed from scratch where it must be exact;
    // u_is_exact says whether it has been since r last changed.
    class GaussSeidelIterate
    {
    public:
      GaussSeidelIterate(const BiPotentialSolver::Settings &settings,
                         const ComplianceMatrix            &W,
                         const std::vector<Vector2>        &u_free,
                         const std::vector<double>         &mu,
                         const std::vector<double>         &rho,
                         const std::vector<double>         &cap,
                         const double                       scale,
                         const double                       free_length,
                         std::vector<Vector2>              &r)
        : settings(settings)
        , W(W)
        , u_free(u_free)
        , mu(mu)
        , rho(rho)
        , cap(cap)
        , scale(scale)
        , free_length(free_length)
        , r(r)
      {
        compute_displacement(W, u_free, r, u);
      }

      // One sweep over the nodes in order, each reaction replaced with the
      // latest ones of all other nodes; returns the largest change of a
      // node's reaction. A node whose reaction does not change costs O(1).
      double
      sweep();

      // u from scratch, so that the round-off of the incremental updates
      // cannot pile up.
      void
      refresh();

      // The bound on the residuals for reactions as large as max_reaction.
      double
      residual_bound(const double max_reaction) const;

      // Whether the iterate satisfies the law to the bound (u exact).
      bool
      satisfies_law(const double bound) const;

      // The polish: the linear law of the iterate's statuses solved
      // directly. Gauss-Seidel finds the statuses long before the values,
      // the more so when W is ill-conditioned (a stiff slave on a soft
      // master: the reactions of neighbouring nodes trade off along an
      // almost null direction of W). If its answer satisfies the law, it
      // becomes the iterate, `bound` is set and the result is true;
      // otherwise it may give Gauss-Seidel a new start (restart_from()).
      bool
      polish_solves(double &bound);

      // u of the returned reactions, exact.
      std::vector<Vector2> &
      exact_displacement();

      // After a divergence: r is set back by the caller, so u no longer
      // belongs to it.
      void
      reactions_replaced();

    private:
      // A polish that is not the answer yet (some statuses were wrong) has
      // the right values on the nodes whose statuses were. Projected on the
      // admissible cones it is a new starting point for Gauss-Seidel: taken
      // if it satisfies the law better than the iterate, a bounded number
      // of times, so that a W that is not positive semi-definite still
      // shows its divergence.
      void
      restart_from(const std::vector<Vector2> &candidate);

      // How far (u, r) is from the law: the sum of its two residuals.
      double
      merit(const std::vector<Vector2> &uu,
            const std::vector<Vector2> &rr) const;

      const BiPotentialSolver::Settings &settings;
      const ComplianceMatrix            &W;
      const std::vector<Vector2>        &u_free;
      const std::vector<double>         &mu;
      const std::vector<double>         &rho;
      const std::vector<double>         &cap;
      const double                       scale;
      const double                       free_length;
      std::vector<Vector2>              &r;
      std::vector<Vector2>               u;
      bool                               u_is_exact = true;
      unsigned int                       restarts   = 0;
    };

    double
    GaussSeidelIterate::sweep()
    {
      double max_change = 0.;
      for (unsigned int k = 0; k < W.n_nodes(); ++k)
        {
          const Vector2 new_r =
            gauss_seidel_update(r[k], u[k], rho[k], mu[k], cap_of(cap, k));
          const Vector2 delta = {{new_r[t] - r[k][t], new_r[n] - r[k][n]}};
          if (delta[t] != 0. || delta[n] != 0.)
            {
              r[k] = new_r;
              W.add_column_product(k, delta, u);
              u_is_exact = false;
              max_change = std::max(max_change, norm(delta));
            }
        }
      return max_change;
    }

    void
    GaussSeidelIterate::refresh()
    {
      compute_displacement(W, u_free, r, u);
      u_is_exact = true;
    }

    double
    GaussSeidelIterate::residual_bound(const double max_reaction) const
    {
      return settings.residual_tolerance *
             std::max(free_length, scale * max_reaction);
    }

    bool
    GaussSeidelIterate::satisfies_law(const double bound) const
    {
      const Residuals residuals = residuals_of(u, r, mu, scale, cap);
      return residuals.complementarity <= bound && residuals.friction <= bound;
    }

    bool
    GaussSeidelIterate::polish_solves(double &bound)
    {
      // (the statuses' linear law has no yielding node: with one at its
      // cap, Gauss-Seidel alone)
      for (unsigned int k = 0; k < r.size(); ++k)
        if (r[k][n] >= cap_of(cap, k) * (1. - 1e-12))
          return false;
      std::vector<Vector2> candidate, candidate_u;
      if (!polish(W, u_free, mu, r, candidate))
        return false;
      compute_displacement(W, u_free, candidate, candidate_u);
      const double    candidate_bound = residual_bound(max_norm(candidate));
      const Residuals residuals =
        residuals_of(candidate_u, candidate, mu, scale, cap);
      if (residuals.complementarity <= candidate_bound &&
          residuals.friction <= candidate_bound &&
          residuals.max_cone_violation <= candidate_bound)
        {
          r          = std::move(candidate);
          u          = std::move(candidate_u);
          u_is_exact = true;
          bound      = candidate_bound;
          return true;
        }
      restart_from(candidate);
      return false;
    }

    std::vector<Vector2> &
    GaussSeidelIterate::exact_displacement()
    {
      if (!u_is_exact)
        refresh();
      return u;
    }

    void
    GaussSeidelIterate::reactions_replaced()
    {
      u_is_exact = false;
    }

    void
    GaussSeidelIterate::restart_from(const std::vector<Vector2> &candidate)
    {
      if (restarts >= max_polish_restarts)
        return;
      std::vector<Vector2> projected(W.n_nodes()), projected_u;
      for (unsigned int k = 0; k < W.n_nodes(); ++k)
        projected[k] =
          BiPotentialSolver::project_on_capped_cone(candidate[k],
                                                    mu[k],
                                                    cap_of(cap, k));
      compute_displacement(W, u_free, projected, projected_u);
      if (!u_is_exact)
        refresh();
      if (merit(projected_u, projected) < merit(u, r))
        {
          r = std::move(projected);
          u = std::move(projected_u);
          ++restarts;
        }
    }

    double
    GaussSeidelIterate::merit(const std::vector<Vector2> &uu,
                              const std::vector<Vector2> &rr) const
    {
      const Residuals e = residuals_of(uu, rr, mu, scale, cap);
      return e.complementarity + e.friction;
    }

    // The sentence for the log on the outcome of a solve, from its result
    // (residuals included). Not converged with friction, it names the usual
    // culprit: a tangential step that cannot contract (see
    // RhoChoice::normal_compliance).
    std::string
    outcome_message(const BiPotentialSolver::Result &result,
                    const ComplianceMatrix          &W,
                    const std::vector<double>       &mu,
                    const std::vector<double>       &rho)
    {
      std::ostringstream message;
      if (result.outcome == Outcome::diverged)
        message << "BiPotentialSolver: the iteration diverged at sweep "
                << result.sweeps
                << "; the starting reactions are returned. Is W positive "
                   "semi-definite? With friction, try a smaller beta or "
                   "RhoChoice::largest_diagonal_compliance.";
      if (result.outcome == Outcome::converged)
        message << "BiPotentialSolver: converged in " << result.sweeps
                << " sweeps" << (result.polished ? " (active-set polish)" : "");
      else if (result.outcome == Outcome::max_sweeps_reached)
        {
          message << "BiPotentialSolver: not converged after " << result.sweeps
                  << " sweeps (last change " << result.last_reaction_change
                  << ", bound " << result.reaction_change_bound << ")";
          unsigned int n_overshooting = 0;
          for (unsigned int k = 0; k < W.n_nodes(); ++k)
            if (mu[k] > 0. && rho[k] * W.diagonal_block(k)[t][t] >= 2.)
              ++n_overshooting;
          if (n_overshooting > 0)
            message << "; " << n_overshooting
                    << " friction node(s) have rho W_tt >= 2, so their stick "
                       "iteration cannot contract: use a smaller beta or "
                       "RhoChoice::largest_diagonal_compliance";
        }
      if (result.outcome != Outcome::diverged)
        message << "; complementarity " << result.residuals.complementarity
                << ", friction " << result.residuals.friction << " (bound "
                << result.residual_bound << ")";
      return message.str();
    }
  } // namespace

  BiPotentialSolver::BiPotentialSolver()
    : settings()
  {}

  BiPotentialSolver::BiPotentialSolver(const Settings &settings)
    : settings(settings)
  {}

  const BiPotentialSolver::Settings &
  BiPotentialSolver::get_settings() const
  {
    return settings;
  }

  Vector2
  BiPotentialSolver::project_on_coulomb_cone(const Vector2 &x, const double mu)
  {
    const double abs_t = std::abs(x[t]);
    // The polar cone {y : y . z <= 0 for all z in K} = {x_n <= -mu |x_t|}
    // projects to the apex. Tested first so that mu = 0 (K is the half-line
    // r_t = 0, r_n >= 0) sends x_n <= 0 to zero.
    if (x[n] <= -mu * abs_t)
      return {{0., 0.}};
    if (abs_t <= mu * x[n])
      return x;
    // Orthogonal projection on the edge spanned by (sign(x_t) mu, 1):
    // r_n = (x . e) / |e|^2 with e = (sign(x_t) mu, 1). Positive here
    // because x is not in the polar cone.
    const double r_n = (x[n] + mu * abs_t) / (1. + mu * mu);
    return {{std::copysign(mu * r_n, x[t]), r_n}};
  }

  Vector2
  BiPotentialSolver::project_on_capped_cone(const Vector2 &x,
                                            const double   mu,
                                            const double   cap)
  {
    // The cone's projection if it is under the cap; otherwise the nearest
    // point of the cap's segment {r_n = cap, |r_t| <= mu cap}, which is the
    // nearest point of the truncated cone then.
    const Vector2 on_cone = project_on_coulomb_cone(x, mu);
    if (!(on_cone[n] > cap))
      return on_cone;
    return {{std::max(-mu * cap, std::min(mu * cap, x[t])), cap}};
  }

  BiPotentialSolver::NodeStatus
  BiPotentialSolver::classify(const Vector2 &r, const double mu)
  {
    if (!(r[n] > 0.))
      return NodeStatus::open;
    // The projection puts a slipping node exactly on the edge; the relative
    // margin only absorbs the rounding of mu r_n.
    if (mu == 0. || std::abs(r[t]) >= mu * r[n] * (1. - 1e-12))
      return NodeStatus::slip;
    return NodeStatus::stick;
  }

  bool
  BiPotentialSolver::solve_for_statuses(const ComplianceMatrix        &W,
                                        const std::vector<Vector2>    &u_free,
                                        const std::vector<double>     &mu,
                                        const std::vector<NodeStatus> &status,
                                        const std::vector<double> &slip_sign,
                                        std::vector<Vector2>      &r)
  {
    const unsigned int n_nodes = W.n_nodes();
    // Unknowns: r_n of every closed node, and r_t of every stick node.
    std::vector<int> normal_unknown(n_nodes, -1),
      tangential_unknown(n_nodes, -1);
    std::size_t m = 0;
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        if (status[k] == NodeStatus::open)
          continue;
        normal_unknown[k] = m++;
        if (status[k] == NodeStatus::stick && mu[k] > 0.)
          tangential_unknown[k] = m++;
      }
    if (m == 0)
      return false;
    // Row of each equation: g_k = 0 in the row of r_n(k), u_t,k = 0 in
    // the row of r_t(k); a slipping node's r_t is slip_sign mu r_n.
    std::vector<double> A(m * m, 0.), b(m, 0.);
    for (unsigned int k = 0; k < n_nodes; ++k)
      for (const unsigned int component : {n, t})
        {
          const int row =
            component == n ? normal_unknown[k] : tangential_unknown[k];
          if (row < 0)
            continue;
          b[row] = -u_free[k][component];
          for (unsigned int l = 0; l < n_nodes; ++l)
            {
              if (normal_unknown[l] < 0 || !W.block_is_stored(k, l))
                continue;
              const ComplianceMatrix::Block w = W.block(k, l);
              const double                  sliding =
                tangential_unknown[l] >= 0 ? 0. : slip_sign[l];
              A[normal_unknown[l] * m + row] +=
                w[component][n] + sliding * mu[l] * w[component][t];
              if (tangential_unknown[l] >= 0)
                A[tangential_unknown[l] * m + row] += w[component][t];
            }
        }
    if (!solve_dense(A, b, m))
      return false;
    r.assign(n_nodes, Vector2{{0., 0.}});
    for (unsigned int k = 0; k < n_nodes; ++k)
      if (normal_unknown[k] >= 0)
        {
          r[k][n] = b[normal_unknown[k]];
          r[k][t] = tangential_unknown[k] >= 0 ? b[tangential_unknown[k]] :
                                                 slip_sign[k] * mu[k] * r[k][n];
        }
    return true;
  }



  BiPotentialSolver::Result
  BiPotentialSolver::solve(const ComplianceMatrix     &W,
                           const std::vector<Vector2> &u_free,
                           const std::vector<double>  &mu,
                           std::vector<Vector2>       &r) const
  {
    return solve(W, u_free, mu, r, {});
  }



  BiPotentialSolver::Result
  BiPotentialSolver::solve(const ComplianceMatrix     &W,
                           const std::vector<Vector2> &u_free,
                           const std::vector<double>  &mu,
                           std::vector<Vector2>       &r,
                           const std::vector<double>  &cap) const
  {
    Result             result;
    const unsigned int n_nodes = W.n_nodes();

    // 1. Refuse what cannot be solved, before touching r.
    std::string problem = invalid_input_message(settings, W, u_free, mu, r);
    if (problem.empty() && !cap.empty())
      {
        if (cap.size() != n_nodes)
          problem = "size mismatch: W has " + std::to_string(n_nodes) +
                    " nodes, the caps " + std::to_string(cap.size());
        for (std::size_t k = 0; k < cap.size() && problem.empty(); ++k)
          if (!(cap[k] > 0.))
            problem = "the cap of node " + std::to_string(k) +
                      " is not > 0 (infinity: none)";
      }
    if (!problem.empty())
      {
        result.outcome = Outcome::invalid_input;
        result.message = "BiPotentialSolver: invalid input: " + problem;
        return result;
      }
    const double max_normal_compliance = natural_scale(W);
    result.singular_nodes = singular_nodes_of(W, max_normal_compliance);
    if (!result.singular_nodes.empty())
      {
        result.outcome = Outcome::singular_node;
        result.message = singular_nodes_message(result.singular_nodes);
        return result;
      }

    // 2. Scales and step lengths.
    const double scale            = settings.force_to_length_scale > 0. ?
                                      settings.force_to_length_scale :
                                      max_normal_compliance;
    result.force_to_length_scale  = scale;
    const std::vector<double> rho = step_lengths(settings, W, mu);

    const std::vector<Vector2> initial_r =
      r.empty() ? std::vector<Vector2>(n_nodes, Vector2{{0., 0.}}) : r;
    r = initial_r;

    const double free_length =
      std::max(max_norm(u_free), settings.length_floor);
    // The forces this problem can produce: those that close the free gaps,
    // or those the caller already had. Used only to detect a blow-up.
    const double force_reference = std::max(
      {free_length / scale, settings.reaction_floor, max_norm(initial_r)});

    // 3. Gauss-Seidel sweeps, until the change of r is small and the law
    // holds; once the statuses have settled, or every polish_period sweeps,
    // the law of the iterate's statuses is solved directly (the polish).
    GaussSeidelIterate iterate(
      settings, W, u_free, mu, rho, cap, scale, free_length, r);
    StatusWatch watch(n_nodes);
    result.outcome = Outcome::max_sweeps_reached;
    for (unsigned int sweep = 1; sweep <= settings.max_sweeps; ++sweep)
      {
        result.sweeps                 = sweep;
        const double max_change       = iterate.sweep();
        const bool   statuses_settled = watch.settled(r, mu);

        const double max_reaction   = max_norm(r);
        result.last_reaction_change = max_change;
        if (!std::isfinite(max_change) || !std::isfinite(max_reaction) ||
            max_reaction > divergence_factor * force_reference)
          {
            result.outcome = Outcome::diverged;
            break;
          }

        result.reaction_change_bound =
          settings.change_tolerance *
          std::max(max_reaction, settings.reaction_floor);
        const bool small_change = max_change <= result.reaction_change_bound;
        if (small_change || sweep % refresh_period == 0)
          iterate.refresh();
        if (small_change)
          {
            result.residual_bound = iterate.residual_bound(max_reaction);
            if (iterate.satisfies_law(result.residual_bound))
              {
                result.outcome = Outcome::converged;
                break;
              }
          }
        else if (settings.polish_period > 0 &&
                 (statuses_settled || sweep % settings.polish_period == 0 ||
                  sweep == settings.max_sweeps))
          {
            double bound = 0.;
            if (iterate.polish_solves(bound))
              {
                result.residual_bound = bound;
                result.polished       = true;
                result.outcome        = Outcome::converged;
                break;
              }
          }
      }

    // 4. Report on exactly what is returned.
    if (result.outcome == Outcome::diverged)
      {
        r = initial_r;
        iterate.reactions_replaced();
      }
    std::vector<Vector2> &u = iterate.exact_displacement();
    result.residuals        = residuals_of(u, r, mu, scale, cap);
    if (result.residual_bound == 0.)
      result.residual_bound = iterate.residual_bound(max_norm(r));
    result.converged    = result.outcome == Outcome::converged;
    result.displacement = std::move(u);
    result.status.resize(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      result.status[k] = classify(r[k], mu[k]);
    result.message = outcome_message(result, W, mu, rho);
    return result;
  }



  BiPotentialSolver::Residuals
  compute_contact_residuals(const ComplianceMatrix     &W,
                            const std::vector<Vector2> &u_free,
                            const std::vector<double>  &mu,
                            const std::vector<Vector2> &r,
                            const double                force_to_length_scale,
                            std::vector<Vector2>       *displacement,
                            const std::vector<double>  &cap)
  {
    std::vector<Vector2> u;
    compute_displacement(W, u_free, r, u);
    const double scale =
      force_to_length_scale > 0. ? force_to_length_scale : natural_scale(W);
    const Residuals result = residuals_of(u, r, mu, scale, cap);
    if (displacement != nullptr)
      *displacement = std::move(u);
    return result;
  }
} // namespace glissade
