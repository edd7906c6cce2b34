// The contact law on the condensed system by a primal-dual active-set
// iteration: BiPotentialSolver::solve_by_active_set (see its declaration).

#include <glissade/base/debug_log.h>
#include <glissade/contact/local_solvers/bipotential_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace glissade
{
  BiPotentialSolver::Result
  BiPotentialSolver::solve_by_active_set(const ComplianceMatrix     &W,
                                         const std::vector<Vector2> &u_free,
                                         const std::vector<double>  &mu,
                                         std::vector<Vector2>       &r) const
  {
    constexpr unsigned int t       = ComplianceMatrix::tangential;
    constexpr unsigned int n       = ComplianceMatrix::normal;
    const unsigned int     n_nodes = W.n_nodes();
    Result                 result;
    if (u_free.size() != n_nodes || mu.size() != n_nodes ||
        (!r.empty() && r.size() != n_nodes) || !W.all_entries_finite())
      {
        result.outcome = Outcome::invalid_input;
        result.message = "BiPotentialSolver (active set): invalid input";
        return result;
      }
    const std::vector<Vector2> start =
      r.empty() ? std::vector<Vector2>(n_nodes, Vector2{{0., 0.}}) : r;

    // The length scale of the law's residuals and the rho of each node.
    double scale = settings.force_to_length_scale;
    if (!(scale > 0.))
      for (unsigned int k = 0; k < n_nodes; ++k)
        scale = std::max(scale, std::abs(W.normal_compliance(k)));
    if (!(scale > 0.))
      {
        result.outcome = Outcome::singular_node;
        result.message = "BiPotentialSolver (active set): W is zero";
        return result;
      }
    std::vector<double> rho(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        const double w = std::abs(W.normal_compliance(k));
        rho[k]         = 1. / (w > 1e-14 * scale ? w : scale);
      }
    double free_length = settings.length_floor;
    for (const auto &u : u_free)
      free_length = std::max(free_length, std::hypot(u[0], u[1]));

    // The statuses of the start, then those that each solution implies.
    std::vector<NodeStatus> status(n_nodes);
    std::vector<double>     slip_sign(n_nodes, 0.);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        status[k] = classify(start[k], mu[k]);
        if (status[k] == NodeStatus::slip && mu[k] > 0.)
          slip_sign[k] = start[k][t] >= 0. ? 1. : -1.;
      }
    const unsigned int   max_updates = std::min(settings.max_sweeps, 100u);
    std::vector<Vector2> u;
    result.outcome = Outcome::max_sweeps_reached;
    for (unsigned int update = 1; update <= max_updates; ++update)
      {
        result.sweeps = update;
        if (!solve_for_statuses(W, u_free, mu, status, slip_sign, r))
          r.assign(n_nodes, Vector2{{0., 0.}});
        result.residuals =
          compute_contact_residuals(W, u_free, mu, r, scale, &u);

        // x = r - rho (u_t, g + mu |u_t|), projected on the cone: its
        // status is the one the law gives the node (the semismooth Newton
        // step's active set).
        bool changed = false;
        for (unsigned int k = 0; k < n_nodes; ++k)
          {
            const Vector2 x = {
              {r[k][t] - rho[k] * u[k][t],
               r[k][n] - rho[k] * (u[k][n] + mu[k] * std::abs(u[k][t]))}};
            const Vector2    p    = project_on_coulomb_cone(x, mu[k]);
            const NodeStatus s    = classify(p, mu[k]);
            const double     sign = s == NodeStatus::slip && mu[k] > 0. ?
                                      (p[t] >= 0. ? 1. : -1.) :
                                      0.;
            if (s != status[k] || sign != slip_sign[k])
              {
                changed = true;
                if (debug_log::at(3))
                  debug_log::stream()
                    << "        update " << update << " node " << k << ": "
                    << int(status[k]) << " " << slip_sign[k] << " -> " << int(s)
                    << " " << sign << "  r (" << r[k][t] << ", " << r[k][n]
                    << ") u (" << u[k][t] << ", " << u[k][n] << ")"
                    << std::endl;
              }
            status[k]    = s;
            slip_sign[k] = sign;
          }
        double largest_r = 0.;
        for (const auto &rk : r)
          largest_r = std::max(largest_r, std::hypot(rk[0], rk[1]));
        const double bound = settings.residual_tolerance *
                             std::max(free_length, scale * largest_r);
        result.residual_bound = bound;
        if (!changed && result.residuals.complementarity <= bound &&
            result.residuals.friction <= bound &&
            result.residuals.max_cone_violation <= bound)
          {
            result.outcome = Outcome::converged;
            break;
          }
      }

    result.converged             = result.outcome == Outcome::converged;
    result.polished              = true;
    result.force_to_length_scale = scale;
    result.displacement          = u;
    result.status.resize(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      result.status[k] = classify(r[k], mu[k]);
    if (!result.converged)
      {
        std::ostringstream message;
        message << "BiPotentialSolver (active set): the statuses did not "
                   "settle in "
                << result.sweeps << " updates; complementarity "
                << result.residuals.complementarity << ", friction "
                << result.residuals.friction << " (bound "
                << result.residual_bound << ")";
        result.message = message.str();
        r              = start;
      }
    return result;
  }
} // namespace glissade
