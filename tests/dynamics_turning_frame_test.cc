// A blade in its own turning frame (Body/Turning frame): the first bending
// frequency of the blade of prm/blade_casing.prm spun at Omega in its
// plane, against that of a rotating Euler-Bernoulli cantilever (the
// reference below, a 1D model: EI w'''' - (T w')' - rho A Omega^2 w = rho
// A omega^2 w, the centrifugal tension T(x) = rho A Omega^2 int_x^L (r_0 +
// s) ds stiffening it, the tangential component of the centrifugal force
// softening it, Southwell's omega^2 = omega_0^2 + k Omega^2 with k = 3.335
// for a root at r_0 = 2 L).

#include <deal.II/lac/lapack_full_matrix.h>

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iomanip>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /**
   * The first in-plane bending frequency of a cantilever (root at radius
   * r_0, length L, EI, rho A) spun at Omega: cubic Hermite beam elements,
   * the tension's geometric stiffness integrated by 4-point Gauss, the
   * generalised eigenproblem by LAPACK.
   */
  double
  rotating_cantilever_frequency(const double EI,
                                const double rho_A,
                                const double r_0,
                                const double L,
                                const double Omega)
  {
    const unsigned int       n_elements = 60, n = 2 * n_elements;
    const double             h = L / n_elements;
    LAPACKFullMatrix<double> K(n, n), M(n, n);
    const double             gauss_x[4] = {-0.8611363115940526,
                                           -0.3399810435848563,
                                           0.3399810435848563,
                                           0.8611363115940526};
    const double             gauss_w[4] = {0.3478548451374538,
                                           0.6521451548625461,
                                           0.6521451548625461,
                                           0.3478548451374538};
    for (unsigned int e = 0; e < n_elements; ++e)
      {
        // dofs w_e, w'_e, w_e+1, w'_e+1; the root's two are clamped
        const int dof[4]   = {2 * int(e) - 2,
                              2 * int(e) - 1,
                              2 * int(e),
                              2 * int(e) + 1};
        double    ke[4][4] = {}, me[4][4] = {};
        for (unsigned int q = 0; q < 4; ++q)
          {
            const double xi = 0.5 * (gauss_x[q] + 1.), w = 0.5 * gauss_w[q] * h;
            const double x = (e + xi) * h;
            // Hermite shape functions, their first and second derivatives
            const double N[4]   = {1 - 3 * xi * xi + 2 * xi * xi * xi,
                                   h * (xi - 2 * xi * xi + xi * xi * xi),
                                   3 * xi * xi - 2 * xi * xi * xi,
                                   h * (-xi * xi + xi * xi * xi)};
            const double dN[4]  = {(-6 * xi + 6 * xi * xi) / h,
                                   1 - 4 * xi + 3 * xi * xi,
                                   (6 * xi - 6 * xi * xi) / h,
                                   -2 * xi + 3 * xi * xi};
            const double ddN[4] = {(-6 + 12 * xi) / (h * h),
                                   (-4 + 6 * xi) / h,
                                   (6 - 12 * xi) / (h * h),
                                   (-2 + 6 * xi) / h};
            const double tension =
              rho_A * Omega * Omega * (r_0 * (L - x) + 0.5 * (L * L - x * x));
            for (unsigned int i = 0; i < 4; ++i)
              for (unsigned int j = 0; j < 4; ++j)
                {
                  ke[i][j] +=
                    w * (EI * ddN[i] * ddN[j] + tension * dN[i] * dN[j] -
                         rho_A * Omega * Omega * N[i] * N[j]);
                  me[i][j] += w * rho_A * N[i] * N[j];
                }
          }
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            if (dof[i] >= 0 && dof[j] >= 0)
              {
                K(dof[i], dof[j]) += ke[i][j];
                M(dof[i], dof[j]) += me[i][j];
              }
      }
    std::vector<Vector<double>> modes(n, Vector<double>(n));
    K.compute_generalized_eigenvalues_symmetric(M, modes);
    double lowest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n; ++i)
      lowest = std::min(lowest, K.eigenvalue(i).real());
    return std::sqrt(lowest);
  }

  /**
   * A slender titanium blade (h = 2, L = 100 mm, plane stress, Hermite
   * elements, 2 x 40 cells) clamped at r_0 = 50 mm on a hub, in its frame
   * turning at Omega about the hub's centre, started with the velocity of
   * the first cantilever mode: its tip's frequency from the zero crossings
   * of its tangential displacement over eight periods, from the second
   * one, 40 steps a period of the expected frequency. Its spin is put on
   * at t = 0 (spun up over a period, the Euler forces would bend it by
   * more than its length): its weight sets it ringing along its length at
   * some 80,000 rad/s, the tension swinging by as much as its mean and
   * shaking the bending mode, which a stiffness damping a_K = 1e-5 s
   * takes out (a damping ratio of 0.4 on that ringing, 0.011 on the
   * bending mode at 2 omega_0, whose frequency it lowers by 6e-5). At 2
   * omega_0 the centrifugal stress stretches the blade by 0.17 %.
   */
  double
  spun_blade_frequency(const double Omega,
                       const double expected,
                       const bool   coriolis)
  {
    const double      period = 2. * M_PI / expected;
    const std::string b      = "1.8751*(y-50)/100";
    const std::string mode   = "40*(cosh(" + b + ")-cos(" + b +
                             ")-0.7341*(sinh(" + b + ")-sin(" + b + ")))";
    const std::string scene = R"(
subsection Scene
  set Bodies = blade
end
subsection Body blade
  subsection Mesh
    set Type         = rectangle
    set Corner 1     = -1, 50
    set Corner 2     = 1, 150
    set Subdivisions = 2, 40
  end
  subsection Element
    set Space = hermite
  end
  subsection Material
    set Hypothesis    = plane stress
    set Young modulus = 110000
    set Poisson ratio = 0.3
    set Density       = 4.4e-9
  end
  subsection Boundary conditions
    set Fixed = bottom: all
  end
end
subsection Time integration
  set Scheme            = newmark
  set Stiffness damping = 1e-5
end
subsection Output
  set VTU interval = 0
  set Progress     = false
end
)";
    Simulation        simulation(SceneReader::read_string(
      scene,
      "spun_blade.prm",
      {"Output/Directory=dynamics_turning_blade_" + std::to_string(int(Omega)) +
                (coriolis ? "_coriolis" : ""),
              "Body blade/Initial velocity=" + mode + ", 0",
              "Body blade/Turning frame/Angular velocity=" + std::to_string(Omega),
              std::string("Body blade/Turning frame/Coriolis=") +
                (coriolis ? "true" : "false"),
              "Load program/Stage end times=" + std::to_string(9.5 * period),
              "Load program/Stage increments=380"}));
    const Body       &blade = simulation.body("blade");
    const auto        tip   = vertex_value_dofs(blade, Point<2>(0., 150.));
    // (from the first period on)
    ZeroCrossings crossings;
    crossings.from          = period;
    simulation.on_increment = [&](unsigned int, double t) {
      crossings.record(t, blade.displacement()(tip[0]));
    };
    simulation.run();
    check(crossings.times.size() >= 16, "the tip did not swing eight times");
    return crossings.angular_frequency();
  }
} // namespace

