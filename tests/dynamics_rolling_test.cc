// Disks that roll, against a rigid disk's closed forms with the moment of
// inertia of the mass as the scheme holds it (the redistribution moves the
// rim's mass inward by one cell: k^2 = I / (m R^2) below the ring's
// (1 + 0.05^2) / 2 by O(h^2 / R^2)), so that what is measured is the time
// integration and the contact, not the mass's discretisation:
// - prm/rolling_disk.prm, launched at v0 without spin on a rough flat: it
//   rolls from t* = v0 / (mu g (1 + 1 / k^2)) at v* = v0 / (1 + k^2),
//   friction having dissipated m v0^2 / 2 k^2 / (1 + k^2);
// - the same disk at rest on a 20-degree slope: it rolls without slipping
//   at g sin a / (1 + k^2) where mu >= k^2 / (1 + k^2) tan a (tan(a) / 3
//   for a solid disk), and slips below, its centre at g (sin a - mu cos a)
//   and its spin at mu g cos a / (k^2 R).
// In every step the contact's work is <= 0.

#include <deal.II/grid/grid_tools.h>

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
  /** k^2 = I / (m R^2) of a disk's mass as the scheme holds it. */
  double
  radius_of_gyration_squared(const Body &disk, const double radius)
  {
    // density 1, thickness 1: the mass is the mesh's area
    const double mass = GridTools::volume(disk.triangulation());
    return disk.inertia()->moment_of_inertia(disk, Point<2>(0., 0.)) /
           (mass * radius * radius);
  }
} // namespace

// prm/rolling_disk.prm: a ring (radii 0.05 and 1) launched at v0 = 1
// without spin on a flat with mu = 0.3 under g = 1, by Moreau-Jean (theta
// = 1). t* is the last step whose friction force is mu times the normal one
// (sliding): within 2 %; the speed at the next step within 1 % of v* (after
// it, the 96-sided rim loses speed at each of its vertices' impacts); the
// friction's dissipation within 1 % of the rigid disk's.
GLISSADE_TEST(dynamics_rolling_disk_moreau_jean)
{
  const double v0 = 1., mu = 0.3, g = 1.;
  Simulation   simulation(
    SceneReader::read_file(source_path("prm/rolling_disk.prm"),
                           {"Output/Progress=false",
                              "Output/VTU interval=0",
                              "Output/Directory=dynamics_rolling_disk"}));
  const Body      &disk      = simulation.body("disk");
  const double     mass      = GridTools::volume(disk.triangulation());
  double           last_slip = 0., v_rolling = 0.;
  ContactWorkWatch work;
  simulation.on_increment = [&](unsigned int, double t) {
    const auto f = simulation.contact().contact_pairs()[0]->total_force();
    if (f[1] > 0. && std::abs(f[0]) >= 0.99 * mu * f[1])
      {
        last_slip = t;
        v_rolling = -1.;
      }
    else if (v_rolling < 0.)
      v_rolling = disk.inertia()->momentum()[0] / mass;
    work.record(*simulation.energies());
  };
  simulation.run();
  const double k2       = radius_of_gyration_squared(disk, 1.);
  const double t_star   = v0 / (mu * g * (1. + 1. / k2));
  const double v_star   = v0 / (1. + k2);
  const double lost     = 0.5 * mass * v0 * v0 * k2 / (1. + k2);
  const double friction = simulation.energies()->friction_dissipation;
  std::cout << std::setprecision(6) << "  k^2 of the mass " << k2
            << " (the ring's " << (1. + 0.05 * 0.05) / 2.
            << "); rolling from t = " << last_slip << " (t* " << t_star
            << ") at " << v_rolling << " (v* " << v_star
            << "), friction dissipated " << friction << " (rigid disk " << lost
            << "); largest contact work of a step " << work.largest
            << std::endl;
  check_relative(last_slip, t_star, 0.02, "the time rolling starts");
  check_relative(v_rolling, v_star, 0.01, "the speed rolling starts at");
  check_relative(friction, lost, 0.01, "the energy friction dissipated");
  check(work.largest <= 1e-10 * work.energies,
        "a step's contact did positive work");
}

namespace
{
  /**
   * The disk of prm/rolling_disk.prm at rest on a slope of angle a, its
   * weight put on over t_r = 0.2 (g t / t_r, then g: the disk's vibration,
   * of period 4 R / c = 0.013, is not shaken up), for T = 2: the speed
   * step by step, and at T the centre's travel along the slope and the
   * angle turned.
   */
  struct SlopeRun
  {
    double              k2 = 0., travel = 0., angle = 0.;
    std::vector<double> t, v;
    ContactWorkWatch    work;
  };

