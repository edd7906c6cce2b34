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
  } // namespace



  std::unique_ptr<TimeScheme>
  make_alpha_method(double alpha_m, double alpha_f, double beta, double gamma);



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



  /**
   * Newmark's scheme: from the state (u_n, v_n, a_n) over a step dt, with
   * the predictors u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n and v~ = v_n
   * + (1 - gamma) dt a_n, the end state's a(u) = (u - u~) / (beta dt^2)
   * and v(u) = v~ + gamma dt a(u), and the equation of motion that of the
   * end state. The smooth forces by Newmark's rule, the contact by the
   * step's impulse P = dt F_c / 2, its law on the end positions, every
   * node within the alert distance (the quasi-static step's): its work
   * over the step, P . du / dt, is -P_N g_n - mu P_N |slip| <= 0, so the
   * contact never creates energy (doc/theory.md, "Energy"). Its formulas
   * are the generalised-alpha method's with alpha_m = alpha_f = 0
   * (generalized_alpha.cc).
   */
  std::unique_ptr<TimeScheme>
  make_newmark_scheme(const std::any &settings)
  {
    const auto newmark = std::any_cast<NewmarkSettings>(settings);
    return make_alpha_method(0., 0., newmark.beta, newmark.gamma);
  }
} // namespace glissade
