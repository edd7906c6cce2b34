// Material/Kinematics = small strain: linear elasticity, whatever the
// load. A thick cylinder (a = 1, b = 2, E = 1000, nu = 0.3) under an
// internal pressure of 150, which blows it up by 48 % at large strain,
// gives Lame's linear u_r = (1 + nu) / E ((1 - 2 nu) A r + B / r), A = p
// a^2 / (b^2 - a^2), B = A b^2, at every node of the radius y = 0: as an
// axisymmetric section and as a plane-strain quarter ring (q2, 16 radial
// cells; the tolerance of the small-load test axisymmetric_thick_cylinder_
// is_plane_strain). At large strain the same load is 68 % of u_r(a) away.

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
  /** The largest |u_r - Lame| / u_r(a) along y = 0. */
  double
  worst_against_lame(const std::vector<std::string> &overrides,
                     const std::string              &label)
  {
    std::vector<std::string> all = overrides;
    for (const std::string o : {"Output/Progress=false",
                                "Output/VTU interval=0",
                                "Output/Contact table interval=0",
                                "Load program/Stage increments=1"})
      all.push_back(o);
    all.push_back("Output/Directory=small_strain_" + label);
    Simulation simulation(
      SceneReader::read_file(source_path("prm/thick_cylinder.prm"), all));
    simulation.run();
    const double E = 1000., nu = 0.3, p = 150., a = 1., b = 2.;
    const double A = p * a * a / (b * b - a * a), B = A * b * b;
    const auto   u_r = [&](const double r) {
      return (1. + nu) / E * ((1. - 2. * nu) * A * r + B / r);
    };
    const Body &body  = simulation.body("cylinder");
    double      worst = 0.;
    for (unsigned int i = 0; i <= 16; ++i)
      {
        const double r = 1. + i / 16.;
        worst =
          std::max(worst,
                   std::abs(vertex_displacement(body, Point<2>(r, 0.))[0] -
                            u_r(r)) /
                     u_r(a));
      }
    std::cout << "  " << label << ": largest |u_r - Lame| / u_r(a) " << worst
              << std::endl;
    return worst;
  }

  const std::vector<std::string> ring = thick_cylinder_as_plane_ring("150*t");
} // namespace

GLISSADE_TEST(small_strain_is_lame_at_any_load)
{
  const std::string small = "Body cylinder/Material/Kinematics=small strain",
                    load  = "Body cylinder/Boundary conditions/Pressure=left: "
                            "150*t";
  check(worst_against_lame({small, load}, "axisymmetric") <= 1e-5,
        "the axisymmetric section at small strain is not Lame's cylinder");
  std::vector<std::string> ring_small = ring;
  ring_small.push_back(small);
  check(worst_against_lame(ring_small, "plane_ring") <= 1e-5,
        "the plane-strain ring at small strain is not Lame's cylinder");
  // (the same load at large strain: far from the linear answer)
  std::vector<std::string> ring_large = ring;
  ring_large.push_back("Load program/Stage increments=4");
  check(worst_against_lame(ring_large, "plane_ring_large_strain") > 0.1,
        "at large strain the load of 150 should not give Lame's answer");
}
