// Rayleigh damping under a dynamic scheme: a blade's first bending mode
// decays at the ratio a_M / (2 omega) + a_K omega / 2, with the energy
// the damping takes accounted for; the stiffness-proportional part (a
// Kelvin-Voigt stress on the Green-Lagrange strain rate) brakes no rigid
// spin, which a_K K_0 v would.

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iomanip>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

// The blade of prm/blade_casing.prm, free of the casing, launched in its
// first Euler-Bernoulli mode (omega_1 = 2537.5 rad/s) with a_M and a_K
// each worth a damping ratio of 1 %. The tip's successive positive peaks
// (each refined by a parabola through its three steps) fall by exp(-2 pi
// zeta / sqrt(1 - zeta^2)) a period: zeta measured over eight periods
// within 5 % of 0.02 (Newmark's trapezoidal rule adds no damping; 40
// steps a period shift the ratio by a few tenths of a percent). The energy
// balance (kinetic + strain + dissipated = initial) closes to 1e-3 of the
// initial energy, and the damping has taken 1 - exp(-4 pi zeta n) of it
// after n = 8.5 periods, within 3 %.
GLISSADE_TEST(dynamics_rayleigh_damping_ratio)
{
  const BladeFirstMode mode      = blade_first_mode(110000., 4.4e-9, 5.);
  const double         omega_1   = mode.omega_1;
  const double         zeta_each = 0.01;
  const double a_M = 2. * zeta_each * omega_1, a_K = 2. * zeta_each / omega_1;
  const double period = 2. * M_PI / omega_1;
  std::ostringstream a_M_text, a_K_text;
  a_M_text << std::setprecision(17) << a_M;
  a_K_text << std::setprecision(17) << a_K;
  Simulation          simulation(SceneReader::read_file(
    source_path("prm/blade_casing.prm"),
    {"Output/Progress=false",
              "Output/VTU interval=0",
              "Output/Directory=dynamics_blade_rayleigh_damping",
              "Contact tip/Obstacle/Lobe depth=0",
              "Contact tip/Obstacle/Radius=320",
              "Body blade/Initial velocity=" + mode.shape + ", 0",
              "Time integration/Mass damping=" + a_M_text.str(),
              "Time integration/Stiffness damping=" + a_K_text.str(),
              "Time integration/Newmark gamma=0.5",
              "Time integration/Newmark beta=0.25",
              "Load program/Stage end times=" + std::to_string(8.5 * period),
              "Load program/Stage increments=340"}));
  const Body         &blade = simulation.body("blade");
  const auto          tip   = vertex_value_dofs(blade, Point<2>(0., 300.));
  std::vector<double> times, tip_x;
  double              worst_balance = 0.;
  simulation.on_increment           = [&](unsigned int, double t) {
    times.push_back(t);
    tip_x.push_back(blade.displacement()(tip[0]));
    worst_balance =
      std::max(worst_balance, std::abs(simulation.energies()->balance()));
  };
  simulation.run();
  const EnergyAccount &energies = *simulation.energies();

  // The positive peaks, each at the vertex of the parabola through the
  // step of largest tip displacement and its two neighbours.
  std::vector<std::pair<double, double>> peaks;
  for (unsigned int k = 1; k + 1 < tip_x.size(); ++k)
    if (tip_x[k] > 0. && tip_x[k] >= tip_x[k - 1] && tip_x[k] > tip_x[k + 1])
      {
        const double y0 = tip_x[k - 1], y1 = tip_x[k], y2 = tip_x[k + 1];
        const double curvature = y0 - 2. * y1 + y2;
        const double s         = 0.5 * (y0 - y2) / curvature;
        const double dt        = times[k] - times[k - 1];
        peaks.emplace_back(times[k] + s * dt, y1 - 0.25 * (y0 - y2) * s);
      }
  check(peaks.size() >= 9, "fewer than nine peaks of the tip");
  // (the first peak still carries the higher modes' start)
  const auto  &first = peaks[1], &last = peaks.back();
  const double periods       = peaks.size() - 2.;
  const double log_decrement = std::log(first.second / last.second) / periods;
  const double zeta =
    log_decrement / std::sqrt(4. * M_PI * M_PI + log_decrement * log_decrement);
  std::cout << std::setprecision(6) << "  damping ratio " << zeta << " over "
            << periods << " periods, Rayleigh's " << 2. * zeta_each
            << "; energy balance within " << worst_balance << " of "
            << energies.initial << ", dissipated "
            << energies.damping_dissipation << std::endl;
  check_relative(zeta, 2. * zeta_each, 0.05, "the damping ratio");
  check(worst_balance < 1e-3 * energies.initial,
        "the energy balance does not close");
  check_relative(energies.damping_dissipation / energies.initial,
                 1. - std::exp(-4. * M_PI * 2. * zeta_each * 8.5),
                 0.03,
                 "the fraction of the energy dissipated");
}



