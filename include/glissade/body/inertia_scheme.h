#pragma once

#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace glissade
{
  /**
   * The formulas of a one-step implicit scheme that a body's inertia
   * (BodyInertia) applies: what a time scheme tells a body, and all it
   * tells it. The schemes themselves (source/time/, one file each) also
   * say what they ask of the contact (TimeScheme); a body sees only this.
   *
   * Every scheme here writes a step of length dt from the accepted state
   * (u_n, v_n, a_n) as the quasi-static equation of its end state, in
   * which the end velocity and acceleration are linear in the end
   * displacement u about predictors u~, v~:
   *
   *   v(u) = v~ + c_v (u - u~),   a(u) = c_a (u - u~),
   *
   * and the equation is
   *
   *   M (c_M (u - u~) + a_M v(u)) + F_int(u) + F_v = F_ext + f_carried
   *                                                  + F_c,
   *
   * f_carried being the forces of the start state the step carries as
   * loads (start_state_forces()). Its tangent gains (c_M + a_M c_v) M.
   * The contact acts by the step's impulse P = w dt F_c (w:
   * contact_impulse_weight()), the law it obeys being the contact's.
   */
  class InertiaScheme
  {
  public:
    virtual ~InertiaScheme() = default;

    /** The coefficients of a step's end state (see the class). */
    struct StepCoefficients
    {
      /** c_M: the inertia force of the step's equation, M c_M (u - u~). */
      double inertia = 0.;
      /** c_v: v(u) = v~ + c_v (u - u~). */
      double velocity = 0.;
      /** c_a: a(u) = c_a (u - u~). */
      double acceleration = 0.;
      /**
       * What the velocity takes of q = M^-1 F_c beyond what v(u) counts,
       * so that the impulse changes it by M^-1 P = w dt q: the inertia
       * force balances F_c by u - u~ = q / c_M, which v(u) counts as c_v /
       * c_M q, so w dt - c_v / c_M (used where the predictor takes the
       * acceleration; the scheme writes it in the form that keeps its own
       * round-off, Newmark's (1/2 - gamma) dt).
       */
      double impulse_velocity = 0.;
    };

    /**
     * The predictors u~ and v~ of a step of length dt from the accepted
     * state (u_n, v_n, a_n), a_n being the acceleration of the smooth
     * forces alone (the contact's impulse taken out), and the step's
     * coefficients.
     */
    virtual StepCoefficients
    predict(const dealii::Vector<double> &u_n,
            const dealii::Vector<double> &v_n,
            const dealii::Vector<double> &a_n,
            const double                  dt,
            dealii::Vector<double>       &u_predicted,
            dealii::Vector<double>       &v_predicted) const = 0;

    /**
     * w in P = w dt F_c: the step's contact impulse P from the contact
     * force F_c of the step's equation. The outputs report P / dt = w F_c
     * (the step's mean force), and the contact's work on the step's motion
     * is P . du / dt = w F_c . du.
     */
    virtual double
    contact_impulse_weight() const = 0;

    /**
     * True if the predictor takes the acceleration a_n: the impulse's share
     * of the end acceleration is then taken out of the next step's a_n
     * (a body whose contact dofs carry mass factorises its mass for it),
     * and the end velocity given the impulse's velocity change M^-1 P.
     */
    virtual bool
    predictor_takes_acceleration() const = 0;

    /** What start_state_forces() may use of the accepted state. */
    struct StartState
    {
      /** f = F_ext - F_int - F_v (with a turning frame's forces) on every
       *  dof, contact excluded. */
      const dealii::Vector<double> &forces;
      /** The free dofs without mass (the contact dofs of a redistributed
       *  mass), whose rows carry no inertia. */
      const std::vector<bool> &without_mass;
      /** M a_n, a_n the smooth acceleration (computed when called). */
      std::function<dealii::Vector<double>()> mass_times_acceleration;
      /** The mass damping's force a_M M v_n (computed when called). */
      std::function<dealii::Vector<double>()> mass_damping_force;
    };

    /**
     * The forces of the accepted state that the next step's equation
     * carries as loads (f_carried, every dof). A row without mass carries
     * no inertia: its equation is the step's impulse balance, dt ((1 - w)
     * f_n + w f_n+1) + P = 0, which the step writes as f_n+1 + (1 - w) / w
     * f_n + F_c = 0 (carried_by_rows_without_mass()).
     */
    virtual void
    start_state_forces(const StartState       &state,
                       dealii::Vector<double> &carried) const = 0;

  protected:
    /** (1 - w) / w f on the rows without mass, the others left as they
     *  are. */
    void
    carried_by_rows_without_mass(const StartState       &state,
                                 dealii::Vector<double> &carried) const
    {
      const double w = contact_impulse_weight();
      for (unsigned int i = 0; i < carried.size(); ++i)
        if (state.without_mass[i])
          carried(i) = (1. - w) / w * state.forces(i);
    }
  };
} // namespace glissade
