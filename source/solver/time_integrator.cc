#include <glissade/solver/time_integrator.h>

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
      accept_step() override
      {}
    };



    /**
     * Newmark's implicit scheme (BodyInertia has the formulas): each body's
     * inertia terms in its assembly, the contact step unchanged on the
     * dynamic tangent.
     */
    class Newmark : public TimeIntegrator
    {
    public:
      Newmark(const SceneDescription                   &scene,
              const std::vector<std::unique_ptr<Body>> &bodies)
        : scene(scene)
        , bodies(bodies)
      {
        for (const auto &body : bodies)
          body->hold_rigid_motions_by_inertia();
      }

      bool
      dynamic() const override
      {
        return true;
      }

      void
      attach(const ContactProblem &contact_problem) override
      {
        contact = &contact_problem;
        const ContactProblem &contact = contact_problem;
        for (const auto &body : bodies)
          {
            // The dofs the contact pairs touch: the redistributed mass
            // takes theirs away.
            std::set<types::global_dof_index> massless;
            for (const auto &pair :
                 const_cast<ContactProblem &>(contact).contact_pairs())
              for (const auto dof : pair->contact_dofs(*body))
                massless.insert(dof);
            body->set_inertia(std::make_unique<BodyInertia>(
              *body,
              scene.time_integration,
              massless,
              scene.source + ": Body " + body->name()));
          }
      }

      void
      initialize() override
      {
        // The acceleration that balances the loads at t = 0 (no inertia
        // terms yet: the inertia has no step).
        for (const auto &body : bodies)
          {
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
        for (const auto &body : bodies)
          body->inertia()->begin_step(body->displacement(), t - t_start);
      }

      void
      accept_step() override
      {
        for (const auto &body : bodies)
          body->inertia()->accept_step(*body, account);
        // Friction dissipates - r_t times the slip of the step at each
        // node in contact (the slip since the step began, along t).
        for (const auto &pair :
             const_cast<ContactProblem *>(contact)->contact_pairs())
          for (const ContactNode &node : pair->nodes())
            if (node.active)
              account.friction_dissipation -=
                node.reaction[0] * node.linearization.slip;
        measure_energies();
      }

      EnergyAccount *
      energies() override
      {
        return &account;
      }

    private:
      void
      measure_energies()
      {
        account.kinetic = account.strain = 0.;
        for (const auto &body : bodies)
          {
            account.kinetic += body->inertia()->kinetic_energy();
            account.strain += body->strain_energy();
          }
      }

      const SceneDescription                   &scene;
      const std::vector<std::unique_ptr<Body>> &bodies;
      const ContactProblem                     *contact = nullptr;
      EnergyAccount                             account;
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
        case TimeIntegrationSettings::Scheme::quasi_static:
          break;
      }
    return std::make_unique<QuasiStatic>();
  }
} // namespace glissade
