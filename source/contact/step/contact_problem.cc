#include <deal.II/base/timer.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/discretisation/mortar_variables.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/contact/step/held_by_contact.h>
#include <glissade/contact/surfaces/surface_registry.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  ContactProblem::ContactProblem(
    const SceneDescription                   &scene,
    const std::vector<std::unique_ptr<Body>> &bodies,
    TimerOutput                              &timer)
    : automatic(scene.automatic_contact)
    , bodies(bodies)
    , timer(timer)
  {
    // Each pair is built and checked even when another has a mistake: all
    // of them in one message.
    InputErrorList mistakes;
    for (const auto &c : scene.contacts)
      mistakes.collect([&]() {
        auto pair = std::make_unique<ContactPair>(
          c,
          *body_named(c.slave_body),
          c.master == ContactDescription::MasterKind::obstacle ?
            nullptr :
            body_named(c.master_body),
          timer);
        pair->check_initial_state();
        pairs.push_back(std::move(pair));
        sides_of_pair.push_back(
          {{numbers::invalid_unsigned_int, numbers::invalid_unsigned_int}});
        resting.push_back(false);
      });
    mistakes.throw_if_any();

    // Automatic contact: every side's boundary known now (a pair made in
    // the middle of a run must not find a mistake), and the pairs of the
    // couples within reach at the start, checked as pairs written are.
    if (!automatic.empty())
      {
        std::vector<BroadPhase::Side> sides;
        for (unsigned int s = 0; s < automatic.sides.size(); ++s)
          mistakes.collect([&]() {
            const auto       &side  = automatic.sides[s];
            Body             *body  = body_named(side.body);
            const std::string entry = automatic.file +
                                      ": Scene/Contact bodies (body '" +
                                      side.body + "')";
            for (const auto &name : text::split_top_level(side.boundary, ','))
              body->boundary_id(text::trim(name), entry);
            // (the broad phase's boxes and self-contact read the nodes'
            // displacements, which a NURBS body's dofs are not)
            if (!body->space().capabilities().dofs_are_nodal_values)
              throw InputError(entry,
                               "automatic contact among NURBS bodies is not "
                               "built yet; declare the pair (Contact <name>, "
                               "node-to-segment, Surface = nurbs for a NURBS "
                               "master)");
            sides.push_back({body, side.boundary, entry});
            // What the side touches as a master holds what it touches as
            // a slave: its surface's dofs, the vertices' and, on a Hermite
            // body, their derivatives.
            side_dofs.push_back(
              SurfaceRegistry::create({automatic.pair(s, s), body})->dofs());
          });
        mistakes.throw_if_any();
        broad_phase =
          std::make_unique<BroadPhase>(sides,
                                       automatic.settings.alert_distance);
        for (const auto &couple : broad_phase->couples_within_reach())
          mistakes.collect([&]() {
            make_couple_pairs(couple, false);
            for (unsigned int p = pairs.size() - automatic.passes;
                 p < pairs.size();
                 ++p)
              pairs[p]->check_initial_state();
          });
        mistakes.throw_if_any();
      }
    check_free_motions_are_held(bodies, pairs, scene.source);

    for (const auto &body : bodies)
      if (const auto dofs = contact_dofs(*body); !dofs.empty())
        body->system().set_contact_dofs(dofs);

    for (const auto &pair : pairs)
      for (const Body *body : {&pair->slave(), pair->master()})
        if (body != nullptr)
          bodies_in_contact.push_back(body_index(body));
    for (const auto &side : automatic.sides)
      bodies_in_contact.push_back(body_index(body_named(side.body)));
    std::sort(bodies_in_contact.begin(), bodies_in_contact.end());
    bodies_in_contact.erase(std::unique(bodies_in_contact.begin(),
                                        bodies_in_contact.end()),
                            bodies_in_contact.end());

    if (!pairs.empty() || !automatic.empty())
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
      pairs.empty() && automatic.empty() ?
        ContactSolverSettings::Method::condensed :
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



  void
  ContactProblem::make_couple_pairs(const std::array<unsigned int, 2> &couple,
                                    const bool resting_now)
  {
    // (each pass: its slave side and its master side)
    std::vector<std::array<unsigned int, 2>> passes = {couple};
    if (automatic.passes == 2)
      passes.push_back({{couple[1], couple[0]}});
    for (const auto &[slave, master] : passes)
      {
        const ContactDescription description = automatic.pair(slave, master);
        pairs.push_back(
          std::make_unique<ContactPair>(description,
                                        *body_named(description.slave_body),
                                        body_named(description.master_body),
                                        timer));
        pairs.back()->report_forces_scaled_by(reported_force_scale);
        if (resting_now)
          pairs.back()->rest(step_start, step_end);
        sides_of_pair.push_back({{slave, master}});
        resting.push_back(resting_now);
      }
    made_couples.insert(std::upper_bound(made_couples.begin(),
                                         made_couples.end(),
                                         couple),
                        couple);
  }



  void
  ContactProblem::follow_broad_phase(const bool mid_step)
  {
    if (!broad_phase)
      return;
    const auto within_reach = broad_phase->couples_within_reach();
    for (const auto &couple : within_reach)
      if (!std::binary_search(made_couples.begin(), made_couples.end(), couple))
        make_couple_pairs(couple, mid_step);
    // Mid-step, a pair that comes within reach joins with its nodes as
    // they are (inactive, no counterpart): activate_penetrating_nodes()
    // projects them. A pair does not rest before the next detection.
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (const auto [slave, master] = sides_of_pair[p];
          slave != numbers::invalid_unsigned_int)
        {
          const bool in_reach =
            std::binary_search(within_reach.begin(),
                               within_reach.end(),
                               std::array<unsigned int, 2>{
                                 {std::min(slave, master),
                                  std::max(slave, master)}});
          resting[p] = mid_step ? resting[p] && !in_reach : !in_reach;
          if (resting[p])
            continue;
          // The slave nodes searched: those within the alert distance of
          // the master's box (the rest of a ring whose side touches
          // another never is).
          BoundingBox<2> near = broad_phase->box(master);
          near.extend(0.5 * automatic.settings.alert_distance);
          pairs[p]->search_only_within(near);
        }
  }



  ContactPair *
  ContactProblem::pair_named(const std::string &name)
  {
    for (const auto &pair : pairs)
      if (pair->name() == name)
        return pair.get();
    // "<slave> on <master>" of two listed bodies: their couple's pairs.
    const auto &sides = automatic.sides;
    for (unsigned int i = 0; i < sides.size(); ++i)
      if (name.rfind(sides[i].body + " on ", 0) == 0)
        for (unsigned int j = 0; j < sides.size(); ++j)
          if (j != i &&
              name.substr(sides[i].body.size() + 4) == sides[j].body &&
              (automatic.passes == 2 || i < j))
            {
              make_couple_pairs({{std::min(i, j), std::max(i, j)}}, true);
              for (const auto &pair : pairs)
                if (pair->name() == name)
                  return pair.get();
            }
    return nullptr;
  }



  std::vector<std::string>
  ContactProblem::automatic_pair_names() const
  {
    std::vector<std::string> names;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (sides_of_pair[p][0] != numbers::invalid_unsigned_int)
        names.push_back(pairs[p]->name());
    return names;
  }



  std::vector<types::global_dof_index>
  ContactProblem::contact_dofs(const Body &body) const
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &pair : pairs)
      {
        const auto d = pair->contact_dofs(body);
        dofs.insert(dofs.end(), d.begin(), d.end());
      }
    for (unsigned int s = 0; s < automatic.sides.size(); ++s)
      if (automatic.sides[s].body == body.name())
        dofs.insert(dofs.end(), side_dofs[s].begin(), side_dofs[s].end());
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    return dofs;
  }



  void
  ContactProblem::report_forces_scaled_by(const double scale)
  {
    reported_force_scale = scale;
    for (const auto &pair : pairs)
      pair->report_forces_scaled_by(scale);
  }



  Body *
  ContactProblem::body_named(const std::string &name) const
  {
    for (const auto &b : bodies)
      if (b->name() == name)
        return b.get();
    return nullptr;
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
    step_start = step_start_time;
    step_end   = time;
    follow_broad_phase(false);
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (resting[p])
        pairs[p]->rest(step_start_time, time);
      else
        pairs[p]->begin_step(step_start_time, time);
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
    follow_broad_phase(true);
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (!resting[p])
        n += pairs[p]->activate_penetrating_nodes();
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
    merged_loads.clear();
    merged_rows.clear();
    for (auto &pair : pairs)
      {
        std::map<std::pair<unsigned int, types::global_dof_index>, DofVector>
                                          on_one_dof;
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
                if (term.load.size() == 1 && !term.row.empty())
                  {
                    // (summed below with the other nodes' terms on the
                    // same dof)
                    const DofCoefficient &e = term.load.front();
                    mortar::add_scaled(on_one_dof[{e.body, e.dof}],
                                       e.value,
                                       term.row);
                  }
                else if (!term.load.empty() && !term.row.empty())
                  nodes.terms.push_back({{&term.load, b}, {&term.row, b}});
            }
        // The terms whose load is one dof (mortar's force weights: each
        // dof is reached by several nodes) as one term per dof: every term
        // costs the condensed step a solve and a column of its Woodbury
        // system.
        for (auto &[dof, row] : on_one_dof)
          {
            mortar::merge_entries(row);
            merged_loads.push_back({{dof.first, dof.second, 1.}});
            merged_rows.push_back(std::move(row));
            nodes.terms.push_back(
              {{&merged_loads.back(), b}, {&merged_rows.back(), b}});
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
      for (unsigned int p = 0; p < pairs.size(); ++p)
        if (!resting[p])
          pairs[p]->update_geometry();
    }
    // The forces of the reactions at the new state: the residual of the
    // next iteration is then the true one, R(U, r).
    std::vector<Vector<double>> forces(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      forces[b].reinit(bodies[b]->n_dofs());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (!resting[p])
        {
          ContactPair &pair        = *pairs[p];
          const auto   pair_forces = pair.contact_forces();
          forces[body_index(&pair.slave())] += pair_forces[0];
          if (pair.master())
            forces[body_index(pair.master())] += pair_forces[1];
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
    // A pair made since (a couple that came within reach in the step
    // being undone) goes back to having found nothing.
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (p < stored_nodes.size())
        pairs[p]->nodes() = stored_nodes[p];
      else
        pairs[p]->rest(step_start, step_end);
  }
} // namespace glissade
