#include <glissade/base/input_error.h>
#include <glissade/body/body_measures.h>
#include <glissade/solver/time_integrator.h>

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
      attach(const ContactProblem &) override
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
     * A scheme with inertia: each body gets a BodyInertia (the scheme's
     * formulas are there), whose terms its assembly adds; the contact step
     * works unchanged on the dynamic tangent. Newmark (the default law on
     * positions) and Moreau-Jean (the law on velocities) differ in which
     * nodes a step enforces and on what (begin_contact_step()).
     */
    class WithInertia : public TimeIntegrator
    {
    public:
      WithInertia(const SceneDescription                   &scene,
                  const std::vector<std::unique_ptr<Body>> &bodies)
        : scene(scene)
        , bodies(bodies)
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
      attach(const ContactProblem &contact_problem) override
      {
        contact = const_cast<ContactProblem *>(&contact_problem);
        for (const auto &body : bodies)
          {
            // The dofs the contact pairs touch: the redistributed mass
            // takes theirs away.
            std::set<types::global_dof_index> massless;
            for (const auto &pair : contact->contact_pairs())
              for (const auto dof : pair->contact_dofs(*body))
                massless.insert(dof);
            body->set_inertia(
              std::make_unique<BodyInertia>(*body,
                                            scene.time_integration,
                                            massless,
                                            scene.source + ": Body " +
                                              body->name()));
          }
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
        begin_contact_step(t_start, dt);
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

    protected:
      /** After the detection of a step from t_start of length dt. */
      virtual void
      begin_contact_step(const double t_start, const double dt) = 0;

      const SceneDescription                   &scene;
      const std::vector<std::unique_ptr<Body>> &bodies;
      ContactProblem                           *contact = nullptr;

    private:
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
              node.start_gap = std::numeric_limits<double>::quiet_NaN();
              if (!node.projected)
                continue;
              node.start_gap = node.linearization.gap;
              if (pair->master() == nullptr)
                {
                  Point<2> x = node.reference_position;
                  for (unsigned int d = 0; d < 2; ++d)
                    x[d] += pair->slave().displacement()(node.dofs[d]);
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



    /**
     * Newmark's implicit scheme with the contact implicit (Kane, Repetto,
     * Ortiz & Marsden 1999): the smooth forces by Newmark's rule, the
     * contact by the step's impulse P, its law on the end positions, every
     * node within the alert distance (the quasi-static step's). The end
     * state's equation carries the contact force F_c = 2 P / dt, which the
     * outputs report halved (the step's mean force P / dt). Its work over
     * the step, P . du / dt, is then -P_N g_n - mu P_N |slip| <= 0: the
     * contact never creates energy (doc/theory.md, "Energy").
     */
    class Newmark : public WithInertia
    {
    public:
      using WithInertia::WithInertia;

      void
      attach(const ContactProblem &contact_problem) override
      {
        WithInertia::attach(contact_problem);
        for (const auto &pair : contact->contact_pairs())
          pair->report_forces_scaled_by(0.5);
      }

    protected:
      void
      begin_contact_step(const double, const double) override
      {}
    };



    /**
     * Moreau and Jean's theta-method (Jean 1999; Feng, Joli, Cros &
     * Magnain 2005 with the bi-potential local solver): Signorini's law on
     * the end normal velocity and the step's impulses, for the nodes whose
     * gap closes by the step's theta point, g_n + (1 - theta) dt U_N <= 0,
     * and that do not move away. With U = H v_n the relative velocity at
     * the start, the end velocity's law is the position law shifted: U_N,n+1
     * >= 0 is g(u) - g_n - (1 - theta) dt U_N,n >= 0 to first order.
     * Coulomb's law holds on the step's slip. A node that does not close
     * keeps Signorini's law on its end position, g >= min(g_n, 0).
     *
     * The velocity law needs the contact nodes' mass (Contact mass =
     * kept): a node without mass has no velocity of its own (the scheme's
     * u_n+1 = u_n + dt (theta v_n+1 + (1 - theta) v_n) makes its v ring
     * from step to step at theta = 1/2), and a law on it lets nodes through
     * the master. With the mass redistributed, the law is Signorini's on
     * the end positions, as Newmark's, whose impulse does no positive work
     * either (doc/theory.md, "Energy").
     */
    class MoreauJean : public WithInertia
    {
    public:
      MoreauJean(const SceneDescription                   &scene,
                 const std::vector<std::unique_ptr<Body>> &bodies)
        : WithInertia(scene, bodies)
      {}

      void
      attach(const ContactProblem &contact_problem) override
      {
        WithInertia::attach(contact_problem);
        if (!scene.time_integration.redistribute_contact_mass)
          contact->use_velocity_law();
        // The local problem's unknown is the step's impulse over theta
        // dt; the outputs report the mean force, the impulse over dt.
        for (const auto &pair : contact->contact_pairs())
          pair->report_forces_scaled_by(scene.time_integration.theta);
      }

    protected:
      void
      begin_contact_step(const double t_start, const double dt) override
      {
        if (contact->position_law())
          return;
        const double theta = scene.time_integration.theta;
        for (const auto &pair : contact->contact_pairs())
          {
            const std::array<const Body *, 2> body = {
              {&pair->slave(), pair->master()}};
            const auto velocity_along = [&](const DofVector &row) {
              double value = 0.;
              for (const DofCoefficient &e : row)
                if (body[e.body] != nullptr)
                  value += e.value * body[e.body]->inertia()->velocity()(e.dof);
              return value;
            };
            for (ContactNode &node : pair->nodes())
              {
                node.law_shift = {{0., 0.}};
                if (!node.active)
                  continue;
                const ContactLinearization &l   = node.linearization;
                double                      U_N = velocity_along(l.gap_row);
                // Relative to a moving obstacle's material under the node;
                // the gap at the start is to the obstacle as it stood then
                // (record_start_gaps()).
                const double start_gap = node.start_gap;
                if (body[1] == nullptr)
                  {
                    Point<2> x = node.reference_position;
                    for (unsigned int d = 0; d < 2; ++d)
                      x[d] += pair->slave().displacement()(node.dofs[d]);
                    U_N -=
                      node.normal * pair->surface().velocity_at(x, t_start);
                  }
                if (start_gap + (1. - theta) * dt * U_N > 0.)
                  {
                    // A node that does not close by the theta point keeps
                    // Signorini's law on its end position, g >= min(g_n,
                    // 0): it may open, and it may close within the step
                    // but not pass the master (or, behind it, go further).
                    // Its impulse's work on the step's motion, P (g -
                    // g_n), is then -P g_n <= 0 or zero. (Left out of the
                    // step, as Moreau's index set leaves it, a node whose
                    // start velocity rang away from the master at theta =
                    // 1/2 went behind it by dt times its speed and stayed
                    // there: a block resting on a rough floor tilted by
                    // 1e-4 and was held so by friction.)
                    node.law_shift = {{0., -std::min(start_gap, 0.)}};
                    continue;
                  }
                // The impulse works on the step's mean velocity, theta
                // U_n+1 + (1 - theta) U_n = du / dt. An approaching node
                // (U_N,n <= 0) takes Jean's law, U_N,n+1 >= 0: the normal
                // work (1 - theta) P_N U_N,n is <= 0. A node behind the
                // master that moves away (U_N,n > 0) may not come back
                // within the step, g - g_n >= 0: its normal work is zero
                // (on the end velocity its impulse would work positively).
                // Coulomb's law holds on the step's slip: the friction's
                // work is - mu P_N |slip| <= 0 (on the end velocity alone,
                // a slip that reverses within the step would create
                // energy).
                node.law_shift = {
                  {0., -start_gap - (1. - theta) * dt * std::min(U_N, 0.)}};
              }
          }
      }
    };
  } // namespace



  std::unique_ptr<TimeIntegrator>
  TimeIntegrator::create(const SceneDescription                   &scene,
                         const std::vector<std::unique_ptr<Body>> &bodies)
  {
    switch (scene.time_integration.scheme)
      {
        case TimeIntegrationSettings::Scheme::newmark:
          return std::make_unique<Newmark>(scene, bodies);
        case TimeIntegrationSettings::Scheme::moreau_jean:
          return std::make_unique<MoreauJean>(scene, bodies);
        case TimeIntegrationSettings::Scheme::quasi_static:
          break;
      }
    for (const auto &body : bodies)
      if (body->description_of_body().turning_frame.active())
        throw InputError(scene.source + ": Body " + body->name() +
                           "/Turning frame/Angular velocity",
                         "a turning frame's forces act on the body's inertia: "
                         "choose a dynamic scheme (Time integration/Scheme = "
                         "newmark or moreau-jean), or leave the entry empty");
    return std::make_unique<QuasiStatic>();
  }
} // namespace glissade
