// What a time scheme asks of the contact by default: Signorini's and
// Coulomb's laws on the end positions, the step's mean force reported.

#include <glissade/contact/step/contact_problem.h>
#include <glissade/time/time_scheme.h>

namespace glissade
{
  void
  TimeScheme::attach(ContactProblem &contact,
                     const TimeIntegrationSettings &) const
  {
    // The contact force of the step's equation is F_c = P / (w dt): the
    // outputs report the step's mean force P / dt.
    contact.report_forces_scaled_by(contact_impulse_weight());
  }



  void
  TimeScheme::begin_contact_step(ContactProblem &,
                                 const double,
                                 const double) const
  {}
} // namespace glissade
