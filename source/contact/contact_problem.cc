#include <deal.II/base/timer.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/condensed_problem.h>
#include <glissade/contact/contact_problem.h>
#include <glissade/contact/held_by_contact.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

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
        auto pair = std::make_unique<ContactPair>(c,
                                                  *find(c.slave_body),
                                                  c.master_body == "rigid" ?
                                                    nullptr :
                                                    find(c.master_body),
                                                  timer);
        pair->check_initial_state();
        pairs.push_back(std::move(pair));
      });
    mistakes.throw_if_any();
    check_free_motions_are_held(bodies, pairs, scene.source);

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

    for (const auto &pair : pairs)
      for (const Body *body : {&pair->slave(), pair->master()})
        if (body != nullptr &&
            std::find(bodies_in_contact.begin(),
                      bodies_in_contact.end(),
                      body_index(body)) == bodies_in_contact.end())
          bodies_in_contact.push_back(body_index(body));
    std::sort(bodies_in_contact.begin(), bodies_in_contact.end());
    eliminated_last.resize(bodies.size());
    if (scene.contact_solver.method == ContactSolverSettings::Method::sparse &&
        !pairs.empty())
      {
        // A body that only contact holds has a singular system whenever
        // its nodes open or slip in an active-set pass; the condensed
        // method holds it through springs it takes out again exactly
        // (theory.md, section 4.6), which the sparse system has no room
        // for.
        for (const auto &body : bodies)
          if (!body->free_rigid_motions().empty())
            throw InputError(
              scene.source + ": Contact solver/Method",
              "the sparse method needs every body held by its own supports, "
              "and contact alone holds body '" +
                body->name() + "' (" +
                body->free_rigid_motions()[0].describe(body->size()) +
                "): use Method = condensed, or support the body");
        sparse_step =
          std::make_unique<SparseContactStep>(bodies, bodies_in_contact);
      }

    if (!pairs.empty())
      {
        // (the active nodes of all pairs form one local problem, solved
        // with the section Contact solver's settings)
        const ContactSolverSettings &solver = scene.contact_solver;
        solver_settings.beta                = solver.beta;
        solver_settings.residual_tolerance  = solver.tolerance;
        solver_settings.change_tolerance    = solver.tolerance;
        solver_settings.max_sweeps          = solver.max_sweeps;
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
    if (!sparse_step)
      eliminate_touching_dofs_last();
  }



  void
  ContactProblem::eliminate_touching_dofs_last()
  {
    // The dofs of the active nodes' rows and forces, per body: the ones
    // this increment's W needs. A declared contact area much larger than
    // what touches (Hertz: the whole arc, 1,256 dofs, for some 60 in
    // contact) otherwise puts a dense trailing block of its size into
    // every factorisation. A dof that joins later (a node activated or
    // sliding onto another segment within the increment) is still
    // answered, by back-substitutions.
    std::vector<std::vector<types::global_dof_index>> touching(bodies.size());
    for (const auto &pair : pairs)
      {
        const std::array<unsigned int, 2> b = {
          {body_index(&pair->slave()),
           pair->master() ? body_index(pair->master()) :
                            numbers::invalid_unsigned_int}};
        for (const auto &node : pair->nodes())
          if (node.active)
            {
              const ContactLinearization    &l       = node.linearization;
              std::vector<const DofVector *> vectors = {&l.gap_row,
                                                        &l.slip_row,
                                                        &l.tangential_force,
                                                        &l.normal_force};
              for (const auto &term : l.tangent_terms)
                {
                  vectors.push_back(&term.load);
                  vectors.push_back(&term.row);
                }
              for (const DofVector *v : vectors)
                for (const auto &e : *v)
                  if (b[e.body] != numbers::invalid_unsigned_int)
                    touching[b[e.body]].push_back(e.dof);
            }
      }
    for (const unsigned int b : bodies_in_contact)
      {
        // (a body held by contact keeps its declared area: its springs
        // are chosen among those dofs)
        if (touching[b].empty() || !bodies[b]->free_rigid_motions().empty())
          continue;
        std::sort(touching[b].begin(), touching[b].end());
        touching[b].erase(std::unique(touching[b].begin(), touching[b].end()),
                          touching[b].end());
        if (touching[b] != eliminated_last[b])
          {
            eliminated_last[b] = touching[b];
            bodies[b]->set_contact_dofs(touching[b]);
          }
      }
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
  ContactProblem::correct_sparse(std::vector<Vector<double>> &increments)
  {
    std::vector<ContactNode *>                 active;
    const ActiveNodes                          nodes = active_nodes(active);
    std::vector<BiPotentialSolver::NodeStatus> status(active.size());
    std::vector<BiPotentialSolver::Vector2>    r(active.size());
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        status[k] = active[k]->status;
        r[k]      = {{active[k]->reaction[0], active[k]->reaction[1]}};
      }
    result           = BiPotentialSolver::Result();
    result.converged = true;
    {
      TimerOutput::Scope scope(timer, timing::factorization);
      result.converged =
        sparse_step->solve(nodes, status, r, increments, result.message);
    }
    result.sweeps = sparse_step->passes();
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



  bool
  ContactProblem::correct(std::vector<Vector<double>> &increments)
  {
    if (sparse_step)
      return correct_sparse(increments);

    // Nodes that the free step would take behind the master join now,
    // linearised at the current state like the others (update_state());
    // under a velocity law the integrator chose the step's nodes.
    if (!velocity_law && activate_nodes_crossed_by(increments) > 0)
      {
        TimerOutput::Scope scope(timer, timing::detection);
        for (auto &pair : pairs)
          pair->update_geometry();
      }

    // The active nodes of all pairs form one condensed problem: nodes of
    // different pairs couple through the bodies they share.
    std::vector<ContactNode *> active;
    const ActiveNodes          nodes = active_nodes(active);
    result                           = BiPotentialSolver::Result();
    result.converged                 = true;
    if (active.empty())
      {
        // (with no node in contact, only a body that relies on contact
        // has a problem: nothing holds it)
        if (held_by_contact_message().empty())
          return true;
        result.converged = false;
        result.message   = held_by_contact_message() +
                         ": no slave node is in contact (all farther than "
                         "the alert distance)";
        return false;
      }

    // The reactions, and the condensed problem whose step they go with.
    std::vector<BiPotentialSolver::Vector2> r(active.size());
    for (unsigned int k = 0; k < active.size(); ++k)
      r[k] = {{active[k]->reaction[0], active[k]->reaction[1]}};
    const std::unique_ptr<CondensedProblem> condensed =
      solve_local_problem(active, nodes, increments, r);
    if (!condensed)
      return false;
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        active[k]->reaction = {{r[k][0], r[k][1]}};
        active[k]->status   = result.status[k];
      }
    if (debug_log::at(2))
      for (const ContactNode *node : active)
        debug_log::stream()
          << "      node " << node->vertex << " segment " << node->segment
          << " s " << node->s << " gap " << node->gap << " r "
          << node->reaction[0] << ' ' << node->reaction[1] << std::endl;

    // Corrector: the Newton step.
    std::vector<Vector<double>> contact_forces(bodies.size());
    condensed->correct(r, increments, contact_forces);
    return true;
  }



  ActiveNodes
  ContactProblem::active_nodes(std::vector<ContactNode *> &active)
  {
    ActiveNodes nodes;
    active.clear();
    // The springs of bodies held by contact come out of the Newton matrix
    // again: K = (K + k e e^T) - (k e) (x) e.
    spring_loads.clear();
    spring_rows.clear();
    std::vector<unsigned int> spring_body;
    // (the sparse method does not factorise the bodies alone: no springs)
    for (unsigned int b = 0; b < bodies.size() && !sparse_step; ++b)
      for (const auto &[dof, k] : bodies[b]->regularization())
        {
          spring_loads.push_back({{0, dof, k}});
          spring_rows.push_back({{0, dof, 1.}});
          spring_body.push_back(b);
        }
    for (unsigned int s = 0; s < spring_body.size(); ++s)
      nodes.terms.push_back(
        {{&spring_loads[s], {{spring_body[s], numbers::invalid_unsigned_int}}},
         {&spring_rows[s], {{spring_body[s], numbers::invalid_unsigned_int}}}});
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
              nodes.friction.push_back(
                cone_slope(pair->settings().friction, l.vertex_cone));
              nodes.initial.push_back(
                {{l.slip + node.law_shift[0], l.gap + node.law_shift[1]}});
              nodes.forces.push_back({&l.tangential_force, b});
              nodes.forces.push_back({&l.normal_force, b});
              nodes.rows.push_back({&l.slip_row, b});
              nodes.rows.push_back({&l.gap_row, b});
              for (const auto &term : l.tangent_terms)
                if (!term.load.empty() && !term.row.empty())
                  nodes.terms.push_back({{&term.load, b}, {&term.row, b}});
            }
      }
    return nodes;
  }



  std::unique_ptr<CondensedProblem>
  ContactProblem::solve_local_problem(
    const std::vector<ContactNode *>        &active,
    const ActiveNodes                       &nodes,
    const std::vector<Vector<double>>       &predictor,
    std::vector<BiPotentialSolver::Vector2> &r)
  {
    // The directions the contact law holds at the start: closed normals,
    // sticking tangents. Where the Newton matrix alone is indefinite or
    // singular (a body past a limit point or held by contact only), the
    // local problem is augmented on them (theory.md, section 4.5): exact
    // as long as they stay closed and sticking, which is checked. A node
    // starts with the augmentation of its last solve.
    const unsigned int                            n     = active.size();
    const std::vector<BiPotentialSolver::Vector2> start = r;
    std::vector<std::array<bool, 2>>              held(n);
    Augmentation                                  augmentation;
    augmentation.directions.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto status =
          BiPotentialSolver::classify(start[k], nodes.friction[k]);
        held[k] = {{status == BiPotentialSolver::NodeStatus::stick &&
                      nodes.friction[k] > 0.,
                    status != BiPotentialSolver::NodeStatus::open}};
        for (unsigned int c = 0; c < 2; ++c)
          augmentation.directions[k][c] = held[k][c] && active[k]->augmented[c];
      }

    // Escalation when a solve fails: the held directions, then every
    // direction of every node, then with a ten and a hundred times stiffer
    // augmentation.
    unsigned int                      stage = 0;
    std::unique_ptr<CondensedProblem> condensed;
    while (true)
      {
        {
          TimerOutput::Scope scope(timer, timing::compliance);
          condensed = std::make_unique<CondensedProblem>(nodes,
                                                         augmentation,
                                                         bodies,
                                                         predictor);
        }
        // The bi-potential iteration (Gauss-Seidel), the paper's law
        // solver. Where W is not positive on the directions in play (the
        // tangent alone is indefinite), the law can have other solutions
        // than the Newton step's; if Gauss-Seidel changed the statuses
        // there, or failed, the active-set iteration from the held
        // statuses finds the one that continues them.
        bool solved = false;
        result      = BiPotentialSolver::Result();
        if (condensed->regular())
          {
            TimerOutput::Scope      scope(timer, timing::local_solve);
            const BiPotentialSolver solver(solver_settings);
            r                 = start;
            result            = solver.solve(condensed->compliance(),
                                  condensed->free_displacement(),
                                  nodes.friction,
                                  r);
            solved            = result.converged;
            bool check_branch = !solved;
            if (solved)
              {
                std::vector<std::array<bool, 2>> in_play = held;
                bool                             changed = false;
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const auto                status = result.status[k];
                    const std::array<bool, 2> now    = {
                         {status == BiPotentialSolver::NodeStatus::stick &&
                            nodes.friction[k] > 0.,
                          status != BiPotentialSolver::NodeStatus::open}};
                    changed = changed || now != held[k];
                    for (unsigned int c = 0; c < 2; ++c)
                      in_play[k][c] = in_play[k][c] || now[c];
                  }
                check_branch = changed && augmentation.count() == 0 &&
                               !condensed->positive_definite_on(in_play);
              }
            if (check_branch)
              {
                std::vector<BiPotentialSolver::Vector2> continued = start;
                const BiPotentialSolver::Result         continuation =
                  solver.solve_by_active_set(condensed->compliance(),
                                             condensed->free_displacement(),
                                             nodes.friction,
                                             continued);
                if (continuation.converged)
                  {
                    r      = continued;
                    result = continuation;
                    solved = true;
                  }
              }
          }
        else
          result.message = "the Newton matrix with the contact terms is "
                           "singular on the contact dofs";

        // Augmented directions must end closed (normal) or sticking
        // (tangential); those that do not are released and the problem
        // solved again.
        bool consistent = solved;
        if (solved)
          for (unsigned int k = 0; k < n; ++k)
            {
              auto      &d      = augmentation.directions[k];
              const auto status = result.status[k];
              if (d[1] && status == BiPotentialSolver::NodeStatus::open)
                d = held[k] = {{false, false}}, consistent = false;
              if (d[0] && status != BiPotentialSolver::NodeStatus::stick)
                d[0] = held[k][0] = false, consistent = false;
            }
        if (debug_log::at(1))
          debug_log::stream()
            << "    contact solve: " << augmentation.count()
            << " augmented directions (factor " << augmentation.factor << "), "
            << (result.polished ? "active set" : "Gauss-Seidel") << ": "
            << (solved ? (consistent ? "solved" : "inconsistent") :
                         "failed: " + result.message)
            << std::endl;
        if (consistent)
          break;
        if (solved)
          continue;

        ++stage;
        if (stage == 1 && augmentation.directions != held)
          augmentation.directions = held;
        else if (stage <= 2)
          {
            stage = 2;
            for (unsigned int k = 0; k < n; ++k)
              augmentation.directions[k] = {{nodes.friction[k] > 0., true}};
          }
        else if (stage <= 4)
          augmentation.factor *= 10.;
        else
          {
            if (!held_by_contact_message().empty() && !condensed->regular())
              result.message = held_by_contact_message() +
                               ": its contact nodes are open or slipping "
                               "where they would have to hold it";
            else if (condensed->regular())
              {
                const std::string where = not_positive_at(active, *condensed);
                if (!where.empty())
                  result.message = where;
              }
            return nullptr;
          }
      }

    for (unsigned int k = 0; k < n; ++k)
      active[k]->augmented = augmentation.directions[k];
    return condensed;
  }



  std::string
  ContactProblem::not_positive_at(const std::vector<ContactNode *> &active,
                                  const CondensedProblem &condensed) const
  {
    // The first node whose own compliance is negative: pushing it gives
    // way, so the bodies are unstable there with the rest held.
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        const auto         w = condensed.compliance().diagonal_block(k);
        const unsigned int c = w[1][1] <= 0. ? 1 : w[0][0] < 0. ? 0 : 2;
        if (c == 2)
          continue;
        for (const auto &pair : pairs)
          for (const auto &node : pair->nodes())
            if (&node == active[k])
              {
                std::ostringstream message;
                message << "the bodies in contact are unstable at slave node ("
                        << node.reference_position[0] << ", "
                        << node.reference_position[1] << ") of pair '"
                        << pair->name() << "' (body '" << pair->slave().name()
                        << "'"
                        << (pair->master() ?
                              " on body '" + pair->master()->name() + "'" :
                              std::string(" on the obstacle"))
                        << "): its " << (c == 1 ? "normal" : "tangential")
                        << " compliance in the Newton matrix is " << w[c][c]
                        << " <= 0, so the tangent is not positive there even "
                           "with the contact's closed directions held. The "
                           "bodies are past a limit point of their own "
                           "(buckling, a sidesway, a folding corner), or the "
                           "increment is too large for the change of contact "
                           "status. Try more increments (Load program/Stage "
                           "increments), a support or friction that holds "
                           "the motion, or a finer mesh there";
                return message.str();
              }
      }
    return "";
  }



  std::string
  ContactProblem::held_by_contact_message() const
  {
    std::string names;
    for (const auto &body : bodies)
      if (!body->regularization().empty())
        {
          names += (names.empty() ? "'" : ", '") + body->name() + "'";
          for (const auto &motion : body->free_rigid_motions())
            names += std::string(names.back() == '\'' ? " (" : ", ") +
                     motion.describe(body->size());
          names += ")";
        }
    return names.empty() ? "" :
                           "the contact does not hold the bodies that rely on "
                           "it, " +
                             names;
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
