#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/condensed_problem.h>
#include <glissade/contact/contact_problem.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

namespace glissade
{
  ContactProblem::ContactProblem(
    const SceneDescription                   &scene,
    const std::vector<std::unique_ptr<Body>> &bodies,
    TimerOutput                              &timer)
    : bodies(bodies)
    , timer(timer)
  {
    const auto find = [&](const std::string &name) -> Body * {
      for (const auto &b : bodies)
        if (b->name() == name)
          return b.get();
      return nullptr;
    };
    // Each pair is built and checked even when another has a mistake: all
    // of them in one message.
    InputErrorList mistakes;
    for (const auto &c : scene.contacts)
      mistakes.collect([&]() {
        auto pair = std::make_unique<ContactPair>(
          c,
          *find(c.slave_body),
          c.master_body == "rigid" ? nullptr : find(c.master_body),
          timer);
        pair->check_initial_state();
        pairs.push_back(std::move(pair));
      });
    mistakes.throw_if_any();

    for (const auto &body : bodies)
      {
        std::vector<types::global_dof_index> dofs;
        for (const auto &pair : pairs)
          {
            const auto d = pair->contact_dofs(*body);
            dofs.insert(dofs.end(), d.begin(), d.end());
          }
        if (!dofs.empty())
          body->set_contact_dofs(dofs);
      }

    // The active nodes of all pairs form one local problem, solved with
    // the settings of the first pair.
    if (!pairs.empty())
      {
        const auto &first                  = pairs[0]->settings();
        solver_settings.beta               = first.beta;
        solver_settings.residual_tolerance = first.tolerance;
        solver_settings.change_tolerance   = first.tolerance;
        solver_settings.max_sweeps         = first.max_sweeps;
        solver_settings.rho_choice =
          BiPotentialSolver::RhoChoice::largest_diagonal_compliance;
      }
  }



