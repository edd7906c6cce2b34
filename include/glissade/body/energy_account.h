#pragma once

namespace glissade
{
  /**
   * The energies of a dynamic run, summed over the bodies (history items
   * `energies`): the kinetic energy K = 1/2 v.M v and the stored energy U
   * = int W dV of the current state, and the work done on the bodies since
   * t = 0, each by the trapezoidal rule over the steps, W += 1/2 (f_n +
   * f_n+1).(u_n+1 - u_n):
   * - by the loads and the supports (weight, tractions, pressure, nodal
   *   loads, prescribed motions),
   * - by the contact forces, split into what friction dissipates (- r_t
   *   times the slip of each step, at each slave node) and the rest, what
   *   the normal contact dissipates (at impacts and releases),
   * - by the damping, mass and stiffness proportional (dissipated).
   * The balance K + U - K_0 - U_0 - W_loads - W_contact + D_damping is zero
   * for an exact integration; Newmark's trapezoidal rule makes it so for a
   * linear body, and its departure measures the scheme's energy error.
   */
  struct EnergyAccount
  {
    double kinetic              = 0.;
    double strain               = 0.;
    double initial              = 0.; // K_0 + U_0
    double work_of_loads        = 0.;
    double contact_work         = 0.;
    double friction_dissipation = 0.;
    double damping_dissipation  = 0.;

    /** What the normal contact dissipated: - W_contact - D_friction. */
    double
    contact_dissipation() const
    {
      return -contact_work - friction_dissipation;
    }

    double
    balance() const
    {
      return kinetic + strain - initial - work_of_loads - contact_work +
             damping_dissipation;
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      // clang-format off
      archive & kinetic & strain & initial & work_of_loads & contact_work
              & friction_dissipation & damping_dissipation;
      // clang-format on
    }
  };
} // namespace glissade
