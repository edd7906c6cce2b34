#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/contact_problem.h>

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
    , columns(bodies.size())
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
          scene.source,
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
  ContactProblem::begin_step(const double time)
  {
    TimerOutput::Scope scope(timer, timing::detection);
    for (auto &pair : pairs)
      pair->begin_step(time);
    for (auto &c : columns)
      c.clear();
  }



  const Vector<double> &
  ContactProblem::column(const unsigned int             body,
                         const types::global_dof_index dof)
  {
    auto found = columns[body].find(dof);
    if (found != columns[body].end())
      return found->second;
    Vector<double> unit(bodies[body]->n_dofs());
    unit(dof) = 1.;
    Vector<double> &x = columns[body][dof];
    bodies[body]->solve_homogeneous(unit, x);
    return x;
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
    activate_nodes_crossed_by(increments);

    // Columns of the current tangent: a W frozen at the increment's first
    // iteration lets a sliding mode of faceted masters grow slowly (seen on
    // the concentric rings), so W is formed afresh each iteration.
    for (auto &c : columns)
      c.clear();

    // Scopes, stopped by hand: an exception still closes the section.
    TimerOutput::Scope detection_scope(timer, timing::detection);
    // The active nodes of all pairs form one condensed problem: nodes of
    // different pairs couple through the bodies they share.
    struct Active
    {
      ContactPair *pair;
      ContactNode *node;
      unsigned int slave, master; // body indices (master: invalid if rigid)
    };
    std::vector<Active> active;
    for (auto &pair : pairs)
      {
        pair->update_geometry();
        for (auto &node : pair->nodes())
          if (node.active)
            active.push_back({pair.get(),
                              &node,
                              body_index(&pair->slave()),
                              pair->master() ? body_index(pair->master()) :
                                               numbers::invalid_unsigned_int});
      }
    detection_scope.stop();

    std::vector<Vector<double>> contact_forces(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      contact_forces[b].reinit(bodies[b]->n_dofs());
    if (active.empty())
      {
        for (unsigned int b = 0; b < bodies.size(); ++b)
          bodies[b]->set_contact_forces(contact_forces[b]);
        result = BiPotentialSolver::Result();
        result.converged = true;
        return true;
      }

    const auto body_of = [&](const Active &a, const unsigned int which) {
      return which == 0 ? a.slave : a.master;
    };
    const auto frame = [](const ContactNode &node, const unsigned int row) {
      return row == 0 ? node.tangent : node.normal;
    };

    // W_kl = H_kin,k K^-1 H_force,l^T from the cached columns of K^-1, and
    // u_free_k, summing over the bodies that nodes k and l share.
    TimerOutput::Scope compliance_scope(timer, timing::compliance);
    const unsigned int                      n = active.size();
    ComplianceMatrix                        W;
    std::vector<BiPotentialSolver::Vector2> u_free(n), r(n);
    std::vector<double>                     mu(n);
    W.reinit(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const ContactNode &node = *active[k].node;
        mu[k]                   = active[k].pair->settings().friction;
        r[k]                    = {{node.reaction[0], node.reaction[1]}};
        // Free relative displacement of this iteration, and the slip
        // accumulated since the increment began (for friction).
        Tensor<1, 2> free_motion, slip;
        for (const auto &e : node.kinematics)
          {
            const unsigned int b = body_of(active[k], e.body);
            free_motion[e.component] += e.weight * increments[b](e.dof);
            slip[e.component] +=
              e.weight * (bodies[b]->displacement()(e.dof) -
                          bodies[b]->stored_displacement()(e.dof));
          }
        u_free[k] = {{node.tangent * (slip + free_motion),
                      node.gap + node.normal * free_motion}};
      }
    // W = H_kin C H_force^T with C the block of K_b^-1 on the contact dofs
    // of body b: first T_l = C H_force,l^T (one vector over the contact
    // dofs per node and direction), then W_kl = H_kin,k T_l. This costs
    // O(n e m + n^2 e) instead of O(n^2 e^2) for e map entries per node,
    // which matters for B-spline masters (e ~ 50).
    struct LocalEntry
    {
      unsigned int index; // among the body's contact dofs of this iteration
      unsigned int component;
      double       weight;
    };
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        std::map<types::global_dof_index, unsigned int> index;
        for (const auto &a : active)
          for (const auto *map : {&a.node->kinematics, &a.node->forces})
            for (const auto &e : *map)
              if (body_of(a, e.body) == b)
                index.emplace(e.dof, 0);
        if (index.empty())
          continue;
        std::vector<types::global_dof_index> dofs;
        for (auto &[dof, i] : index)
          {
            i = dofs.size();
            dofs.push_back(dof);
          }
        const unsigned int m = dofs.size();

        // The maps of every node restricted to this body, by local index.
        std::vector<std::vector<LocalEntry>> kinematics(n), forces(n);
        std::vector<bool>                    is_force_dof(m, false);
        for (unsigned int k = 0; k < n; ++k)
          {
            for (const auto &e : active[k].node->kinematics)
              if (body_of(active[k], e.body) == b)
                kinematics[k].push_back({index[e.dof], e.component, e.weight});
            for (const auto &e : active[k].node->forces)
              if (body_of(active[k], e.body) == b)
                {
                  forces[k].push_back({index[e.dof], e.component, e.weight});
                  is_force_dof[index[e.dof]] = true;
                }
          }

        // The columns of C at the force dofs (m x m, column major): from
        // the body's Cholesky factor when it has one, else by solves.
        // Only the columns at the force dofs of this iteration's active
        // nodes are formed, not those of the whole declared area.
        bool              from_factor = true;
        std::vector<long> position(m, -1), force_positions;
        for (unsigned int i = 0; i < m && from_factor; ++i)
          {
            position[i] = bodies[b]->contact_dof_position(dofs[i]);
            from_factor = position[i] >= 0;
            if (is_force_dof[i])
              force_positions.push_back(position[i]);
          }
        from_factor = from_factor &&
                      bodies[b]->prepare_contact_compliance(force_positions);
        std::vector<double> C(std::size_t(m) * m, 0.);
        for (unsigned int j = 0; j < m; ++j)
          if (is_force_dof[j])
            {
              double *c = &C[std::size_t(j) * m];
              if (from_factor)
                for (unsigned int i = 0; i < m; ++i)
                  c[i] = bodies[b]->contact_compliance(position[i], position[j]);
              else
                {
                  const Vector<double> &x = column(b, dofs[j]);
                  for (unsigned int i = 0; i < m; ++i)
                    c[i] = x(dofs[i]);
                }
            }

        std::vector<double> t(m);
        for (unsigned int l = 0; l < n; ++l)
          for (unsigned int col = 0; col < 2 && !forces[l].empty(); ++col)
            {
              std::fill(t.begin(), t.end(), 0.);
              for (const auto &f : forces[l])
                {
                  const double coefficient =
                    f.weight * frame(*active[l].node, col)[f.component];
                  const double *c = &C[std::size_t(f.index) * m];
                  for (unsigned int i = 0; i < m; ++i)
                    t[i] += coefficient * c[i];
                }
              for (unsigned int k = 0; k < n; ++k)
                {
                  if (kinematics[k].empty())
                    continue;
                  ComplianceMatrix::Block block = {{{{0., 0.}}, {{0., 0.}}}};
                  for (const auto &e : kinematics[k])
                    {
                      const double v = e.weight * t[e.index];
                      for (unsigned int row = 0; row < 2; ++row)
                        block[row][col] +=
                          frame(*active[k].node, row)[e.component] * v;
                    }
                  W.add_block(k, l, block);
                }
            }
      }
    compliance_scope.stop();

    TimerOutput::Scope local_solve_scope(timer, timing::local_solve);
    BiPotentialSolver::Settings settings;
    const auto &first = active[0].pair->settings();
    settings.beta               = first.beta;
    settings.residual_tolerance = first.tolerance;
    settings.change_tolerance   = first.tolerance;
    settings.max_sweeps         = first.max_sweeps;
    settings.rho_choice =
      BiPotentialSolver::RhoChoice::largest_diagonal_compliance;
    result = BiPotentialSolver(settings).solve(W, u_free, mu, r);
    local_solve_scope.stop();
    if (!result.converged)
      return false;

    // Corrector du = du_lib + K^-1 H^T r with the current tangent, and the
    // contact forces H^T r.
    for (unsigned int k = 0; k < n; ++k)
      {
        ContactNode &node = *active[k].node;
        node.reaction     = {{r[k][0], r[k][1]}};
        node.status       = result.status[k];
        const Tensor<1, 2> force = node.force();
        for (const auto &e : node.forces)
          contact_forces[body_of(active[k], e.body)](e.dof) +=
            e.weight * force[e.component];
      }
    if (const char *debug = std::getenv("GLISSADE_DEBUG");
        debug != nullptr && std::string(debug) == "2")
      for (unsigned int k = 0; k < n; ++k)
        std::cerr << "      node " << active[k].node->vertex << " segment "
                  << active[k].node->segment << " s " << active[k].node->s
                  << " gap " << active[k].node->gap << " r "
                  << r[k][0] << ' ' << r[k][1] << std::endl;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (contact_forces[b].linfty_norm() > 0.)
        {
          Vector<double> correction;
          bodies[b]->solve_homogeneous(contact_forces[b], correction);
          increments[b] += correction;
        }
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->set_contact_forces(contact_forces[b]);
    return true;
  }
} // namespace glissade
