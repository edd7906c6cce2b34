// Time integration/Scheme = newmark: Newmark's implicit scheme with the
// contact implicit (Kane, Repetto, Ortiz & Marsden 1999), and its entries
// Newmark beta and Newmark gamma.

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/time/time_scheme.h>

#include <any>
#include <cmath>
#include <memory>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    struct NewmarkSettings
    {
      double beta  = 0.25;
      double gamma = 0.5;
    };

    /**
     * Newmark's scheme: from the state (u_n, v_n, a_n) over a step dt, with
     * the predictors u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n and v~ = v_n
     * + (1 - gamma) dt a_n, the end state's a(u) = (u - u~) / (beta dt^2)
     * and v(u) = v~ + gamma dt a(u), and the equation of motion that of the
     * end state. The smooth forces by Newmark's rule, the contact by the
     * step's impulse P = dt F_c / 2, its law on the end positions, every
     * node within the alert distance (the quasi-static step's): its work
     * over the step, P . du / dt, is -P_N g_n - mu P_N |slip| <= 0, so the
     * contact never creates energy (doc/theory.md, "Energy").
     */
    class NewmarkScheme : public TimeScheme
    {
    public:
      explicit NewmarkScheme(const NewmarkSettings &settings)
        : settings(settings)
      {}

      StepCoefficients
      predict(const Vector<double> &u_n,
              const Vector<double> &v_n,
              const Vector<double> &a_n,
              const double          dt,
              Vector<double>       &u_predicted,
              Vector<double>       &v_predicted) const override
      {
        const double beta = settings.beta, gamma = settings.gamma;
        u_predicted = u_n;
        u_predicted.add(dt, v_n, dt * dt * (0.5 - beta), a_n);
        v_predicted = v_n;
        v_predicted.add((1. - gamma) * dt, a_n);
        const double c_a = 1. / (beta * dt * dt);
        return {c_a, gamma / (beta * dt), c_a, (0.5 - gamma) * dt};
      }

      double
      contact_impulse_weight() const override
      {
        return 0.5;
      }

      bool
      predictor_takes_acceleration() const override
      {
        return true;
      }

      void
      start_state_forces(const StartState &state,
                         Vector<double>   &carried) const override
      {
        // The rows with mass carry nothing of the start state; those
        // without mass the trapezoidal rule's mean, f_n+1 + f_n + F_c = 0.
        carried.reinit(state.forces.size());
        carried_by_rows_without_mass(state, carried);
      }

    private:
      const NewmarkSettings settings;
    };
  } // namespace



  void
  declare_newmark_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Newmark beta",
                      "0.25",
                      Patterns::Double(0., 0.5),
                      "Newmark's beta, in (0, 0.5]; 0.25 with gamma = 0.5 "
                      "is the trapezoidal rule, second order and energy "
                      "conserving for a linear body.");
    prm.declare_entry("Newmark gamma",
                      "0.5",
                      Patterns::Double(0.5, 1.),
                      "Newmark's gamma, in [0.5, 1]: above 0.5 the scheme "
                      "damps high frequencies (first order); unconditionally "
                      "stable for beta >= (gamma + 1/2)^2 / 4.");
  }



  std::any
  parse_newmark_parameters(const ParameterHandler &prm,
                           const std::string      &where)
  {
    NewmarkSettings settings;
    settings.beta  = prm.get_double("Newmark beta");
    settings.gamma = prm.get_double("Newmark gamma");
    if (!(settings.beta > 0.))
      throw InputError(where + "Newmark beta",
                       "must be > 0 (beta = 0 is the explicit central "
                       "difference scheme, which glissade does not "
                       "implement)");
    const double stable = 0.25 * std::pow(settings.gamma + 0.5, 2);
    if (settings.beta < stable - 1e-12)
      throw InputError(where + "Newmark beta",
                       "is " + std::to_string(settings.beta) +
                         ": below (gamma + 1/2)^2 / 4 = " +
                         std::to_string(stable) +
                         " the scheme is only conditionally stable; raise "
                         "beta or lower Newmark gamma");
    return settings;
  }



  std::unique_ptr<TimeScheme>
  make_newmark_scheme(const std::any &settings)
  {
    return std::make_unique<NewmarkScheme>(
      std::any_cast<NewmarkSettings>(settings));
  }
} // namespace glissade
