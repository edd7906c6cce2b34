// Time integration/Scheme = generalized-alpha (Chung & Hulbert 1993) and
// hht-alpha (Hilber, Hughes & Taylor 1977, the family's member with alpha_m
// = 0), with their entry Spectral radius at infinity.

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/time/time_scheme.h>

#include <any>
#include <memory>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The method's four parameters (Newmark's: alpha_m = alpha_f = 0). */
    struct AlphaParameters
    {
      double alpha_m = 0., alpha_f = 0., beta = 0.25, gamma = 0.5;
    };

    /**
     * The generalised-alpha method, of which Newmark's scheme is the member
     * alpha_m = alpha_f = 0 (newmark.cc makes it so): Newmark's update of u and
     * v from a_n+1, the equation of motion at the intermediate point
     *
     *   M a_n+1-alpha_m + C v_n+1-alpha_f + F_int,n+1-alpha_f =
     *   F_ext,n+1-alpha_f,   x_n+1-alpha = (1 - alpha) x_n+1 + alpha x_n,
     *
     * divided by 1 - alpha_f so that the end state's F_int(u) stands alone:
     * the inertia force (1 - alpha_m) / (1 - alpha_f) M a(u), and the start
     * state's alpha_f / (1 - alpha_f) (F_ext - F_int - F_v - C v)_n -
     * alpha_m / (1 - alpha_f) M a_n carried as loads. Second order for
     * every rho_inf; a mode of frequency omega keeps its amplitude as omega
     * dt -> 0 and is multiplied by rho_inf per step as omega dt -> infinity
     * (Chung & Hulbert's choice of the four parameters from rho_inf makes
     * the three roots meet there).
     *
     * The contact acts by the step's impulse as in Newmark's scheme (Kane
     * et al.), P = dt F_c / 2, its law on the end positions. The end
     * equation's F_c gives the end acceleration (1 - alpha_f) / (1 -
     * alpha_m) M^-1 F_c, whose displacement, beta dt^2 times it, is that of
     * the impulse P given at tau within the step, dt - tau = 2 beta (1 -
     * alpha_f) / (1 - alpha_m) dt (0.51 dt for rho_inf = 0.8, dt for 0,
     * dt / 2 for 1); the velocity takes P's change M^-1 P and the next
     * predictor the smooth acceleration alone. The impulse's work on the
     * step's motion, P . du / dt, is -P_N g_n - mu P_N |slip| <= 0, as
     * Newmark's, and the kinetic energy it gives, P . v(tau) + |P|^2_M^-1
     * / 2, falls short of that work by (1/2 - tau / dt) |P|^2_M^-1 >= 0:
     * the contact creates no energy (doc/theory.md, "Dynamics"). (With P
     * the step's integral of the force weighted as the method weights the
     * others, (1 - alpha_f) dt F_c, tau would pass dt / 2 for rho_inf >
     * 1/2: a bar whose contact nodes keep their mass gained 1.4 % of its
     * energy.) A row without mass balances the step's impulses by the
     * trapezoidal rule, f_n+1 + f_n + F_c = 0, as Newmark's.
     */
    class GeneralizedAlphaScheme : public TimeScheme
    {
    public:
      explicit GeneralizedAlphaScheme(const AlphaParameters &parameters)
        : p(parameters)
      {}

      StepCoefficients
      predict(const Vector<double> &u_n,
              const Vector<double> &v_n,
              const Vector<double> &a_n,
              const double          dt,
              Vector<double>       &u_predicted,
              Vector<double>       &v_predicted) const override
      {
        u_predicted = u_n;
        u_predicted.add(dt, v_n, dt * dt * (0.5 - p.beta), a_n);
        v_predicted = v_n;
        v_predicted.add((1. - p.gamma) * dt, a_n);
        const double c_a = 1. / (p.beta * dt * dt);
        const double c_M = (1. - p.alpha_m) / (1. - p.alpha_f) * c_a;
        const double c_v = p.gamma / (p.beta * dt);
        // (w dt - c_v / c_M, written so that Newmark's is (1/2 - gamma) dt
        // to the bit)
        return {c_M,
                c_v,
                c_a,
                (contact_impulse_weight() -
                 p.gamma * ((1. - p.alpha_f) / (1. - p.alpha_m))) *
                  dt};
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
        // (Newmark's rows with mass carry nothing of the start state)
        const double scale = 1. / (1. - p.alpha_f);
        carried.reinit(state.forces.size());
        if (p.alpha_f != 0.)
          {
            carried = state.forces;
            carried.add(-1., state.mass_damping_force());
            carried *= p.alpha_f * scale;
          }
        if (p.alpha_m != 0.)
          carried.add(-p.alpha_m * scale, state.mass_times_acceleration());
        carried_by_rows_without_mass(state, carried);
      }

    private:
      const AlphaParameters p;
    };



    /** Chung & Hulbert's parameters from rho_inf, in [0, 1]. */
    AlphaParameters
    chung_hulbert(const double rho_inf)
    {
      AlphaParameters p;
      p.alpha_m = (2. * rho_inf - 1.) / (rho_inf + 1.);
      p.alpha_f = rho_inf / (rho_inf + 1.);
      p.gamma   = 0.5 - p.alpha_m + p.alpha_f;
      p.beta =
        0.25 * (1. - p.alpha_m + p.alpha_f) * (1. - p.alpha_m + p.alpha_f);
      return p;
    }



    /** Hilber, Hughes and Taylor's, alpha = (1 - rho_inf) / (1 + rho_inf)
     *  in [0, 1/3] (the sign of Chung & Hulbert's alpha_f). */
    AlphaParameters
    hilber_hughes_taylor(const double rho_inf)
    {
      const double    alpha = (1. - rho_inf) / (1. + rho_inf);
      AlphaParameters p;
      p.alpha_m = 0.;
      p.alpha_f = alpha;
      p.gamma   = 0.5 + alpha;
      p.beta    = 0.25 * (1. + alpha) * (1. + alpha);
      return p;
    }
  } // namespace



  void
  declare_generalized_alpha_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Spectral radius at infinity",
      "0.8",
      Patterns::Double(0., 1.),
      "rho_inf of Scheme = generalized-alpha (in [0, 1]) and hht-alpha (in "
      "[1/2, 1]): the factor by which a step multiplies a mode far above "
      "what the step resolves (omega dt -> infinity). 1 keeps every mode "
      "(the trapezoidal rule), 0 removes the unresolved ones in one step; "
      "the method stays second order for every value, and a mode that the "
      "step resolves is damped much less (Chung & Hulbert 1993).");
  }



  std::any
  parse_generalized_alpha_parameters(const ParameterHandler &prm,
                                     const std::string &)
  {
    return chung_hulbert(prm.get_double("Spectral radius at infinity"));
  }



  std::any
  parse_hht_alpha_parameters(const ParameterHandler &prm,
                             const std::string      &where)
  {
    const double rho_inf = prm.get_double("Spectral radius at infinity");
    if (rho_inf < 0.5)
      throw InputError(where + "Spectral radius at infinity",
                       "is " + std::to_string(rho_inf) +
                         ": Scheme = hht-alpha reaches 1/2 at the least "
                         "(alpha = 1/3); use Scheme = generalized-alpha "
                         "for a smaller one");
    return hilber_hughes_taylor(rho_inf);
  }



  std::unique_ptr<TimeScheme>
  make_alpha_method(const double alpha_m,
                    const double alpha_f,
                    const double beta,
                    const double gamma)
  {
    return std::make_unique<GeneralizedAlphaScheme>(
      AlphaParameters{alpha_m, alpha_f, beta, gamma});
  }



  std::unique_ptr<TimeScheme>
  make_generalized_alpha_scheme(const std::any &settings)
  {
    return std::make_unique<GeneralizedAlphaScheme>(
      std::any_cast<AlphaParameters>(settings));
  }
} // namespace glissade
