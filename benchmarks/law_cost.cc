// The cost of one quadrature point's stress and tangent for every law of
// the registry (Law = energy: by automatic differentiation of its energy),
// and for the neo-Hookean energy given as a C++ function. Prints figures;
// not a test.
//
//   build/benchmarks/glissade_law_benchmark [evaluations]

#include <deal.II/base/timer.h>

#include <glissade/material/energy_law.h>
#include <glissade/material/law_registry.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>

using namespace glissade;
using namespace dealii;

namespace
{
  /** Nanoseconds per evaluate() over n strains near E0, and a checksum. */
  std::pair<double, double>
  time_law(const HyperelasticLaw &law, const unsigned int n)
  {
    SymmetricTensor<2, 3> E, S;
    SymmetricTensor<4, 3> D;
    double                checksum = 0.;
    Timer                 timer;
    for (unsigned int k = 0; k < n; ++k)
      {
        // (a strain that changes from call to call, so that no call is
        // optimised away)
        const double s = 1e-3 * (k % 97);
        E[0][0]        = 0.1 + s;
        E[1][1]        = -0.05 + 0.5 * s;
        E[0][1]        = 0.03 - s;
        law.evaluate(E, S, D);
        checksum += S[0][0] + D[0][0][1][1];
      }
    timer.stop();
    return {1e9 * timer.wall_time() / n, checksum};
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned int n      = argc > 1 ? std::atoi(argv[1]) : 200000;
  const double       lambda = 577., mu = 385.;
  std::cout << "law, ns per stress and tangent (" << n
            << " evaluations), checksum" << std::endl;
  double neo_hookean = 0., formula = 0.;
  for (const LawRegistry::Entry &entry : LawRegistry::entries())
    {
      const auto law              = entry.create(lambda, mu, {});
      const auto [time, checksum] = time_law(*law, n);
      if (entry.name == "neo-Hookean")
        neo_hookean = time;
      if (entry.name == "energy")
        formula = time;
      std::cout << entry.name << ", " << std::setprecision(4) << time << ", "
                << std::setprecision(10) << checksum << std::endl;
    }
  const auto function =
    make_energy_law("neo-Hookean as a C++ energy",
                    [=](const StrainMeasures &s) -> EnergyNumber {
                      return mu / 2. * (s.I1 - 3.) - mu * s.ln_J +
                             lambda / 2. * s.ln_J * s.ln_J;
                    });
  const auto [time, checksum] = time_law(*function, n);
  std::cout << function->name() << ", " << std::setprecision(4) << time << ", "
            << std::setprecision(10) << checksum << std::endl;
  std::cout << "the neo-Hookean energy against the hand-written law: "
            << std::setprecision(3) << formula / neo_hookean
            << " times its time as Law = energy's formula (its default), "
            << time / neo_hookean << " as a C++ function" << std::endl;
  return 0;
}
