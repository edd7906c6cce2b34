// Patch tests: a homogeneous deformation X -> F X imposed on the boundary of
// a distorted mesh must be reproduced inside to round-off, because every
// element space contains the linear fields and a homogeneous state is in
// equilibrium. The stress is then checked against the closed-form
// neo-Hookean Cauchy stress, computed here independently of the code.


#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  const double young_modulus = 1000.;
  const double poisson_ratio = 0.3;
  /** The Mooney-Rivlin law's third constant, c2 / (c1 + c2). */
  const double mooney_rivlin_ratio = 0.3;

  std::string
  patch_scene(const std::string  &space,
              const Tensor<2, 2> &F,
              const std::string  &law,
              const std::string  &hypothesis,
              const unsigned int  increments,
              const bool          ring)
  {
    std::ostringstream ux, uy;
    ux.precision(17);
    uy.precision(17);
    ux << "(" << F[0][0] - 1 << "*x + " << F[0][1] << "*y)*t";
    uy << "(" << F[1][0] << "*x + " << F[1][1] - 1 << "*y)*t";
    const std::string  both = ux.str() + ", " + uy.str();
    std::ostringstream prm;
    prm << "subsection Scene\n set Bodies = block\nend\n"
        << "subsection Body block\n subsection Mesh\n";
    if (ring)
      prm << "  set Type = half ring\n  set Center = 0.2, -0.1\n"
          << "  set Inner radius = 0.5\n  set Outer radius = 1.2\n"
          << "  set Start angle = 10\n  set End angle = 130\n"
          << "  set Subdivisions = 6, 3\n end\n";
    else
      prm << "  set Type = rectangle\n"
          << "  set Corner 1 = 0, 0\n  set Corner 2 = 1, 1\n"
          << "  set Subdivisions = 4, 4\n  set Distortion = 0.3\n end\n";
    const std::string sides =
      ring ? "inner,outer,start,end" : "left,right,bottom,top";
    std::string conditions;
    for (const auto &side : Utilities::split_string_list(sides, ','))
      conditions += (conditions.empty() ? "" : "; ") + side + ": xy: " + both;
    prm << " subsection Element\n  set Space = " << space << "\n end\n"
        << " subsection Material\n  set Law = " << law << "\n"
        << "  set Mooney-Rivlin ratio = " << mooney_rivlin_ratio << "\n"
        << "  set Young modulus = " << young_modulus << "\n"
        << "  set Poisson ratio = " << poisson_ratio << "\n"
        << "  set Hypothesis = " << hypothesis << "\n end\n"
        << " subsection Boundary conditions\n"
        << "  set Prescribed displacement = " << conditions << "\n end\nend\n"
        << "subsection Load program\n set Stage increments = " << increments
        << "\nend\n"
        << "subsection Newton\n set Residual tolerance = 1e-12\n"
        << " set Displacement tolerance = 1e-12\nend\n"
        << "subsection Output\n set Progress = false\nend\n";
    return prm.str();
  }

  /** Closed-form neo-Hookean Cauchy stress for a homogeneous F. */
  SymmetricTensor<2, 3>
  neo_hookean_cauchy(const Tensor<2, 2> &F2, const bool plane_stress)
  {
    const double lambda = young_modulus * poisson_ratio /
                          ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
    const double mu = young_modulus / (2 * (1 + poisson_ratio));
    const double J2 = determinant(F2);
    // Plane stress: the thickness stretch l3 solves
    // sigma_33 = (mu (l3^2 - 1) + lambda ln(J2 l3)) / J = 0, by bisection.
    double l3 = 1.;
    if (plane_stress)
      {
        double lo = 1e-3, hi = 1e3;
        for (int i = 0; i < 200; ++i)
          {
            l3                = std::sqrt(lo * hi);
            const double s    = mu * (l3 * l3 - 1) + lambda * std::log(J2 * l3);
            (s > 0 ? hi : lo) = l3;
          }
      }
    const double          J = J2 * l3;
    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        sigma[i][j] = mu / J * (F2[i][0] * F2[j][0] + F2[i][1] * F2[j][1]);
    sigma[2][2] = mu / J * l3 * l3;
    for (unsigned int i = 0; i < 3; ++i)
      sigma[i][i] += (-mu + lambda * std::log(J)) / J;
    return sigma;
  }

  /**
   * Closed-form plane-strain Mooney-Rivlin Cauchy stress, from W = c1 (I1
   * - 3) + c2 (I2 - 3) - (2 c1 + 4 c2) ln J + lambda_w / 2 (ln J)^2 with c1
   * + c2 = mu / 2, c2 = ratio mu / 2, lambda_w = lambda - 4 c2 (Hooke's
   * constants at small strain): sigma = (2 c1 B + 2 c2 (I1 B - B^2) - (2
   * c1 + 4 c2 - lambda_w ln J) I) / J, B = F F^T.
   */
  SymmetricTensor<2, 3>
  mooney_rivlin_cauchy(const Tensor<2, 2> &F2)
  {
    const double lambda = young_modulus * poisson_ratio /
                          ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
    const double mu       = young_modulus / (2 * (1 + poisson_ratio));
    const double c2       = 0.5 * mooney_rivlin_ratio * mu;
    const double c1       = 0.5 * mu - c2;
    const double lambda_w = lambda - 4 * c2;
    Tensor<2, 3> F;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        F[i][j] = F2[i][j];
    F[2][2]                = 1.;
    const Tensor<2, 3> B   = F * transpose(F);
    const double       J   = determinant(F);
    const Tensor<2, 3> sig = (2 * c1 * B + 2 * c2 * (trace(B) * B - B * B) -
                              (2 * c1 + 4 * c2 - lambda_w * std::log(J)) *
                                Tensor<2, 3>(unit_symmetric_tensor<3>())) /
                             J;
    return symmetrize(sig);
  }

  /** Closed-form plane-stress Saint Venant-Kirchhoff Cauchy stress. */
  SymmetricTensor<2, 3>
  svk_plane_stress_cauchy(const Tensor<2, 2> &F)
  {
    const double lambda = young_modulus * poisson_ratio /
                          ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
    const double mu           = young_modulus / (2 * (1 + poisson_ratio));
    const double lambda_plane = 2 * lambda * mu / (lambda + 2 * mu);
    Tensor<2, 2> E            = 0.5 * (transpose(F) * F);
    E[0][0] -= 0.5;
    E[1][1] -= 0.5;
    const double E33 = -lambda / (lambda + 2 * mu) * (E[0][0] + E[1][1]);
    Tensor<2, 2> S   = 2 * mu * E;
    S[0][0] += lambda_plane * (E[0][0] + E[1][1]);
    S[1][1] += lambda_plane * (E[0][0] + E[1][1]);
    const double          J     = determinant(F) * std::sqrt(1 + 2 * E33);
    const Tensor<2, 2>    sigma = F * S * transpose(F) / J;
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        result[i][j] = sigma[i][j];
    return result;
  }

  void
  run_patch(const std::string  &space,
            const Tensor<2, 2> &F,
            const std::string  &law,
            const std::string  &hypothesis,
            const unsigned int  increments,
            const bool          ring = false)
  {
    const SceneDescription scene = SceneReader::read_string(
      patch_scene(space, F, law, hypothesis, increments, ring), "patch test");
    Simulation simulation(scene);
    for (unsigned int k = 1; k <= increments; ++k)
      simulation.advance_to(double(k) / increments, "increment");
    const Body &body = simulation.body("block");

    // Displacement, its gradient and the Cauchy stress at the points of a
    // Gauss rule richer than the assembly's, against u = (F - I) X.
    const bool                  plane_stress = (hypothesis == "plane stress");
    const SymmetricTensor<2, 3> exact_sigma =
      // (Law = energy's default formula is the neo-Hookean energy)
      law == "neo-Hookean" || law == "energy" ?
        neo_hookean_cauchy(F, plane_stress) :
      law == "Mooney-Rivlin" ? mooney_rivlin_cauchy(F) :
                               svk_plane_stress_cauchy(F);
    const auto          evaluator = body.space().create_evaluator(5);
    std::vector<double> values(evaluator->dofs_per_cell());
    const Tensor<2, 2>  exact_H = F - unit_symmetric_tensor<2>();
    double max_u_error = 0., max_u = 0., max_H_error = 0., max_sigma_error = 0.;
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        evaluator->reinit(cell);
        cell->get_dof_values(body.displacement(), values.begin(), values.end());
        for (unsigned int q = 0; q < evaluator->n_quadrature_points(); ++q)
          {
            const Tensor<1, 2> u       = evaluator->value(values, q);
            const Tensor<2, 2> H       = evaluator->gradient(values, q);
            const Point<2>     X       = evaluator->quadrature_point(q);
            const Tensor<1, 2> exact_u = exact_H * X;
            max_u_error = std::max(max_u_error, (u - exact_u).norm());
            max_u       = std::max(max_u, exact_u.norm());
            max_H_error = std::max(max_H_error, (H - exact_H).norm());
            max_sigma_error =
              std::max(max_sigma_error,
                       (body.materials().of_body().cauchy_stress(H) -
                        exact_sigma)
                         .norm());
          }
      }
    std::cout << "  space " << space
              << (ring ? " on a ring mesh" : " on a distorted mesh") << ", "
              << law << ", " << hypothesis << ": max |u_h - u| " << max_u_error
              << " (max |u| " << max_u << "), max |H_h - H| " << max_H_error
              << ", max |sigma_h - sigma| / |sigma| "
              << max_sigma_error / exact_sigma.norm() << std::endl;
    check(max_u_error <= 1e-10 * max_u, "displacement is not exact");
    check(max_H_error <= 1e-9 * exact_H.norm(),
          "displacement gradient is not exact");
    check(max_sigma_error <= 1e-8 * exact_sigma.norm(),
          "Cauchy stress differs from the closed form");
  }

  Tensor<2, 2>
  small_strain_gradient()
  {
    return Tensor<2, 2>({{1 + 2e-5, 1e-5}, {-0.5e-5, 1 - 1e-5}});
  }

  Tensor<2, 2>
  large_strain_gradient()
  {
    // Stretch, shear and a rotation of about 20 degrees: J = 1.1.
    return Tensor<2, 2>({{1.35, 0.55}, {-0.25, 0.9}});
  }
} // namespace

