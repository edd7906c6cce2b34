#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/contact/contact_problem.h>

namespace glissade
{
  ContactProblem::ContactProblem(
    const SceneDescription                   &scene,
    const std::vector<std::unique_ptr<Body>> &bodies)
    : bodies(bodies)
  {
    const auto find = [&](const std::string &name) -> Body * {
      for (const auto &b : bodies)
        if (b->name() == name)
          return b.get();
      return nullptr;
    };
    for (const auto &c : scene.contacts)
      pairs.push_back(std::make_unique<ContactPair>(
        c,
        *find(c.slave_body),
        c.master_body == "rigid" ? nullptr : find(c.master_body),
        scene.source));
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
    Timer timer;
    for (auto &pair : pairs)
      pair->begin_step(time);
    detection_seconds += timer.wall_time();
  }



  unsigned int
  ContactProblem::n_active() const
  {
    unsigned int n = 0;
    for (const auto &pair : pairs)
      n += pair->n_active();
    return n;
  }



  bool
  ContactProblem::correct(std::vector<Vector<double>> &increments)
  {
    Timer detection;
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
    detection_seconds += detection.wall_time();

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

    // Compliance columns Y = K^-1 H_force^T, two per node and body.
    Timer                  compliance_timer;
    const unsigned int     n = active.size();
    std::vector<std::array<std::array<Vector<double>, 2>, 2>> Y(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int which = 0; which < 2; ++which)
        {
          const unsigned int b = body_of(active[k], which);
          if (b == numbers::invalid_unsigned_int)
            continue;
          for (unsigned int row = 0; row < 2; ++row)
            {
              Vector<double> f(bodies[b]->n_dofs());
              for (const auto &e : active[k].node->forces)
                if (e.body == which)
                  f(e.dof) += frame(*active[k].node, row)[e.component] * e.weight;
              bodies[b]->solve_homogeneous(f, Y[k][which][row]);
            }
        }

    // W_kl = H_kin,k Y_l and u_free_k, summing over the bodies of node k.
    ComplianceMatrix                            W;
    std::vector<BiPotentialSolver::Vector2>     u_free(n), r(n);
    std::vector<double>                         mu(n);
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

        for (unsigned int l = 0; l < n; ++l)
          {
            ComplianceMatrix::Block block = {{{{0., 0.}}, {{0., 0.}}}};
            bool                    coupled = false;
            for (const auto &e : node.kinematics)
              {
                const unsigned int b = body_of(active[k], e.body);
                for (unsigned int which = 0; which < 2; ++which)
                  if (body_of(active[l], which) == b)
                    {
                      coupled = true;
                      for (unsigned int row = 0; row < 2; ++row)
                        for (unsigned int col = 0; col < 2; ++col)
                          block[row][col] += frame(node, row)[e.component] *
                                             e.weight *
                                             Y[l][which][col](e.dof);
                    }
              }
            if (coupled)
              W.set_block(k, l, block);
          }
      }
    compliance_seconds += compliance_timer.wall_time();

    Timer                       local_timer;
    BiPotentialSolver::Settings settings;
    const auto &first = active[0].pair->settings();
    settings.beta               = first.beta;
    settings.residual_tolerance = first.tolerance;
    settings.change_tolerance   = first.tolerance;
    settings.max_sweeps         = first.max_sweeps;
    settings.rho_choice =
      BiPotentialSolver::RhoChoice::largest_diagonal_compliance;
    result = BiPotentialSolver(settings).solve(W, u_free, mu, r);
    local_solve_seconds += local_timer.wall_time();
    if (!result.converged)
      return false;

    // Corrector du = du_lib + K^-1 H^T r, and the contact forces H^T r.
    for (unsigned int k = 0; k < n; ++k)
      {
        ContactNode &node = *active[k].node;
        node.reaction     = {{r[k][0], r[k][1]}};
        node.status       = result.status[k];
        for (unsigned int which = 0; which < 2; ++which)
          {
            const unsigned int b = body_of(active[k], which);
            if (b == numbers::invalid_unsigned_int)
              continue;
            for (unsigned int row = 0; row < 2; ++row)
              increments[b].add(r[k][row], Y[k][which][row]);
          }
        const Tensor<1, 2> force = node.force();
        for (const auto &e : node.forces)
          contact_forces[body_of(active[k], e.body)](e.dof) +=
            e.weight * force[e.component];
      }
    for (unsigned int b = 0; b < bodies.size(); ++b)
      bodies[b]->set_contact_forces(contact_forces[b]);
    return true;
  }
} // namespace glissade