// The reference itself: at Omega = 0 it is Euler-Bernoulli's 1.8751^2 sqrt(
// EI / (rho A L^4)) to 1e-6, and at small Omega its slope gives Southwell's
// coefficient for a root at r_0 = 2 L in the plane of rotation, k = K_1 -
// 1 + K_2 r_0 / L with K_1 = int (L^2 - x^2) / 2 phi'^2 / int phi^2 and K_2
// = L int (L - x) phi'^2 / int phi^2 over Euler-Bernoulli's first mode phi
// (integrated here by Simpson's rule: 1.1933 and 1.5709), within 0.1 %.
GLISSADE_TEST(dynamics_turning_frame_reference_beam)
{
  const double E = 110000., rho = 4.4e-9, h = 5., L = 100.;
  const double EI = E * h * h * h / 12., rho_A = rho * h;
  const double omega_0 = rotating_cantilever_frequency(EI, rho_A, 200., L, 0.);
  const double b       = 1.8751040687;
  const double euler_bernoulli =
    b * b * std::sqrt(EI / (rho_A * std::pow(L, 4)));
  // Southwell's coefficients from the mode shape (x = s / L)
  const double c = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  const auto   phi = [&](const double x) {
    return std::cosh(b * x) - std::cos(b * x) -
           c * (std::sinh(b * x) - std::sin(b * x));
  };
  const auto slope = [&](const double x) {
    return b * (std::sinh(b * x) + std::sin(b * x) -
                c * (std::cosh(b * x) - std::cos(b * x)));
  };
  const unsigned int n    = 2000;
  double             norm = 0., K_1 = 0., K_2 = 0.;
  for (unsigned int i = 0; i <= n; ++i)
    {
      const double x = double(i) / n;
      const double w = (i == 0 || i == n ? 1. : (i % 2 ? 4. : 2.)) / (3. * n);
      norm += w * phi(x) * phi(x);
      K_1 += w * 0.5 * (1. - x * x) * slope(x) * slope(x);
      K_2 += w * (1. - x) * slope(x) * slope(x);
    }
  K_1 /= norm;
  K_2 /= norm;
  const double Omega = 0.02 * omega_0;
  const double omega = rotating_cantilever_frequency(EI, rho_A, 200., L, Omega);
  const double k     = (omega * omega - omega_0 * omega_0) / (Omega * Omega);
  std::cout << std::setprecision(8) << "  omega_0 " << omega_0
            << " (Euler-Bernoulli " << euler_bernoulli
            << "), Southwell's coefficient " << k << " (K_1 " << K_1 << ", K_2 "
            << K_2 << ": " << K_1 - 1. + 2. * K_2 << ")" << std::endl;
  check_relative(omega_0, euler_bernoulli, 1e-6, "the beam's omega_0");
  check_relative(k, K_1 - 1. + 2. * K_2, 1e-3, "Southwell's coefficient");
}

