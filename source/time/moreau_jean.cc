// Time integration/Scheme = moreau-jean: Moreau and Jean's theta-method with
// the contact by the step's impulses, and its entry Moreau-Jean theta (the
// old name Theta an alias).

#include <deal.II/base/parameter_handler.h>

#include <glissade/body/body.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/time/time_scheme.h>

#include <algorithm>
#include <any>
#include <memory>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    struct MoreauJeanSettings
    {
      double theta = 0.5;
    };

    /**
     * Moreau and Jean's theta-method (Jean 1999; Feng, Joli, Cros & Magnain
     * 2005 with the bi-potential local solver), from (u_n, v_n) over a step
     * dt: u_n+1 = u_n + dt (theta v_n+1 + (1 - theta) v_n) and M (v_n+1 -
     * v_n) = dt (theta f_n+1 + (1 - theta) f_n) + P, f = F_ext - F_int,
     * divided by theta dt: the inertia force M (u - u~) / (theta dt)^2 with
     * u~ = u_n + dt v_n, the start state's forces (1 - theta) / theta f_n
     * as loads, and the contact force P / (theta dt).
     *
     * Signorini's law on the end normal velocity and the step's impulses,
     * for the nodes whose gap closes by the step's theta point, g_n + (1 -
     * theta) dt U_N <= 0, and that do not move away. With U = H v_n the
     * relative velocity at the start, the end velocity's law is the
     * position law shifted: U_N,n+1 >= 0 is g(u) - g_n - (1 - theta) dt
     * U_N,n >= 0 to first order. Coulomb's law holds on the step's slip. A
     * node that does not close keeps Signorini's law on its end position,
     * g >= min(g_n, 0).
     *
     * The velocity law needs the contact nodes' mass (Contact mass =
     * kept): a node without mass has no velocity of its own (the scheme's
     * u_n+1 = u_n + dt (theta v_n+1 + (1 - theta) v_n) makes its v ring
     * from step to step at theta = 1/2), and a law on it lets nodes through
     * the master. With the mass redistributed, the law is Signorini's on
     * the end positions, as Newmark's, whose impulse does no positive work
     * either (doc/theory.md, "Energy").
     */
    class MoreauJeanScheme : public TimeScheme
    {
    public:
      explicit MoreauJeanScheme(const MoreauJeanSettings &settings)
        : theta(settings.theta)
      {}

      StepCoefficients
      predict(const Vector<double> &u_n,
              const Vector<double> &v_n,
              const Vector<double> &,
              const double    dt,
              Vector<double> &u_predicted,
              Vector<double> &v_predicted) const override
      {
        u_predicted = u_n;
        u_predicted.add(dt, v_n);
        v_predicted = v_n;
        // (a = (v_n+1 - v_n) / dt, the step's mean acceleration; v(u)
        // counts the impulse's velocity change whole)
        return {1. / (theta * theta * dt * dt),
                1. / (theta * dt),
                1. / (theta * dt * dt),
                0.};
      }

      double
      contact_impulse_weight() const override
      {
        // (the local problem's unknown is the impulse over theta dt)
        return theta;
      }

      bool
      predictor_takes_acceleration() const override
      {
        return false;
      }

      void
      start_state_forces(const StartState &state,
                         Vector<double>   &carried) const override
      {
        // (1 - theta) / theta (F_ext - F_int - F_v)_n on every dof.
        carried = state.forces;
        carried *= (1. - theta) / theta;
      }

      void
      attach(ContactProblem                &contact,
             const TimeIntegrationSettings &settings) const override
      {
        TimeScheme::attach(contact, settings);
        if (!settings.redistribute_contact_mass)
          contact.use_velocity_law();
      }

      void
      begin_contact_step(ContactProblem &contact,
                         const double    t_start,
                         const double    dt) const override;

    private:
      const double theta;
    };



    void
    MoreauJeanScheme::begin_contact_step(ContactProblem &contact,
                                         const double    t_start,
                                         const double    dt) const
    {
      if (contact.position_law())
        return;
      for (const auto &pair : contact.contact_pairs())
        {
          const std::array<const Body *, 2> body = {
            {&pair->slave(), pair->master()}};
          const auto velocity_along = [&](const DofVector &row) {
            double value = 0.;
            for (const DofCoefficient &e : row)
              if (body[e.body] != nullptr)
                value += e.value * body[e.body]->inertia()->velocity()(e.dof);
            return value;
          };
          for (ContactNode &node : pair->nodes())
            {
              node.law_shift = {{0., 0.}};
              if (!node.active)
                continue;
              const ContactLinearization &l   = node.linearization;
              double                      U_N = velocity_along(l.gap_row);
              // Relative to a moving obstacle's material under the node;
              // the gap at the start is to the obstacle as it stood then
              // (TimeIntegrator's start gaps).
              const double start_gap = node.start_gap;
              if (body[1] == nullptr)
                {
                  const Point<2> x =
                    node.reference_position +
                    node.displacement(pair->slave().displacement());
                  U_N -= node.normal * pair->surface().velocity_at(x, t_start);
                }
              if (start_gap + (1. - theta) * dt * U_N > 0.)
                {
                  // A node that does not close by the theta point keeps
                  // Signorini's law on its end position, g >= min(g_n, 0):
                  // it may open, and it may close within the step but not
                  // pass the master (or, behind it, go further). Its
                  // impulse's work on the step's motion, P (g - g_n), is
                  // then -P g_n <= 0 or zero. (Left out of the step, as
                  // Moreau's index set leaves it, a node whose start
                  // velocity rang away from the master at theta = 1/2 went
                  // behind it by dt times its speed and stayed there: a
                  // block resting on a rough floor tilted by 1e-4 and was
                  // held so by friction.)
                  node.law_shift = {{0., -std::min(start_gap, 0.)}};
                  continue;
                }
              // The impulse works on the step's mean velocity, theta
              // U_n+1 + (1 - theta) U_n = du / dt. An approaching node
              // (U_N,n <= 0) takes Jean's law, U_N,n+1 >= 0: the normal
              // work (1 - theta) P_N U_N,n is <= 0. A node behind the
              // master that moves away (U_N,n > 0) may not come back within
              // the step, g - g_n >= 0: its normal work is zero (on the end
              // velocity its impulse would work positively). Coulomb's law
              // holds on the step's slip: the friction's work is - mu P_N
              // |slip| <= 0 (on the end velocity alone, a slip that
              // reverses within the step would create energy).
              node.law_shift = {
                {0., -start_gap - (1. - theta) * dt * std::min(U_N, 0.)}};
            }
        }
    }
  } // namespace



  void
  declare_moreau_jean_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Moreau-Jean theta",
                      "0.5",
                      Patterns::Double(0.5, 1.),
                      "Moreau-Jean's theta, in [1/2, 1]: 1/2 conserves the "
                      "energy of a smooth motion, 1 (implicit Euler) damps "
                      "it. (Its name was Theta, which still sets it.)");
    // (its name before the schemes owned their entries)
    prm.declare_alias("Moreau-Jean theta", "Theta");
  }



  std::any
  parse_moreau_jean_parameters(const ParameterHandler &prm, const std::string &)
  {
    MoreauJeanSettings settings;
    settings.theta = prm.get_double("Moreau-Jean theta");
    return settings;
  }



  std::unique_ptr<TimeScheme>
  make_moreau_jean_scheme(const std::any &settings)
  {
    return std::make_unique<MoreauJeanScheme>(
      std::any_cast<MoreauJeanSettings>(settings));
  }
} // namespace glissade
