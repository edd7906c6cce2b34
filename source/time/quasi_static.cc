// Time integration/Scheme = quasi-static: no inertia, the load program's t
// a load parameter and every step an equilibrium (every scene before
// dynamics).

#include <glissade/time/time_scheme.h>

#include <any>
#include <memory>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** t is a load parameter; no body has inertia, so no formula is
     *  asked of it. */
    class QuasiStaticScheme : public TimeScheme
    {
    public:
      bool
      has_inertia() const override
      {
        return false;
      }

      StepCoefficients
      predict(const Vector<double> &u_n,
              const Vector<double> &,
              const Vector<double> &,
              const double,
              Vector<double> &u_predicted,
              Vector<double> &v_predicted) const override
      {
        u_predicted = u_n;
        v_predicted.reinit(u_n.size());
        return {};
      }

      double
      contact_impulse_weight() const override
      {
        return 1.;
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
        carried.reinit(state.forces.size());
      }
    };
  } // namespace



  std::unique_ptr<TimeScheme>
  make_quasi_static_scheme(const std::any &)
  {
    return std::make_unique<QuasiStaticScheme>();
  }
} // namespace glissade