// The slender blade spun at 0, omega_0 and 2 omega_0 in its turning frame,
// Newmark's trapezoidal rule: its first bending frequency within 1 % of
// the rotating beam's at each speed (Southwell's coefficient K_1 - 1 + K_2
// / 2 = 0.979 at small spin; the beam's frequency falls below Southwell's
// line at 2 omega_0 as the mode's shape changes). The beam's model has no
// Coriolis forces; at 2 omega_0 the run with them, whose coupling to the
// blade's stretching moves the frequency by (omega / omega_axial)^2, gives
// it within 1 % too.
GLISSADE_TEST(dynamics_turning_frame_southwell)
{
  const double E = 110000., rho = 4.4e-9, h = 2., L = 100., r_0 = 50.;
  const double EI = E * h * h * h / 12., rho_A = rho * h;
  const double omega_0 = rotating_cantilever_frequency(EI, rho_A, r_0, L, 0.);
  for (const double ratio : {0., 1., 2.})
    for (const bool coriolis : {false, true})
      {
        if (coriolis && ratio != 2.)
          continue;
        const double Omega = ratio * omega_0;
        const double reference =
          rotating_cantilever_frequency(EI, rho_A, r_0, L, Omega);
        const double measured =
          spun_blade_frequency(Omega, reference, coriolis);
        std::cout << std::setprecision(6) << "  Omega = " << ratio << " omega_0"
                  << (coriolis ? ", with Coriolis" : "")
                  << ": first bending frequency " << measured
                  << " rad/s, the rotating beam's " << reference << " (ratio "
                  << measured / reference << "), Southwell's "
                  << omega_0 * std::sqrt(1. + 0.9788 * ratio * ratio)
                  << std::endl;
        check_relative(measured,
                       reference,
                       0.01,
                       "the frequency at Omega = " + std::to_string(ratio) +
                         " omega_0" + (coriolis ? " with Coriolis" : ""));
      }
}

