// Normal and tangential supports (Fixed = boundary: n or t) on a curved
// boundary, against Lame's closed form for a thick ring under internal
// pressure (plane strain, small strain: p / E = 1e-4).

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  constexpr double a = 1., b = 2., E = 1e4, nu = 0.3, p = 1.;

  /** A ring a < r < b, pressure p on r = a, the outer support given. */
  Simulation
  pressed_ring(const std::string &outer_support)
  {
    std::ostringstream prm;
    prm << "subsection Scene\n set Bodies = ring\nend\n"
        << "subsection Body ring\n subsection Mesh\n  set Type = ring\n"
        << "  set Inner radius = " << a << "\n  set Outer radius = " << b
        << "\n  set Subdivisions = 80, 16\n end\n"
        << " subsection Material\n  set Young modulus = " << E
        << "\n  set Poisson ratio = " << nu << "\n end\n"
        << " subsection Boundary conditions\n  set Fixed = " << outer_support
        << "\n  set Pressure = inner: " << p << "*t\n end\nend\n"
        << "subsection Output\n set Progress = false\n"
        << " set Directory = supports_test\nend\n";
    Simulation simulation(SceneReader::read_string(prm.str(), "supports"));
    simulation.advance_to(1., "increment 1");
    return simulation;
  }

  /** u_r and u_theta at the nodes of radius r (largest deviations). */
  struct RadialField
  {
    double mean_radial = 0., radial_spread = 0., largest_tangential = 0.;
  };

  RadialField
  field_at_radius(const Simulation &simulation, const double r)
  {
    const Body  &ring = const_cast<Simulation &>(simulation).body("ring");
    RadialField  f;
    double       smallest = 1e300, largest = -1e300, sum = 0.;
    unsigned int n = 0;
    for (const auto &X : ring.triangulation().get_vertices())
      if (std::abs(X.norm() - r) < 1e-9)
        {
          const Tensor<1, 2> u  = vertex_displacement(ring, X);
          const Tensor<1, 2> er = X / X.norm();
          const double       ur = u * er;
          const double       ut = u[1] * er[0] - u[0] * er[1];
          smallest              = std::min(smallest, ur);
          largest               = std::max(largest, ur);
          sum += ur;
          ++n;
          f.largest_tangential = std::max(f.largest_tangential, std::abs(ut));
        }
    check(n == 80, "80 nodes at r = " + std::to_string(r));
    f.mean_radial   = sum / n;
    f.radial_spread = (largest - smallest) / std::abs(f.mean_radial);
    return f;
  }

  double
  lame_lambda()
  {
    return E * nu / ((1. + nu) * (1. - 2. * nu));
  }

  double
  lame_mu()
  {
    return E / (2. * (1. + nu));
  }
} // namespace

// Outer boundary on rollers (u . n = 0 at every node of r = b): u_r(b) = 0
// and u(r) = A (r - b^2 / r) with 2 (lambda + mu) A + 2 mu A b^2 / a^2 = -p.
// Rollers all round leave the rotation free (refused: input_free_rotation
// _on_rollers); one tangential point support holds it, with no force, as
// Lame's field has no u_theta.
GLISSADE_TEST(supports_normal_ring_lame)
{
  const Simulation  simulation = pressed_ring("outer: n; point(2, 0): y");
  const RadialField inner      = field_at_radius(simulation, a);
  const RadialField outer      = field_at_radius(simulation, b);
  const double      A =
    -p / (2. * (lame_lambda() + lame_mu()) + 2. * lame_mu() * b * b / (a * a));
  const double expected = A * (a - b * b / a);
  check_relative(inner.mean_radial, expected, 2e-3, "u_r(a), outer on rollers");
  std::cout << "  u_r(b) " << outer.mean_radial << " (|u_r(a)| "
            << std::abs(inner.mean_radial) << "), u_r spread at a "
            << inner.radial_spread << ", largest u_theta "
            << std::max(inner.largest_tangential, outer.largest_tangential)
            << std::endl;
  check(std::abs(outer.mean_radial) <= 1e-12 * std::abs(inner.mean_radial),
        "u_r(b) = 0 on the rollers");
  check(inner.radial_spread <= 1e-9, "an axisymmetric u_r at r = a");
}

// Outer boundary held tangentially only (u . t = 0): free to expand, so the
// free ring's u_r(b) = p a^2 b / ((b^2 - a^2)) (1 / (2 (lambda + mu)) +
// 1 / (2 mu)), and the support carries no rigid rotation.
GLISSADE_TEST(supports_tangential_ring_lame)
{
  const Simulation  simulation = pressed_ring("outer: t");
  const RadialField outer      = field_at_radius(simulation, b);
  const double      expected =
    p * a * a * b / (b * b - a * a) *
    (1. / (2. * (lame_lambda() + lame_mu())) + 1. / (2. * lame_mu()));
  check_relative(outer.mean_radial,
                 expected,
                 2e-3,
                 "u_r(b), outer held tangentially");
  std::cout << "  u_r spread at b " << outer.radial_spread
            << ", largest u_theta at b " << outer.largest_tangential
            << std::endl;
  check(outer.largest_tangential <= 1e-12 * outer.mean_radial,
        "u_theta(b) = 0 on the tangential support");
  check(outer.radial_spread <= 1e-9, "an axisymmetric u_r at r = b");
}
