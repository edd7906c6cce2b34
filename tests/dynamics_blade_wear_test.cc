// A turning blade wears its casing's abradable coating in lobes at the
// critical speeds (prm/blade_casing_wear.prm; issue 51). The blade's first
// bending frequency in its turning frame is Southwell's, omega_1(Omega)^2 =
// omega_0^2 + k Omega^2, with omega_0 Euler-Bernoulli's and k = K_1 - 1 +
// K_2 r_0 / L (K_1 = 1.1933 and K_2 = 1.5709, the first mode's integrals
// that dynamics_turning_frame_test computes); the n-th engine order meets
// it at Omega_n = omega_0 / sqrt(n^2 - k). There the blade's vibration,
// set going by the spin-up and the start of the rub, repeats at every
// revolution and the tip cuts n lobes into the coating as the incursion
// grows: at Omega_3 and Omega_4 the worn profile's largest Fourier harmonic
// is the engine order n, at least three times any other. The contact's work
// is <= 0 at every step (to 1e-10 of the energies), the coating's plastic
// work among it.

#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** Amplitudes of the Fourier harmonics 1 ... count of a periodic profile. */
  std::vector<double>
  harmonics(const std::vector<double> &profile, const unsigned int count)
  {
    std::vector<double> amplitude(count + 1, 0.);
    const unsigned int  n = profile.size();
    for (unsigned int k = 1; k <= count; ++k)
      {
        std::complex<double> sum = 0.;
        for (unsigned int j = 0; j < n; ++j)
          sum += profile[j] * std::polar(1., -2. * M_PI * k * j / n);
        amplitude[k] = 2. * std::abs(sum) / n;
      }
    return amplitude;
  }

  /** The .prm's scene at Omega: the spin-up's expressions, the casing's
   *  radius over the spun-up tip, ten revolutions of incursion, four more. */
  void
  check_lobes_at_critical_speed(const unsigned int engine_order)
  {
    const double E = 110000., rho = 4.4e-9, h = 5., L = 100., r_0 = 200.;
    const double omega_0 =
      1.8751 * 1.8751 * h / (L * L) * std::sqrt(E / (12. * rho));
    const double k       = 1.1933 - 1. + 1.5709 * r_0 / L;
    const double n       = engine_order;
    const double omega   = omega_0 / std::sqrt(n * n - k);
    const double spin_up = 0.02, revolution = 2. * M_PI / omega;
    const double end = spin_up + 14. * revolution;
    // The leading corner once spun up: stretched by the centrifugal load
    // and bent by the lean (0.30 at Omega_3, as the .prm says), with the
    // .prm's clearance 0.01 and coating 0.5 over it.
    const double radius =
      std::hypot(32.5, 300.) + 0.30 * std::pow(omega / 1066., 2) + 0.01 + 0.5;
    const std::string W = std::to_string(omega);
    Simulation        simulation(SceneReader::read_file(
      source_path("prm/blade_casing_wear.prm"),
      {"Output/Progress=false",
              "Output/VTU interval=0",
              "Output/Directory=dynamics_blade_wear_" + std::to_string(engine_order),
              "Output/History=wear(tip)",
              "Body blade/Turning frame/Angular velocity=" + W +
                "*(t < 0.02 ? (t/0.02)^2*(3 - 2*t/0.02) : 1)",
              "Contact tip/Obstacle/Rotation=-" + W +
                "*(t < 0.02 ? t^3/0.02^2 - t^4/(2*0.02^3) : t - 0.01)",
              "Contact tip/Obstacle/Radius=" + std::to_string(radius),
              "Body blade/Boundary conditions/Prescribed displacement=bottom: y: "
                     "0.11*min(max(t - 0.02, 0)/" +
                std::to_string(10. * revolution) + ", 1)",
              "Load program/Stage end times=" + std::to_string(end),
              "Load program/Stage increments=" +
                std::to_string(static_cast<int>(std::round(end / 5e-5)))}));
    ContactWorkWatch  work;
    simulation.on_increment = [&](unsigned int, double) {
      work.record(*simulation.energies());
    };
    simulation.run();

    const ContactPair &pair      = *simulation.contact().contact_pairs()[0];
    const auto        &profile   = pair.coating()->profile();
    const auto         amplitude = harmonics(profile, 40);
    const unsigned int largest =
      std::distance(amplitude.begin(),
                    std::max_element(amplitude.begin(), amplitude.end()));
    double next = 0.;
    for (unsigned int j = 1; j < amplitude.size(); ++j)
      if (j != largest)
        next = std::max(next, amplitude[j]);
    std::cout << std::setprecision(5) << "  Omega_" << engine_order << " = "
              << omega << " rad/s: worn depth up to "
              << *std::max_element(profile.begin(), profile.end())
              << ", largest harmonic " << largest << " of "
              << amplitude[largest] << " (next " << next
              << "); largest contact work of a step " << work.largest
              << " (energies " << work.energies << ")" << std::endl;
    check(largest == engine_order,
          "the worn profile's lobes are not the engine order");
    check(amplitude[largest] >= 3. * next,
          "the lobes do not stand out of the worn profile");
    check(work.largest <= 1e-10 * work.energies,
          "a step's contact did positive work");
  }
} // namespace

GLISSADE_TEST(dynamics_blade_wear_lobes_engine_order_3)
{
  check_lobes_at_critical_speed(3);
}

GLISSADE_TEST(dynamics_blade_wear_lobes_engine_order_4)
{
  check_lobes_at_critical_speed(4);
}