  SlopeRun
  roll_down(const std::string &scheme, const double mu, const double a)
  {
    const std::string ramp    = "min(t / 0.2, 1)";
    const std::string gravity = std::to_string(std::sin(a)) + " * " + ramp +
                                ", " + std::to_string(-std::cos(a)) + " * " +
                                ramp;
    std::vector<std::string> overrides = {
      "Output/Progress=false",
      "Output/VTU interval=0",
      "Output/History=momentum(disk); energies()",
      "Output/Directory=dynamics_rolling_slope_" + scheme + "_" +
        std::to_string(mu),
      "Body disk/Mesh/Subdivisions=192, 4",
      "Newton/Residual tolerance=1e-9",
      "Newton/Displacement tolerance=1e-9",
      "Body disk/Initial velocity=0, 0",
      "Body disk/Boundary conditions/Gravity=" + gravity,
      "Contact floor/Friction coefficient=" + std::to_string(mu),
      "Load program/Stage end times=2",
      "Load program/Stage increments=200",
      "Time integration/Scheme=" + scheme};
    if (scheme == "moreau-jean")
      overrides.push_back("Time integration/Theta=1");
    Simulation simulation(
      SceneReader::read_file(source_path("prm/rolling_disk.prm"), overrides));
    const Body  &disk = simulation.body("disk");
    const double mass = GridTools::volume(disk.triangulation());
    SlopeRun     run;
    simulation.on_increment = [&](unsigned int, double t) {
      run.t.push_back(t);
      run.v.push_back(disk.inertia()->momentum()[0] / mass);
      run.work.record(*simulation.energies());
    };
    simulation.run();
    run.k2 = radius_of_gyration_squared(disk, 1.);
    // The travel of the vertices' centroid, and the rotation that best
    // maps the vertices' reference positions onto their current ones
    // (both about their centroids), atan2(sum X x x, sum X . x).
    const auto  &vertices = disk.triangulation().get_vertices();
    const auto   u        = vertex_displacements(disk);
    const double share    = 1. / vertices.size();
    Tensor<1, 2> X0, x0;
    for (unsigned int k = 0; k < vertices.size(); ++k)
      {
        X0 += share * vertices[k];
        x0 += share * (vertices[k] + u[k]);
      }
    double cross = 0., dot = 0.;
    for (unsigned int k = 0; k < vertices.size(); ++k)
      {
        const Tensor<1, 2> X = vertices[k] - Point<2>(X0);
        const Tensor<1, 2> x = vertices[k] + u[k] - Point<2>(x0);
        cross += X[0] * x[1] - X[1] * x[0];
        dot += X * x;
      }
    run.travel = x0[0] - X0[0];
    run.angle  = std::atan2(cross, dot);
    return run;
  }

  /** The least-squares slope of v(t) over t >= t_0. */
  double
  acceleration_after(const SlopeRun &run, const double t_0)
  {
    double n = 0., st = 0., sv = 0., stt = 0., stv = 0.;
    for (unsigned int i = 0; i < run.t.size(); ++i)
      if (run.t[i] >= t_0)
        {
          n += 1.;
          st += run.t[i];
          sv += run.v[i];
          stt += run.t[i] * run.t[i];
          stv += run.t[i] * run.v[i];
        }
    return (n * stv - st * sv) / (n * stt - st * st);
  }
} // namespace

// The disk at rest on a 30-degree slope (g = 1, put on over 0.2 s), for 2
// s, its rim of 192 sides. With mu = 0.4, above k^2 / (1 + k^2) tan a
// (0.169), it rolls: its centre's acceleration is g sin a / (1 + k^2) once
// the weight is on (least squares over t >= 0.3), and it turns by minus its
// travel over R (no slip). With mu = 0.1 it slips: its centre at g (sin a -
// mu cos a), and it turns by -mu cos a / (k^2 R (sin a - mu cos a)) per
// unit travel. Each within 1 %, for Newmark and Moreau-Jean (theta = 1),
// but the no-slip of Newmark's rolling disk, within 2 %: the trapezoidal
// rule leaves the rim's nodes ringing from step to step after each
// vertex's touch-down (its rows' memory of the previous step, mass kept or
// not), and the ringing force slips them past Coulomb's cone now and then
// (0.9 % of the travel here; 1.3 % at 20 degrees with a 64-sided rim, 1.1
// % with 128 sides); implicit Euler damps it (0.01 %). (The slipping
// disk's spin depends on the rim's sides: the contact node's lever arm
// turns with it, 2.9 % off the circle's with 64 sides, 0.5 % with 256.)
GLISSADE_TEST(dynamics_rolling_down_a_slope)
{
  const double a = 30. * numbers::PI / 180., T = 2., t_r = 0.2;
  // int_0^T int_0^t g(t') dt' dt for g = min(t / t_r, 1)
  const double travel_integral =
    t_r * t_r / 6. + 0.5 * (std::pow(T - t_r / 2., 2) - std::pow(t_r / 2., 2));
  for (const std::string scheme : {"newmark", "moreau-jean"})
    for (const double mu : {0.4, 0.1})
      {
        const SlopeRun run       = roll_down(scheme, mu, a);
        const double   threshold = run.k2 / (1. + run.k2) * std::tan(a);
        const bool     rolls     = mu >= threshold;
        const double   along =
          rolls ? std::sin(a) / (1. + run.k2) : std::sin(a) - mu * std::cos(a);
        const double acceleration = acceleration_after(run, 0.3);
        // the angle turned per unit travel: -1 / R rolling, -mu cos a /
        // (k^2 R (sin a - mu cos a)) slipping (the same integral of g(t)
        // over both, whichever the scheme's error on positions)
        const double turn = run.angle / run.travel;
        const double turn_cf =
          rolls ?
            -1. :
            -mu * std::cos(a) / (run.k2 * (std::sin(a) - mu * std::cos(a)));
        std::cout << std::setprecision(6) << "  " << scheme << ", mu = " << mu
                  << (rolls ? " (rolls" : " (slips") << ", threshold "
                  << threshold << "): acceleration " << acceleration << " ("
                  << along << "), travel " << run.travel << " ("
                  << along * travel_integral << "), angle turned " << run.angle
                  << ", per unit travel " << turn << " (" << turn_cf
                  << "); largest contact work of a step " << run.work.largest
                  << std::endl;
        const std::string what =
          scheme + ", mu = " + std::to_string(mu) + ": the ";
        check_relative(acceleration, along, 0.01, what + "acceleration");
        check_relative(turn,
                       turn_cf,
                       scheme == "newmark" && rolls ? 0.02 : 0.01,
                       what + "angle turned per unit travel");
        check(run.work.largest <= 1e-10 * run.work.energies,
              what + "contact did positive work in a step");
      }
}
