#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/solver/time_integrator.h>
#include <glissade/time/time_scheme_registry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** t is a load parameter, a step an equilibrium. */
    class QuasiStatic : public TimeIntegrator
    {
    public:
      bool
      dynamic() const override
      {
        return false;
      }
      void
      attach(ContactProblem &) override
      {}
      void
      initialize() override
      {}
      void
      begin_step(const double, const double) override
      {}
      void
      accept_step(const double) override
      {}
    };



    /**
     * A scheme with inertia: each body gets a BodyInertia that applies the
     * scheme's formulas (InertiaScheme), whose terms its assembly adds; the
     * contact step works on the dynamic tangent with the law the scheme
     * asks of it (TimeScheme::attach, begin_contact_step). What is the
     * same for every scheme is here: the initial acceleration, the start
     * gaps of a step, the energy account of each accepted step.
     */
    class WithInertia : public TimeIntegrator
    {
    public:
      WithInertia(const SceneDescription                   &scene,
                  const std::vector<std::unique_ptr<Body>> &bodies,
                  std::shared_ptr<const TimeScheme>         scheme)
        : scene(scene)
        , bodies(bodies)
        , scheme(std::move(scheme))
      {
        for (const auto &body : bodies)
          body->system().hold_rigid_motions_by_inertia();
      }

      bool
      dynamic() const override
      {
        return true;
      }

      void
      attach(ContactProblem &contact_problem) override
      {
        contact = &contact_problem;
        for (const auto &body : bodies)
          {
            // The dofs the contact pairs touch: the redistributed mass
            // takes theirs away.
            const std::vector<types::global_dof_index> dofs =
              contact->contact_dofs(*body);
            std::set<types::global_dof_index> massless(dofs.begin(),
                                                       dofs.end());
            body->set_inertia(
              std::make_unique<BodyInertia>(*body,
                                            scene.time_integration,
                                            scheme,
                                            massless,
                                            scene.source + ": Body " +
                                              body->name()));
          }
        scheme->attach(*contact, scene.time_integration);
      }

      void
      initialize() override
      {
        // The acceleration that balances the loads at t = 0 (no inertia
        // terms yet: the inertia has no step; the viscous stress of the
        // initial velocity is assembled).
        for (const auto &body : bodies)
          {
            body->inertia()->set_initial_velocity(*body);
            body->set_time(0.);
            body->assemble();
            Vector<double> residual = body->unbalanced_forces();
            residual *= -1.;
            body->inertia()->initialize(*body, residual);
          }
        account = EnergyAccount();
        measure_energies();
        account.initial = account.kinetic + account.strain;
      }

      void
      begin_step(const double t_start, const double t) override
      {
        const double dt = step_length(t_start, t);
        for (const auto &body : bodies)
          body->inertia()->begin_step(body->displacement(), dt, t);
        record_start_gaps(t_start, dt);
        scheme->begin_contact_step(*contact, t_start, dt);
      }

      void
      accept_step(const double t) override
      {
        const double contact_work_before = account.contact_work;
        for (const auto &body : bodies)
          body->inertia()->accept_step(*body, account);
        // A rigid obstacle that moves works on the bodies through its
        // contact as a prescribed motion does: that is the work of the
        // loads and supports. The contact's own work, on the relative
        // motion, is r_t slip + r_n (g_n+1 - g_n) at each node (which its
        // law makes <= 0); the rest of what its forces did on the slave's
        // dofs is the obstacle's (on a curved obstacle that turns under a
        // node, the relative motion is along the curve, not the chord the
        // dofs' displacement takes).
        double obstacle_work = 0.;
        for (const auto &pair : contact->contact_pairs())
          if (pair->master() == nullptr)
            {
              const Body    &slave = pair->slave();
              Vector<double> du    = slave.displacement();
              du -= slave.stored_displacement();
              const auto on_slave = [&](const DofVector &row) {
                double value = 0.;
                for (const DofCoefficient &e : row)
                  if (e.body == 0)
                    value += e.value * du(e.dof);
                return value;
              };
              for (const ContactNode &node : pair->nodes())
                if (node.active)
                  {
                    const ContactLinearization &l = node.linearization;
                    const std::array<double, 2> r =
                      pair->reported_reaction(node);
                    const double received =
                      r[0] * on_slave(l.tangential_force) +
                      r[1] * on_slave(l.normal_force);
                    const double relative =
                      r[0] * l.slip + r[1] * (std::isfinite(node.start_gap) ?
                                                l.gap - node.start_gap :
                                                0.);
                    obstacle_work += received - relative;
                  }
            }
        account.contact_work -= obstacle_work;
        account.work_of_loads += obstacle_work;
        account.record_step_contact_work(account.contact_work -
                                           contact_work_before,
                                         t);
        // Friction dissipates - r_t times the slip of the step at each
        // node in contact (the slip since the step began, along t).
        for (const auto &pair : contact->contact_pairs())
          for (const ContactNode &node : pair->nodes())
            if (node.active)
              account.friction_dissipation -=
                pair->reported_reaction(node)[0] * node.linearization.slip;
        measure_energies();
      }

      EnergyAccount *
      energies() override
      {
        return &account;
      }

    private:
      const SceneDescription                   &scene;
      const std::vector<std::unique_ptr<Body>> &bodies;
      const std::shared_ptr<const TimeScheme>   scheme;
      ContactProblem                           *contact = nullptr;

      /**
       * Each node's gap at the step's start, to the master as it stood
       * then: the detection's gap (the node at u_n) to an obstacle moved
       * back by its motion over the step (the detection takes it at the
       * step's end). NaN for a node without a counterpart.
       */
      void
      record_start_gaps(const double t_start, const double dt)
      {
        for (const auto &pair : contact->contact_pairs())
          for (ContactNode &node : pair->nodes())
            {
              node.start_gap         = std::numeric_limits<double>::quiet_NaN();
              node.start_gap_in_dofs = node.start_gap;
              if (!node.projected)
                continue;
              node.start_gap         = node.linearization.gap;
              node.start_gap_in_dofs = node.linearization.gap;
              if (pair->master() == nullptr)
                {
                  const Point<2> x =
                    node.reference_position +
                    node.displacement(pair->slave().displacement());
                  node.start_gap +=
                    dt * (node.normal *
                          pair->surface().velocity_at(x, t_start + 0.5 * dt));
                }
            }
      }

      void
      measure_energies()
      {
        account.kinetic = account.strain = 0.;
        for (const auto &body : bodies)
          {
            account.kinetic += body->inertia()->kinetic_energy();
            account.strain += strain_energy(*body);
          }
      }

      /**
       * The step's length as the load program means it: its stage's
       * (t_end - t_begin) / n, halved by each cut-back, where t - t_start
       * is that to round-off. Equal steps then have the same length to the
       * bit (t - t_start differs in its last bits as t grows: 1e-13 of dt
       * at t = 3 with dt = 0.005), which keeps the tangent's inertia
       * terms, 1 / (beta dt^2) M, the same matrix from step to step (a
       * tangent changed in its last bit is factorised anew), and a run
       * restarted from a checkpoint takes the same steps as one that was
       * not interrupted.
       */
      double
      step_length(const double t_start, const double t) const
      {
        const double dt     = t - t_start;
        const auto  &stages = scene.load_program;
        double       begin  = 0.;
        for (unsigned int s = 0; s < stages.stage_end_times.size(); ++s)
          {
            const double end = stages.stage_end_times[s];
            if (t <= end + 1e-12 * std::abs(end))
              {
                double nominal = (end - begin) / stages.stage_increments[s];
                for (unsigned int depth = 0; depth <= stages.max_cut_back_depth;
                     ++depth, nominal *= 0.5)
                  if (std::abs(dt - nominal) <= 1e-11 * nominal)
                    return nominal;
                return dt;
              }
            begin = end;
          }
        return dt;
      }

      EnergyAccount account;
    };



  } // namespace



  std::unique_ptr<TimeIntegrator>
  TimeIntegrator::create(const SceneDescription                   &scene,
                         const std::vector<std::unique_ptr<Body>> &bodies)
  {
    const auto                       &settings = scene.time_integration;
    std::shared_ptr<const TimeScheme> scheme =
      TimeSchemeRegistry::entry(settings.scheme)
        .create(settings.scheme_settings);
    if (scheme->has_inertia())
      return std::make_unique<WithInertia>(scene, bodies, scheme);
    for (const auto &body : bodies)
      if (body->description_of_body().turning_frame.active())
        throw InputError(scene.source + ": Body " + body->name() +
                           "/Turning frame/Angular velocity",
                         "a turning frame's forces act on the body's inertia: "
                         "choose a dynamic scheme (Time integration/Scheme = "
                         "one of " +
                           TimeSchemeRegistry::names_with_inertia() +
                           "), or leave the entry empty");
    return std::make_unique<QuasiStatic>();
  }
} // namespace glissade
