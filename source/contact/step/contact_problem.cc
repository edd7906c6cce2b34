#include <deal.II/base/timer.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/contact/step/held_by_contact.h>

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
        auto pair = std::make_unique<ContactPair>(
          c,
          *find(c.slave_body),
          c.master == ContactDescription::MasterKind::obstacle ?
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
          body->system().set_contact_dofs(dofs);
      }

    for (const auto &pair : pairs)
      for (const Body *body : {&pair->slave(), pair->master()})
        if (body != nullptr &&
            std::find(bodies_in_contact.begin(),
                      bodies_in_contact.end(),
                      body_index(body)) == bodies_in_contact.end())
          bodies_in_contact.push_back(body_index(body));
    std::sort(bodies_in_contact.begin(), bodies_in_contact.end());

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
    step = ContactStep::create(
      pairs.empty() ? ContactSolverSettings::Method::condensed :
                      scene.contact_solver.method,
      {bodies, bodies_in_contact, solver_settings, timer, scene.source});
    for (const auto &pair : pairs)
      if (pair->coating() != nullptr &&
          scene.contact_solver.method !=
            ContactSolverSettings::Method::condensed)
        throw InputError(scene.source + ": Contact solver/Method",
                         "pair '" + pair->name() +
                           "' has an abradable coating, whose capped "
                           "reactions the condensed method solves: use "
                           "Method = condensed");
  }



  void
  ContactProblem::accept_step()
  {
    for (auto &pair : pairs)
      pair->wear_coating();
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
    step->begin_step(*this);
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
    return step->correct(*this, increments);
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
    // (only the condensed method has them: the sparse one refuses a body
    // that relies on contact)
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (const auto &[dof, k] : bodies[b]->system().regularization())
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
        const std::vector<double> cap = pair->normal_force_caps();
        for (unsigned int k = 0; k < pair->nodes().size(); ++k)
          if (ContactNode &node = pair->nodes()[k]; node.active)
            {
              const ContactLinearization &l = node.linearization;
              active.push_back(&node);
              nodes.friction.push_back(
                cone_slope(pair->settings().friction, l.vertex_cone));
              nodes.normal_cap.push_back(cap[k]);
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



  std::string
  ContactProblem::held_by_contact_message() const
  {
    std::string names;
    for (const auto &body : bodies)
      if (!body->system().regularization().empty())
        {
          names += (names.empty() ? "'" : ", '") + body->name() + "'";
          for (const auto &motion : body->system().free_rigid_motions())
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
