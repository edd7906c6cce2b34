#pragma once

#include <glissade/body/body.h>
#include <glissade/body/energy_account.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/description/scene_description.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * How a step from t_start to t is made of the bodies' equations: the
   * part of the run that time integration owns, so that the load program
   * (Simulation: steps, Newton, cut-back, output) is the same for every
   * scheme, as Lethe's time-stepping classes are beside its solvers.
   *
   * - Time integration/Scheme = quasi-static: t is a load parameter and a
   *   step is an equilibrium; nothing to do.
   * - A scheme with inertia (newmark, moreau-jean, generalized-alpha,
   *   hht-alpha: TimeSchemeRegistry): every body gets a BodyInertia that
   *   applies the scheme's formulas, whose terms its assembly adds; a step
   *   begins from the accepted state, and the state it converges to is
   *   accepted before the next. Every scheme takes the contact as the
   *   step's impulse, with the law it asks of the contact
   *   (TimeScheme::attach).
   *
   * A scheme is one file in source/time/ and one line in
   * time_scheme_registry.cc (doc/adding_a_time_scheme.md); this class is
   * the same for every one.
   */
  class TimeIntegrator
  {
  public:
    virtual ~TimeIntegrator() = default;

    /**
     * The scheme the scene asks for. Under a dynamic one each body's
     * inertia holds its rigid motions (before the contact problem checks
     * that something does): call before building the ContactProblem, and
     * attach() after it.
     */
    static std::unique_ptr<TimeIntegrator>
    create(const SceneDescription                   &scene,
           const std::vector<std::unique_ptr<Body>> &bodies);

    /** True for a scheme with inertia. */
    virtual bool
    dynamic() const = 0;

    /**
     * With the contact problem built (its boundaries are the massless
     * ones of a redistributed mass): gives each body what the scheme
     * adds to its assembly.
     */
    virtual void
    attach(ContactProblem &contact) = 0;

    /** At t = 0 of a fresh run (not a restart): the initial state. */
    virtual void
    initialize() = 0;

    /** Before the Newton iterations of a step (and of each cut-back). */
    virtual void
    begin_step(const double t_start, const double t) = 0;

    /**
     * After a converged step ending at t: its end state becomes the start
     * state, and its energies are accounted.
     */
    virtual void
    accept_step(const double t) = 0;

    /**
     * The energies so far (EnergyAccount), for the history and the
     * checkpoint; nullptr for a scheme without inertia.
     */
    virtual EnergyAccount *
    energies()
    {
      return nullptr;
    }
  };
} // namespace glissade