namespace
{
  /**
   * A free elastic disk (radii 0.2 and 1, centre (3, 0)) at rest in the
   * inertial frame, seen from a frame that spins up about the origin,
   * Omega(t) = 2 pi min(t, 1): at t = 2 it has turned back by phi = 3 pi.
   * Returns the largest distance of its vertices from the rigid rotation by
   * -phi, and its largest stored energy over its kinetic one.
   */
  std::array<double, 2>
  body_at_rest_seen_turning(const unsigned int steps)
  {
    const std::string scene = R"(
subsection Scene
  set Bodies = disk
end
subsection Body disk
  subsection Mesh
    set Type         = ring
    set Center       = 3, 0
    set Inner radius = 0.2
    set Outer radius = 1
    set Subdivisions = 32, 4
  end
  subsection Material
    set Young modulus = 1000
    set Density       = 1
  end
  subsection Turning frame
    set Angular velocity = 2 * pi * min(t, 1)
    set Centre           = 0, 0
  end
end
subsection Time integration
  set Scheme = newmark
end
subsection Load program
  set Stage end times  = 2
end
subsection Output
  set VTU interval = 0
  set Progress     = false
  set History      = energies()
end
)";
    Simulation        simulation(SceneReader::read_string(
      scene,
      "body_at_rest.prm",
      {"Load program/Stage increments=" + std::to_string(steps),
              "Output/Directory=dynamics_turning_frame_body_at_rest_" +
                std::to_string(steps)}));
    const Body       &disk   = simulation.body("disk");
    double            strain = 0.;
    simulation.on_increment  = [&](unsigned int, double) {
      const EnergyAccount &e = *simulation.energies();
      strain = std::max(strain, e.strain / std::max(e.kinetic, 1e-300));
    };
    simulation.run();
    const double phi      = 3. * M_PI;
    const auto  &vertices = disk.triangulation().get_vertices();
    const auto   u        = vertex_displacements(disk);
    double       worst    = 0.;
    for (unsigned int k = 0; k < vertices.size(); ++k)
      {
        const Point<2> X = vertices[k];
        const Point<2> rotated(std::cos(phi) * X[0] + std::sin(phi) * X[1],
                               -std::sin(phi) * X[0] + std::cos(phi) * X[1]);
        worst = std::max(worst, (X + u[k] - rotated).norm());
      }
    return {{worst, strain}};
  }
} // namespace

// The disk at rest in the inertial frame, seen from the frame spinning up
// (centrifugal, Coriolis and Euler forces together): a rigid motion, its
// stored energy below 1e-6 of its kinetic one, and its points where the
// rigid rotation by -phi puts them within 1e-2 of its radius at 400 steps,
// the distance shrinking fourfold (3.5 to 4.5) at 800: the trapezoidal
// rule's second-order phase error, nothing more.
GLISSADE_TEST(dynamics_turning_frame_body_at_rest)
{
  const auto coarse = body_at_rest_seen_turning(400);
  const auto fine   = body_at_rest_seen_turning(800);
  std::cout << std::setprecision(6) << "  largest distance to the rigid "
            << "rotation by -3 pi: " << coarse[0] << " (400 steps), " << fine[0]
            << " (800 steps), ratio " << coarse[0] / fine[0]
            << "; largest stored / kinetic energy " << coarse[1] << ", "
            << fine[1] << std::endl;
  check(coarse[0] <= 1e-2, "the body at rest is not seen turning back");
  check(coarse[0] / fine[0] >= 3.5 && coarse[0] / fine[0] <= 4.5,
        "the distance to the rigid rotation does not fall at second order");
  check(std::max(coarse[1], fine[1]) <= 1e-6, "the body at rest is strained");
}