// The ring of prm/rolling_disk.prm, clear of the floor and without
// gravity, spun as a rigid body at omega = 1 (kinetic energy 0.766) over
// a quarter turn with a_K = 1e-2 s, a damping ratio of 1.6 for its
// breathing mode (316 rad/s). The viscous stress sees only the strain
// rate: the energy it takes is the breathing the spin starts (centrifugal
// strain rho omega^2 R^2 / E = 1e-5) and the scheme's chord error, below
// 1e-4 of the kinetic energy. Rayleigh's a_K K_0 v would see the strain
// rate -omega sin(theta) I of the turned rotation field and dissipate a_K
// omega^2 sin^2(theta) 4 (lambda + mu) per unit volume, about 1e4 over the
// quarter turn: the spin would stop. The energy balance closes to 1e-4:
// the trapezoidal rule does not conserve the energy exactly at finite
// rotations (3.5e-5 short without damping).
GLISSADE_TEST(dynamics_stiffness_damping_spares_rigid_spin)
{
  Simulation simulation(SceneReader::read_file(
    source_path("prm/rolling_disk.prm"),
    {"Output/Progress=false",
     "Output/VTU interval=0",
     "Output/Directory=dynamics_spinning_ring",
     "Body disk/Boundary conditions/Gravity=0, 0",
     "Body disk/Initial velocity=-y, x",
     "Contact floor/Obstacle/Point=0, -2",
     "Time integration/Scheme=newmark",
     "Time integration/Stiffness damping=1e-2",
     "Newton/Residual tolerance=1e-8",
     "Load program/Stage end times=" + std::to_string(0.5 * M_PI),
     "Load program/Stage increments=200"}));
  simulation.run();
  const EnergyAccount &energies = *simulation.energies();
  std::cout << std::setprecision(6) << "  kinetic energy " << energies.kinetic
            << " (initially " << energies.initial << "), dissipated "
            << energies.damping_dissipation << ", balance "
            << energies.balance() << std::endl;
  check(energies.damping_dissipation >= 0., "negative dissipation");
  check(energies.damping_dissipation < 1e-4 * energies.initial,
        "the stiffness damping brakes a rigid spin");
  check(std::abs(energies.balance()) < 1e-4 * energies.initial,
        "the energy balance does not close");
}



// The hoop terms of the viscous stress (dE_33/dt = F_33 v_r / r and D_0's
// hoop coupling): a long thick cylinder (axisymmetric section, axial
// rollers) breathing from v_r = 0.1 r with a_K = 3e-3 s must lose the
// same fraction of its energy to the damping, and reach the same bore, as
// the plane-strain quarter ring that is its cross-section (the hoop in
// the plane): within 1e-4 (q2 on 16 radial cells, 32 around the ring; the
// two discretise one answer).
GLISSADE_TEST(dynamics_stiffness_damping_axisymmetric_is_the_plane_ring)
{
  const std::vector<std::string> common = {
    "Output/Progress=false",
    "Output/VTU interval=0",
    "Body cylinder/Material/Density=1",
    "Time integration/Scheme=newmark",
    "Time integration/Stiffness damping=3e-3",
    "Newton/Residual tolerance=1e-10",
    "Newton/Displacement tolerance=1e-10",
    "Load program/Stage end times=0.5",
    "Load program/Stage increments=100"};
  auto cylinder_overrides = common;
  for (const std::string o :
       {"Output/Directory=dynamics_breathing_cylinder",
        "Body cylinder/Boundary conditions/Pressure=left: 0",
        "Body cylinder/Initial velocity=0.1*x, 0"})
    cylinder_overrides.push_back(o);
  auto ring_overrides = thick_cylinder_as_plane_ring("0");
  ring_overrides.insert(ring_overrides.end(), common.begin(), common.end());
  ring_overrides.push_back("Output/Directory=dynamics_breathing_ring");
  ring_overrides.push_back("Body cylinder/Initial velocity=0.1*x, 0.1*y");

  const auto run = [](const std::vector<std::string> &overrides) {
    auto simulation = std::make_unique<Simulation>(
      SceneReader::read_file(source_path("prm/thick_cylinder.prm"), overrides));
    simulation->run();
    return simulation;
  };
  const auto   cylinder              = run(cylinder_overrides);
  const auto   ring                  = run(ring_overrides);
  const auto  &axisymmetric_energies = *cylinder->energies();
  const auto  &plane_energies        = *ring->energies();
  const double axisymmetric_share =
    axisymmetric_energies.damping_dissipation / axisymmetric_energies.initial;
  const double plane_share =
    plane_energies.damping_dissipation / plane_energies.initial;
  std::cout << std::setprecision(8) << "  dissipated share: axisymmetric "
            << axisymmetric_share << ", plane ring " << plane_share
            << std::endl;
  check(plane_share > 0.05, "the plane ring's damping took under 5 %");
  check_relative(axisymmetric_share,
                 plane_share,
                 1e-4,
                 "the share of the energy the damping took");
  check_relative(
    vertex_displacement(cylinder->body("cylinder"), Point<2>(1., 0.))[0],
    vertex_displacement(ring->body("cylinder"), Point<2>(1., 0.))[0],
    1e-4,
    "the bore's radial displacement");
}
