#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

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
    /**
     * What the scheme itself dissipates: Moreau-Jean's for theta > 1/2,
     * (theta - 1/2) (|v_n+1 - v_n|_M^2 + du . (F_int,n+1 - F_int,n)) a
     * step; zero for Newmark's trapezoidal rule.
     */
    double scheme_dissipation = 0.;

    /**
     * The steps whose contact did positive work on the bodies (created
     * energy) beyond round-off, 1e-8 of the energies at stake: how many,
     * what they created in all, the largest and when, and the end times of
     * the first ten. Every scheme's contact law makes the work of each
     * step <= 0 (doc/theory.md, "Energy"); a step that breaks it is
     * reported in the summary.
     */
    unsigned int        contact_creating_steps = 0;
    double              contact_created        = 0.;
    double              largest_created = 0., largest_created_at = 0.;
    std::vector<double> contact_creating_times;

    /** The contact's work over the step that ended at t (all bodies). */
    void
    record_step_contact_work(const double work, const double t)
    {
      // (the energies at stake: a step's work within 1e-8 of them is the
      // round-off of a body at rest, whose energies are its weight's)
      const double scale = std::max({initial,
                                     kinetic + strain,
                                     std::abs(work_of_loads),
                                     friction_dissipation});
      if (!(work > 1e-8 * scale))
        return;
      ++contact_creating_steps;
      contact_created += work;
      if (work > largest_created)
        {
          largest_created    = work;
          largest_created_at = t;
        }
      if (contact_creating_times.size() < 10)
        contact_creating_times.push_back(t);
    }

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
             damping_dissipation + scheme_dissipation;
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      // clang-format off
      archive & kinetic & strain & initial & work_of_loads & contact_work
              & friction_dissipation & damping_dissipation
              & scheme_dissipation & contact_creating_steps & contact_created
              & largest_created & largest_created_at
              & contact_creating_times;
      // clang-format on
    }
  };
} // namespace glissade