// Every element space, on a distorted mesh and on a ring mesh, small and
// large strain (neo-Hookean, plane strain); plus plane stress and Saint
// Venant-Kirchhoff on Q1.
#define PATCH_TESTS(space)                                                \
  GLISSADE_TEST(patch_small_strain_##space)                               \
  {                                                                       \
    run_patch(                                                            \
      #space, small_strain_gradient(), "neo-Hookean", "plane strain", 1); \
  }                                                                       \
  GLISSADE_TEST(patch_large_strain_##space)                               \
  {                                                                       \
    run_patch(                                                            \
      #space, large_strain_gradient(), "neo-Hookean", "plane strain", 4); \
  }                                                                       \
  GLISSADE_TEST(patch_ring_large_strain_##space)                          \
  {                                                                       \
    run_patch(#space,                                                     \
              large_strain_gradient(),                                    \
              "neo-Hookean",                                              \
              "plane strain",                                             \
              4,                                                          \
              true);                                                      \
  }

PATCH_TESTS(q1)
PATCH_TESTS(q2)
PATCH_TESTS(q3)
PATCH_TESTS(q8)
PATCH_TESTS(q12)
PATCH_TESTS(hermite)

GLISSADE_TEST(patch_large_strain_plane_stress_q1)
{
  run_patch("q1", large_strain_gradient(), "neo-Hookean", "plane stress", 4);
}

GLISSADE_TEST(patch_large_strain_svk_q1)
{
  run_patch(
    "q1", large_strain_gradient(), "Saint Venant-Kirchhoff", "plane stress", 4);
}

// A law with a third constant (LawRegistry, doc/adding_a_material.md): the
// Mooney-Rivlin law with c2 / (c1 + c2) = 0.3, large strain, plane strain,
// on Q1 and on Q2 meshes of the ring.
GLISSADE_TEST(patch_large_strain_mooney_rivlin_q1)
{
  run_patch("q1", large_strain_gradient(), "Mooney-Rivlin", "plane strain", 4);
}

GLISSADE_TEST(patch_ring_large_strain_mooney_rivlin_q2)
{
  run_patch(
    "q2", large_strain_gradient(), "Mooney-Rivlin", "plane strain", 4, true);
}

// A law given by its strain energy alone (Law = energy, its default formula
// the neo-Hookean energy; energy_law_test.cc): the neo-Hookean closed form,
// plane strain on a distorted Q1 mesh and on a Q2 ring, plane stress on Q1.
GLISSADE_TEST(patch_large_strain_energy_law_q1)
{
  run_patch("q1", large_strain_gradient(), "energy", "plane strain", 4);
}

GLISSADE_TEST(patch_ring_large_strain_energy_law_q2)
{
  run_patch("q2", large_strain_gradient(), "energy", "plane strain", 4, true);
}

GLISSADE_TEST(patch_large_strain_plane_stress_energy_law_q1)
{
  run_patch("q1", large_strain_gradient(), "energy", "plane stress", 4);
}
