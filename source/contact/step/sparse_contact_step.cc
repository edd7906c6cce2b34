#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/input_error.h>
#include <glissade/base/processes.h>
#include <glissade/base/timing_sections.h>
#include <glissade/body/body.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/contact/step/sparse_contact_step.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int tangential = 0, normal = 1;

    // Active-set passes at most per Newton correction: the statuses of the
    // last correction are the start, and a pass that changes none ends it.
    constexpr unsigned int max_passes = 50;

    // The stiffness c_k of node k's status tests, as a fraction of the
    // inverse of its normal compliance estimated from the diagonals
    // (solve()): a node's own stiffness through the bodies is well below
    // that estimate. Measured: 0.01 and 0.1 give the condensed method's
    // Newton iterations on the walkthrough's roller, the pad on a strip and
    // case 3 with mu = 0.3; 1 and 10 (then of the bodies' mean diagonal)
    // made the roller's statuses cycle (3 and 17 cut-backs).
    constexpr double trial_stiffness = 0.1;

    // The slip (row 2k) or gap (row 2k + 1) of a node after the step:
    // its value now plus the row applied to the increments.
    double
    value_after_step(const ActiveNodes                         &nodes,
                     const unsigned int                         row,
                     const std::vector<dealii::Vector<double>> &increments)
    {
      const PairVector &v      = nodes.rows[row];
      double            result = nodes.initial[row / 2][row % 2];
      for (const auto &e : *v.coefficients)
        {
          const unsigned int b = v.bodies[e.body];
          if (b != dealii::numbers::invalid_unsigned_int)
            result += e.value * increments[b](e.dof);
        }
      return result;
    }

    void
    log_sparse_pass(const unsigned int                                pass,
                    const std::vector<BiPotentialSolver::NodeStatus> &status,
                    const bool                                        changed)
    {
      unsigned int counts[3] = {0, 0, 0};
      for (const BiPotentialSolver::NodeStatus st : status)
        ++counts[static_cast<int>(st)];
      debug_log::stream() << "      sparse pass " << pass << ": open "
                          << counts[0] << " stick " << counts[1] << " slip "
                          << counts[2] << (changed ? " (changed)" : "")
                          << std::endl;
    }
  } // namespace



  SparseContactStep::SparseContactStep(const ContactStepContext &context)
    : bodies(context.bodies)
    , in_contact(context.bodies_in_contact)
    , timer(context.timer)
    , offset(bodies.size(), numbers::invalid_unsigned_int)
    , inhomogeneity(bodies.size())
  {
    // A body that only contact holds has a singular system whenever
    // its nodes open or slip in an active-set pass; the condensed
    // method holds it through springs it takes out again exactly
    // (theory.md, section 4.6), which the sparse system has no room
    // for.
    for (const auto &body : bodies)
      if (!body->system().free_rigid_motions().empty())
        throw InputError(
          context.source + ": Contact solver/Method",
          "the sparse method needs every body held by its own supports, "
          "and contact alone holds body '" +
            body->name() + "' (" +
            body->system().free_rigid_motions()[0].describe(body->size()) +
            "): use Method = condensed, or support the body");
    lu.use_unsymmetric_ordering();
    for (const unsigned int b : in_contact)
      {
        offset[b] = n_body_unknowns;
        n_body_unknowns += bodies[b]->n_dofs();
      }
  }



  void
  SparseContactStep::expand(const unsigned int  b,
                            const unsigned int  dof,
                            std::vector<Share> &shares,
                            double             &constant) const
  {
    const AffineConstraints<double> &constraints =
      bodies[b]->system().constraints();
    constant = 0.;
    if (!constraints.is_constrained(dof))
      {
        shares.push_back({offset[b] + dof, 1.});
        return;
      }
    constant = constraints.get_inhomogeneity(dof);
    if (const auto *entries = constraints.get_constraint_entries(dof))
      for (const auto &[j, w] : *entries)
        shares.push_back({offset[b] + static_cast<unsigned int>(j), w});
  }



  void
  SparseContactStep::expand(const PairVector   &v,
                            std::vector<Share> &shares,
                            double             &constant) const
  {
    shares.clear();
    constant = 0.;
    std::vector<Share> one;
    for (const auto &e : *v.coefficients)
      {
        const unsigned int b = v.bodies[e.body];
        // (a rigid obstacle has no dofs)
        if (b == numbers::invalid_unsigned_int || e.value == 0.)
          continue;
        one.clear();
        double c = 0.;
        expand(b, e.dof, one, c);
        for (const Share &s : one)
          shares.push_back({s.column, e.value * s.weight});
        constant += e.value * c;
      }
  }



  void
  SparseContactStep::set_up_pattern(const ActiveNodes &nodes)
  {
    const unsigned int     n_unknowns = n_body_unknowns + 2 * nodes.size();
    DynamicSparsityPattern dsp(n_unknowns, n_unknowns);
    std::vector<types::global_dof_index> columns;
    for (const unsigned int b : in_contact)
      {
        const SparsityPattern &sp =
          bodies[b]->system().tangent_matrix().get_sparsity_pattern();
        for (unsigned int i = 0; i < sp.n_rows(); ++i)
          {
            columns.clear();
            for (auto it = sp.begin(i); it != sp.end(i); ++it)
              columns.push_back(offset[b] + it->column());
            std::sort(columns.begin(), columns.end());
            dsp.add_entries(offset[b] + i,
                            columns.begin(),
                            columns.end(),
                            true);
          }
      }
    std::vector<Share> a, c;
    double             constant = 0.;
    for (const RankOneTerm &term : nodes.terms)
      {
        expand(term.load, a, constant);
        expand(term.row, c, constant);
        for (const Share &i : a)
          for (const Share &j : c)
            dsp.add(i.column, j.column);
      }
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (const unsigned int d : {tangential, normal})
        {
          const unsigned int reaction = n_body_unknowns + 2 * k + d;
          expand(nodes.forces[2 * k + d], a, constant);
          for (const Share &i : a)
            dsp.add(i.column, reaction);
          expand(nodes.rows[2 * k + d], c, constant);
          for (const Share &j : c)
            dsp.add(reaction, j.column);
          for (const unsigned int e : {tangential, normal})
            dsp.add(reaction, n_body_unknowns + 2 * k + e);
        }

    // The couplings change as nodes slide and reactions appear; the
    // pattern only grows (with the last one's entries, unused ones held as
    // zeros), so that after a few corrections it stays the same object and
    // the sparse LU keeps its analysis, the dearest part of a factorisation
    // here.
    const bool same_size = pattern && pattern->n_rows() == n_unknowns;
    if (same_size)
      for (unsigned int i = 0; i < n_unknowns; ++i)
        {
          columns.clear();
          for (auto it = pattern->begin(i); it != pattern->end(i); ++it)
            columns.push_back(it->column());
          std::sort(columns.begin(), columns.end());
          dsp.add_entries(i, columns.begin(), columns.end(), true);
        }
    if (same_size && dsp.n_nonzero_elements() == pattern->n_nonzero_elements())
      return;
    auto fresh = std::make_unique<SparsityPattern>();
    fresh->copy_from(dsp);
    // A new object, so that the factorisation analyses it afresh.
    if (debug_log::at(1))
      debug_log::stream() << "      sparse system: new pattern, "
                          << fresh->n_rows() << " unknowns, "
                          << fresh->n_nonzero_elements() << " entries"
                          << std::endl;
    matrix.reinit(*fresh);
    pattern = std::move(fresh);
    rhs.reinit(n_unknowns);
  }



  void
  SparseContactStep::assemble(const ActiveNodes             &nodes,
                              const std::vector<NodeStatus> &status,
                              const std::vector<double>     &slip_sign)
  {
    matrix = 0.;
    rhs    = 0.;
    // Each body's tangent is the process's share, and MUMPS sums the
    // processes' entries: the contact's own entries are added by one
    // process alone. (The right-hand side is MUMPS's on process 0; every
    // process forms it.)
    const double contact_share = processes::adds_terms_held_once() ? 1. : 0.;
    for (const unsigned int b : in_contact)
      {
        const SparseMatrix<double> &K = bodies[b]->system().tangent_matrix();
        for (unsigned int i = 0; i < K.m(); ++i)
          for (auto it = K.begin(i); it != K.end(i); ++it)
            matrix.add(offset[b] + i, offset[b] + it->column(), it->value());
        const Vector<double> &f = bodies[b]->system().right_hand_side();
        for (unsigned int i = 0; i < f.size(); ++i)
          rhs(offset[b] + i) = f(i);
      }

    // K - U V, and U (V b) to the right-hand side for the rows' constant
    // parts (a prescribed motion of this correction under a term's row).
    std::vector<Share> a, c;
    double             load_constant = 0., row_constant = 0.;
    for (const RankOneTerm &term : nodes.terms)
      {
        expand(term.load, a, load_constant);
        expand(term.row, c, row_constant);
        for (const Share &i : a)
          {
            for (const Share &j : c)
              matrix.add(i.column,
                         j.column,
                         -contact_share * i.weight * j.weight);
            rhs(i.column) += i.weight * row_constant;
          }
      }

    // The reactions, r = alpha x: columns -alpha F; their rows, scaled by
    // alpha so that the system's entries are of one size.
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const unsigned int t_unknown = n_body_unknowns + 2 * k + tangential;
        const unsigned int n_unknown = n_body_unknowns + 2 * k + normal;
        for (const unsigned int d : {tangential, normal})
          {
            expand(nodes.forces[2 * k + d], a, load_constant);
            for (const Share &i : a)
              matrix.add(i.column,
                         n_body_unknowns + 2 * k + d,
                         -contact_share * alpha * i.weight);
          }
        const bool   closed = status[k] != NodeStatus::open;
        const double mu     = nodes.friction[k];
        // The normal row: the linearised gap closed, or r_n = 0.
        if (closed)
          {
            expand(nodes.rows[2 * k + normal], c, row_constant);
            for (const Share &j : c)
              matrix.add(n_unknown, j.column, contact_share * alpha * j.weight);
            rhs(n_unknown) = -alpha * (nodes.initial[k][normal] + row_constant);
          }
        else
          matrix.add(n_unknown, n_unknown, contact_share * alpha);
        // The tangential row: the linearised slip held (stick), friction at
        // Coulomb's bound against the slip (slip), or r_t = 0.
        if (closed && mu > 0. && status[k] == NodeStatus::stick)
          {
            expand(nodes.rows[2 * k + tangential], c, row_constant);
            for (const Share &j : c)
              matrix.add(t_unknown, j.column, contact_share * alpha * j.weight);
            rhs(t_unknown) =
              -alpha * (nodes.initial[k][tangential] + row_constant);
          }
        else if (closed && mu > 0.)
          {
            matrix.add(t_unknown, t_unknown, contact_share * alpha);
            matrix.add(t_unknown,
                       n_unknown,
                       -contact_share * alpha * slip_sign[k] * mu);
          }
        else
          matrix.add(t_unknown, t_unknown, contact_share * alpha);
      }
  }



  bool
  SparseContactStep::solve(const ActiveNodes                   &nodes,
                           std::vector<NodeStatus>             &status,
                           std::vector<Vector2>                &r,
                           std::vector<dealii::Vector<double>> &increments,
                           std::string                         &message)
  {
    const unsigned int m = nodes.size();
    set_up_pattern(nodes);
    const std::vector<double> diagonal  = scale_reactions();
    const std::vector<double> stiffness = status_stiffness(nodes, diagonal);

    // Friction against the slip: r_t = s mu r_n, s from the last reaction.
    std::vector<double> slip_sign(m);
    for (unsigned int k = 0; k < m; ++k)
      slip_sign[k] = r[k][tangential] >= 0. ? 1. : -1.;

    // The active-set passes: solve with the statuses, then the statuses
    // of the solution, until they no longer change.
    Vector<double> x;
    for (last_passes = 1; last_passes <= max_passes; ++last_passes)
      {
        assemble(nodes, status, slip_sign);
        if (!solve_system(x, message))
          return false;
        read_solution(x, r, increments);
        const bool changed =
          update_statuses(nodes, r, increments, stiffness, status, slip_sign);
        if (debug_log::at(1))
          log_sparse_pass(last_passes, status, changed);
        if (!changed)
          {
            for (unsigned int k = 0; k < m; ++k)
              if (status[k] == NodeStatus::open)
                r[k] = {{0., 0.}};
            return true;
          }
      }
    std::ostringstream text;
    text << "the contact statuses did not settle in " << max_passes
         << " active-set passes of the sparse method";
    message = text.str();
    return false;
  }



  std::vector<double>
  SparseContactStep::scale_reactions()
  {
    std::vector<double> diagonal(n_body_unknowns);
    double              sum = 0.;
    for (const unsigned int b : in_contact)
      {
        // (the whole tangent's: on several processes, the shares' summed)
        const std::vector<double> K_diagonal =
          bodies[b]->system().tangent_diagonal();
        for (unsigned int i = 0; i < K_diagonal.size(); ++i)
          {
            diagonal[offset[b] + i] = std::abs(K_diagonal[i]);
            sum += diagonal[offset[b] + i];
          }
      }
    alpha = n_body_unknowns > 0 && sum > 0. ? sum / n_body_unknowns : 1.;
    return diagonal;
  }



  std::vector<double>
  SparseContactStep::status_stiffness(const ActiveNodes         &nodes,
                                      const std::vector<double> &diagonal) const
  {
    // trial_stiffness over the diagonal estimate of the node's normal
    // compliance, sum g_j^2 / K_jj over the unknowns of its gap row
    // (through both bodies; a stiffness ratio between the bodies then does
    // not leave the soft side's nodes judged by the stiff side's scale).
    std::vector<double> stiffness(nodes.size(), alpha * trial_stiffness);
    std::vector<Share>  c;
    double              constant = 0.;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        expand(nodes.rows[2 * k + normal], c, constant);
        double compliance = 0.;
        for (const Share &j : c)
          if (diagonal[j.column] > 0.)
            compliance += j.weight * j.weight / diagonal[j.column];
        if (compliance > 0.)
          stiffness[k] = trial_stiffness / compliance;
      }
    return stiffness;
  }



  bool
  SparseContactStep::solve_system(Vector<double> &x, std::string &message)
  {
    try
      {
        lu.factorize(matrix);
      }
    catch (const std::exception &e)
      {
        message = std::string("the sparse contact system cannot be "
                              "factorised (a body that nothing holds "
                              "with these contact statuses?): ") +
                  e.what();
        return false;
      }
    x = rhs;
    lu.solve(x);
    for (unsigned int i = 0; i < x.size(); ++i)
      if (!std::isfinite(x(i)))
        {
          message = "the sparse contact system is singular (a body that "
                    "nothing holds with these contact statuses?)";
          return false;
        }
    return true;
  }



  void
  SparseContactStep::read_solution(
    const Vector<double>                &x,
    std::vector<Vector2>                &r,
    std::vector<dealii::Vector<double>> &increments) const
  {
    for (const unsigned int b : in_contact)
      {
        increments[b].reinit(bodies[b]->n_dofs());
        for (unsigned int i = 0; i < increments[b].size(); ++i)
          increments[b](i) = x(offset[b] + i);
        bodies[b]->system().constraints().distribute(increments[b]);
      }
    for (unsigned int k = 0; k < r.size(); ++k)
      r[k] = {{alpha * x(n_body_unknowns + 2 * k + tangential),
               alpha * x(n_body_unknowns + 2 * k + normal)}};
  }



  bool
  SparseContactStep::update_statuses(
    const ActiveNodes                         &nodes,
    const std::vector<Vector2>                &r,
    const std::vector<dealii::Vector<double>> &increments,
    const std::vector<double>                 &stiffness,
    std::vector<NodeStatus>                   &status,
    std::vector<double>                       &slip_sign) const
  {
    // Round-off of the reactions and of the positions.
    double largest = 0.;
    for (const Vector2 &r_k : r)
      largest = std::max(largest, std::abs(r_k[normal]));
    const double force_tolerance = 1e-12 * largest;
    double       size            = 0.;
    for (const unsigned int b : in_contact)
      size = std::max(size, bodies[b]->size());
    const double gap_tolerance = 1e-12 * size;

    // The statuses of the semi-smooth Newton method for the contact law's
    // complementarity functions (Hueber, Stadler and Wohlmuth, SIAM J. Sci.
    // Comput. 30, 2008), with a stiffness c turning displacements into
    // forces: closed if r_n - c g > 0; then sticking if |r_t - c u_t| < mu
    // (r_n - c g), else slipping with friction along r_t - c u_t. A
    // consistent stick (u_t = 0) or slip (u_t against r_t) keeps its
    // status.
    bool changed = false;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const double     mu  = nodes.friction[k];
        const NodeStatus old = status[k];
        const double gap = value_after_step(nodes, 2 * k + normal, increments);
        const double c   = stiffness[k];
        const double normal_trial = r[k][normal] - c * gap;
        if (!(normal_trial > force_tolerance + c * gap_tolerance))
          status[k] = NodeStatus::open;
        else if (mu == 0.)
          status[k] = NodeStatus::slip;
        else
          {
            const double trial =
              r[k][tangential] -
              c * value_after_step(nodes, 2 * k + tangential, increments);
            const double bound  = mu * normal_trial;
            const double margin = force_tolerance + c * gap_tolerance;
            if (std::abs(trial) < bound - margin)
              status[k] = NodeStatus::stick;
            else if (std::abs(trial) > bound + margin)
              {
                const double sign = trial >= 0. ? 1. : -1.;
                changed =
                  changed || (old == NodeStatus::slip && sign != slip_sign[k]);
                status[k]    = NodeStatus::slip;
                slip_sign[k] = sign;
              }
            // (on the bound to round-off: the status stays)
          }
        changed = changed || status[k] != old;
      }
    return changed;
  }



  bool
  SparseContactStep::correct(ContactProblem              &problem,
                             std::vector<Vector<double>> &increments)
  {
    std::vector<ContactNode *> active;
    const ActiveNodes          nodes = problem.active_nodes(active);
    std::vector<BiPotentialSolver::NodeStatus> status(active.size());
    std::vector<BiPotentialSolver::Vector2>    r(active.size());
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        status[k] = active[k]->status;
        r[k]      = {{active[k]->reaction[0], active[k]->reaction[1]}};
      }
    result = BiPotentialSolver::Result();
    {
      TimerOutput::Scope scope(timer, timing::factorization);
      result.converged = solve(nodes, status, r, increments, result.message);
    }
    result.sweeps = passes();
    if (!result.converged)
      return false;
    result.status = status;
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        active[k]->reaction = {{r[k][0], r[k][1]}};
        active[k]->status   = status[k];
      }
    return true;
  }
} // namespace glissade
