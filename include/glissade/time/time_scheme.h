#pragma once

#include <glissade/body/inertia_scheme.h>

namespace glissade
{
  class ContactProblem;
  struct TimeIntegrationSettings;

  /**
   * A time scheme (Time integration/Scheme): the formulas a body's inertia
   * applies (InertiaScheme), and what the scheme asks of the contact. One
   * file each in source/time/ defines the class, reads its own entries and
   * makes it; one line of time_scheme_registry.cc names it
   * (doc/adding_a_time_scheme.md).
   *
   * The run around the scheme is the same for every one
   * (TimeIntegrator: the initial acceleration, the start gaps of a step,
   * the energy account of each accepted step).
   */
  class TimeScheme : public InertiaScheme
  {
  public:
    /**
     * False for the quasi-static scheme: t is a load parameter, no body
     * has inertia, and nothing below is called.
     */
    virtual bool
    has_inertia() const
    {
      return true;
    }

    /**
     * With the contact problem built: the law its step enforces and the
     * scale of the forces it reports. By default Signorini's and Coulomb's
     * laws on the end positions (every node within the alert distance, as
     * the quasi-static step), the reported force the step's mean, w F_c.
     */
    virtual void
    attach(ContactProblem                &contact,
           const TimeIntegrationSettings &settings) const;

    /**
     * After the detection of a step from t_start of length dt, with each
     * node's start_gap recorded: the nodes' law shifts for the step
     * (ContactNode::law_shift). None by default.
     */
    virtual void
    begin_contact_step(ContactProblem &contact,
                       const double    t_start,
                       const double    dt) const;
  };
} // namespace glissade