  unsigned int
  ContactProblem::body_index(const Body *body) const
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b].get() == body)
        return b;
    return numbers::invalid_unsigned_int;
  }



  void
  ContactProblem::begin_step(const double step_start_time, const double time)
  {
    TimerOutput::Scope scope(timer, timing::detection);
    for (auto &pair : pairs)
      pair->begin_step(step_start_time, time);
  }



  unsigned int
  ContactProblem::n_active() const
  {
    unsigned int n = 0;
    for (const auto &pair : pairs)
      n += pair->n_active();
    return n;
  }



  unsigned int
  ContactProblem::activate_penetrating_nodes()
  {
    TimerOutput::Scope scope(timer, timing::detection);
    unsigned int       n = 0;
    for (auto &pair : pairs)
      n += pair->activate_penetrating_nodes();
    return n;
  }



  unsigned int
  ContactProblem::activate_nodes_crossed_by(
    const std::vector<Vector<double>> &free_step)
  {
    // Each body holds u + du_lib while the nodes are projected, then gets
    // its own u back unchanged (a swap, not u + du - du). The master curve
    // is left at the trial state: the next update rebuilds it.
    std::vector<Vector<double>> other(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        other[b] = bodies[b]->displacement();
        other[b] += free_step[b];
        bodies[b]->swap_displacement(other[b]);
      }
    const unsigned int n = activate_penetrating_nodes();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->swap_displacement(other[b]);
    return n;
  }



  bool
  ContactProblem::correct(std::vector<Vector<double>> &increments)
  {
    // Nodes that the free step would take behind the master join now,
    // linearised at the current state like the others (update_state()).
    if (activate_nodes_crossed_by(increments) > 0)
      {
        TimerOutput::Scope scope(timer, timing::detection);
        for (auto &pair : pairs)
          pair->update_geometry();
      }

    // The active nodes of all pairs form one condensed problem: nodes of
    // different pairs couple through the bodies they share. Per node the
    // forces of unit reactions and the slip and gap rows, and the terms of
    // the contact tangent.
    std::vector<ContactNode *> active;
    std::vector<double>        mu;
    std::vector<PairVector>    forces, rows;
    std::vector<BiPotentialSolver::Vector2> initial;
    std::vector<RankOneTerm>   tangent_terms;
    for (auto &pair : pairs)
      {
        const std::array<unsigned int, 2> b = {
          {body_index(&pair->slave()),
           pair->master() ? body_index(pair->master()) :
                            numbers::invalid_unsigned_int}};
        for (auto &node : pair->nodes())
          if (node.active)
            {
              const ContactLinearization &l = node.linearization;
              active.push_back(&node);
              mu.push_back(pair->settings().friction);
              initial.push_back({{l.slip, l.gap}});
              forces.push_back({&l.tangential_force, b});
              forces.push_back({&l.normal_force, b});
              rows.push_back({&l.slip_row, b});
              rows.push_back({&l.gap_row, b});
              for (const auto &[load, row] :
                   {std::make_pair(&l.sliding_load, &l.sliding_row),
                    std::make_pair(&l.rotation_load, &l.rotation_row)})
                if (!load->empty() && !row->empty())
                  tangent_terms.push_back({{load, b}, {row, b}});
            }
      }
    result           = BiPotentialSolver::Result();
    result.converged = true;
    if (active.empty())
      return true;
    const unsigned int n = active.size();

    // The local problem on the condensed system, first as it is; if it
    // fails (a tangent that is indefinite or singular without the contact
    // that holds it), again with the closed constraints augmented
    // (theory.md, section 4.5): exact once the augmented nodes stay closed.
    std::vector<BiPotentialSolver::Vector2> start(n), r(n);
    for (unsigned int k = 0; k < n; ++k)
      start[k] = {{active[k]->reaction[0], active[k]->reaction[1]}};
    std::vector<std::array<bool, 2>> augmented(n, {{false, false}});
    std::vector<DofVector>           scaled;
    std::unique_ptr<CondensedProblem> condensed;
    std::vector<double>               stiffness(n, 0.);
    bool                              consistent = false;
    // (The condensed problem refers to these: they live as long as it.)
    std::vector<RankOneTerm> terms;
    std::vector<PairVector>  extra;
    for (unsigned int attempt = 0; attempt < 8 && !consistent; ++attempt)
      {
        terms = tangent_terms;
        extra.clear();
        scaled.clear();
        scaled.reserve(4 * n);
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < 2; ++c)
            if (augmented[k][c])
              {
                // K + E row (x) row and the right-hand side - E u_0 row:
                // the constraint row . du + u_0 = 0 of a closed direction.
                const double       E   = stiffness[k];
                const PairVector  &row = rows[2 * k + c];
                const double u0 = c == 0 ? active[k]->linearization.slip :
                                           active[k]->linearization.gap;
                scaled.push_back(*row.coefficients);
                for (auto &e : scaled.back())
                  e.value *= -E;
                terms.push_back({{&scaled.back(), row.bodies}, row});
                scaled.push_back(*row.coefficients);
                for (auto &e : scaled.back())
                  e.value *= -E * u0;
                extra.push_back({&scaled.back(), row.bodies});
              }

        TimerOutput::Scope compliance_scope(timer, timing::compliance);
        condensed = std::make_unique<CondensedProblem>(
          initial, forces, rows, terms, extra, bodies, increments);
        compliance_scope.stop();

        bool solved = condensed->regular();
        if (solved)
          {
            TimerOutput::Scope local_solve_scope(timer, timing::local_solve);
            r      = start;
            result = BiPotentialSolver(solver_settings)
                       .solve(condensed->compliance(),
                              condensed->free_displacement(), mu, r);
            solved = result.converged;
          }
        else
          {
            result.converged = false;
            result.message   = "the Newton matrix with the contact terms is "
                             "singular on the contact dofs";
          }

        if (attempt == 0)
          {
            // The augmentation's stiffness: the inverse of each node's
            // compliance through its bodies alone (without the contact
            // terms), a scale at which S stays well conditioned.
            for (unsigned int k = 0; k < n; ++k)
              {
                const double w = condensed->base_normal_compliance(k);
                stiffness[k] = w > 0. ? 1. / w : 0.;
              }
            double largest = *std::max_element(stiffness.begin(), stiffness.end());
            for (auto &E : stiffness)
              if (!(E > 0.))
                E = largest;
          }

        // Augmented directions must end closed (normal) or sticking
        // (tangential): then the answer is exact. The others are released.
        consistent = solved;
        if (solved)
          for (unsigned int k = 0; k < n; ++k)
            {
              const auto status = result.status[k];
              if (augmented[k][1] && status == BiPotentialSolver::NodeStatus::open)
                augmented[k] = {{false, false}}, consistent = false;
              if (augmented[k][0] && status != BiPotentialSolver::NodeStatus::stick)
                augmented[k][0] = false, consistent = false;
            }
        if (std::getenv("GLISSADE_DEBUG"))
          {
            unsigned int n_augmented = 0;
            for (const auto &a : augmented)
              n_augmented += a[0] + a[1];
            std::cerr << "    contact attempt " << attempt << ": "
                      << n_augmented << " augmented directions, "
                      << (solved ? (consistent ? "solved" : "inconsistent") :
                                   "failed")
                      << std::endl;
          }
        if (solved)
          continue; // done, or the same problem with fewer augmented directions

        if (std::getenv("GLISSADE_DEBUG"))
          std::cerr << "    augmentation, attempt " << attempt + 1 << ": "
                    << result.message << std::endl;
        // Failed: augment every node that pushes (or, once that failed
        // too, every active node), in the directions its status holds.
        if (attempt >= 4)
          return false;
        for (unsigned int k = 0; k < n; ++k)
          {
            const auto status =
              BiPotentialSolver::classify(start[k], mu[k]);
            const bool closed =
              attempt >= 1 || status != BiPotentialSolver::NodeStatus::open;
            augmented[k][1] = closed;
            augmented[k][0] =
              closed && mu[k] > 0. &&
              (attempt >= 1 || status == BiPotentialSolver::NodeStatus::stick);
          }
        if (attempt >= 2)
          for (auto &E : stiffness)
            E *= 10.;
      }
    if (!consistent)
      {
        result.converged = false;
        return false;
      }

    for (unsigned int k = 0; k < n; ++k)
      {
        active[k]->reaction = {{r[k][0], r[k][1]}};
        active[k]->status   = result.status[k];
      }
    if (const char *debug = std::getenv("GLISSADE_DEBUG");
        debug != nullptr && std::string(debug) == "2")
      for (const ContactNode *node : active)
        std::cerr << "      node " << node->vertex << " segment "
                  << node->segment << " s " << node->s << " gap " << node->gap
                  << " r " << node->reaction[0] << ' ' << node->reaction[1]
                  << std::endl;

    // Corrector: the Newton step.
    std::vector<Vector<double>> contact_forces(bodies.size());
    condensed->correct(r, increments, contact_forces);
    return true;
  }



  void
  ContactProblem::update_state()
  {
    {
      TimerOutput::Scope scope(timer, timing::detection);
      for (auto &pair : pairs)
        pair->update_geometry();
    }
    // The forces of the reactions at the new state: the residual of the
    // next iteration is then the true one, R(U, r).
    std::vector<Vector<double>> forces(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      forces[b].reinit(bodies[b]->n_dofs());
    for (auto &pair : pairs)
      {
        const auto pair_forces = pair->contact_forces();
        forces[body_index(&pair->slave())] += pair_forces[0];
        if (pair->master())
          forces[body_index(pair->master())] += pair_forces[1];
      }
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->set_contact_forces(forces[b]);
  }



  void
  ContactProblem::store_state()
  {
    stored_nodes.clear();
    for (const auto &pair : pairs)
      stored_nodes.push_back(pair->nodes());
  }



  void
  ContactProblem::restore_state()
  {
    for (unsigned int p = 0; p < pairs.size(); ++p)
      pairs[p]->nodes() = stored_nodes[p];
  }
} // namespace glissade
