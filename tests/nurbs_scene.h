#pragma once

// Scenes and measures of the NURBS tests (nurbs_test.cc,
// nurbs_multipatch_test.cc).

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace glissade_tests
{
  using namespace glissade;
  using namespace dealii;

  /** A NURBS body `mesh` (the Mesh subsection's entries) in plane
   *  strain, `conditions` its boundary conditions. */
  inline std::string
  nurbs_scene(const std::string &mesh,
              const unsigned int degree,
              const std::string &kinematics,
              const std::string &conditions,
              const std::string &label)
  {
    return "subsection Scene\n set Bodies = ring\nend\n"
           "subsection Body ring\n subsection Mesh\n" +
           mesh +
           "\n end\n subsection Element\n  set Space = nurbs\n"
           "  set Degree = " +
           std::to_string(degree) +
           "\n end\n subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n  set Hypothesis = plane strain\n"
           "  set Kinematics = " +
           kinematics + "\n end\n subsection Boundary conditions\n" +
           conditions +
           "\n end\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-13\n"
           " set Displacement tolerance = 1e-13\nend\n"
           "subsection Output\n set Progress = false\n set Plots = false\n"
           " set VTU interval = 0\n set Directory = output/nurbs_" +
           label + "\nend\n";
  }

  /** A quarter ring a = 1 < r < b = 2; Lame's problem when `conditions`
   *  are symmetric supports and a pressure. */
  inline std::string
  quarter_ring(const unsigned int degree,
               const unsigned int n_around,
               const unsigned int n_through,
               const std::string &kinematics,
               const std::string &conditions,
               const std::string &label)
  {
    return nurbs_scene("  set Type = half ring\n  set Inner radius = 1\n"
                       "  set Outer radius = 2\n  set Start angle = 0\n"
                       "  set End angle = 90\n  set Subdivisions = " +
                         std::to_string(n_around) + ", " +
                         std::to_string(n_through),
                       degree,
                       kinematics,
                       conditions,
                       label);
  }

  /** The errors of a body's displacement against u(X) and grad u(X),
   *  relative to u's norms, on `points` Gauss points a direction. */
  inline std::pair<double, double>
  relative_errors(const Body                                          &body,
                  const std::function<Tensor<1, 2>(const Point<2> &)> &u,
                  const std::function<Tensor<2, 2>(const Point<2> &)> &grad,
                  const unsigned int                                   points)
  {
    const auto evaluator = body.space().create_evaluator(points);
    std::vector<types::global_dof_index> local;
    std::vector<double>                  values;
    double                               e0 = 0., e1 = 0., n0 = 0., n1 = 0.;
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        evaluator->reinit(cell);
        body.space().cell_dof_indices(cell, local);
        values.resize(local.size());
        for (unsigned int i = 0; i < local.size(); ++i)
          values[i] = body.displacement()(local[i]);
        for (unsigned int q = 0; q < evaluator->n_quadrature_points(); ++q)
          {
            const Point<2> X = evaluator->quadrature_point(q);
            e0 += (evaluator->value(values, q) - u(X)).norm_square() *
                  evaluator->JxW(q);
            e1 += (evaluator->gradient(values, q) - grad(X)).norm_square() *
                  evaluator->JxW(q);
            n0 += u(X).norm_square() * evaluator->JxW(q);
            n1 += grad(X).norm_square() * evaluator->JxW(q);
          }
      }
    return {std::sqrt(e0 / n0), std::sqrt(e1 / n1)};
  }

  /** What a scene is refused with, or "accepted". */
  inline std::string
  refusal(const std::string &scene)
  {
    try
      {
        Simulation simulation(SceneReader::read_string(scene, "scene.prm"));
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "accepted";
  }

  /** The largest relative difference of two lists of figures (to the
   *  largest magnitude of the first). */
  inline double
  largest_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double scale = 0., worst = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        scale = std::max(scale, std::abs(a[i]));
        worst = std::max(worst, std::abs(a[i] - b[i]));
      }
    return worst / scale;
  }

  /** The largest error of a body's nodal view (the displacement at every
   *  node of the output's elements) against u(X). */
  inline double
  largest_nodal_error(const Body                                          &body,
                      const std::function<Tensor<1, 2>(const Point<2> &)> &u)
  {
    std::map<types::global_dof_index, Point<2>> support;
    DoFTools::map_dofs_to_support_points(body.space().mapping(),
                                         body.dof_handler(),
                                         support);
    const auto                          &fe    = body.dof_handler().get_fe();
    const auto                          &nodal = body.nodal_displacement();
    double                               worst = 0.;
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          worst = std::max(
            worst,
            std::abs(
              nodal(local[i]) -
              u(support[local[i]])[fe.system_to_component_index(i).first]));
      }
    return worst;
  }

  /** The patch tests' affine field u = a + G X: its components as a
   *  scene's expressions (at t = 1), its value and its gradient. */
  inline const std::string affine_field_x = "(0.01 + 0.02*x - 0.03*y)*t",
                           affine_field_y = "(-0.02 + 0.015*x + 0.025*y)*t";

  inline Tensor<1, 2>
  affine_field(const Point<2> &X)
  {
    return Tensor<1, 2>(
      {0.01 + 0.02 * X[0] - 0.03 * X[1], -0.02 + 0.015 * X[0] + 0.025 * X[1]});
  }

  inline Tensor<2, 2>
  affine_field_gradient(const Point<2> &)
  {
    return Tensor<2, 2>({{0.02, -0.03}, {0.015, 0.025}});
  }

  /**
   * Lame's thick ring a = 1 < r < b = 2 under an inner pressure p, plane
   * strain, small strain (E = 1000, nu = 0.3): u_r = (1 + nu) / E ((1 -
   * 2 nu) A r + B / r), A = p a^2 / (b^2 - a^2), B = A b^2; the
   * displacement and its gradient at X.
   */
  struct LameRing
  {
    double E = 1000., nu = 0.3, p = 1e-4, a = 1., b = 2.;

    double
    u_r(const double r) const
    {
      const double A = p * a * a / (b * b - a * a), B = A * b * b;
      return (1. + nu) / E * ((1. - 2. * nu) * A * r + B / r);
    }

    Tensor<1, 2>
    u(const Point<2> &X) const
    {
      return u_r(X.norm()) / X.norm() * Tensor<1, 2>(X);
    }

    Tensor<2, 2>
    grad(const Point<2> &X) const
    {
      const double A = p * a * a / (b * b - a * a), B = A * b * b;
      const double r    = X.norm();
      const double du_r = (1. + nu) / E * ((1. - 2. * nu) * A - B / (r * r));
      const Tensor<1, 2> e_r({X[0] / r, X[1] / r}), e_t({-X[1] / r, X[0] / r});
      return du_r * outer_product(e_r, e_r) +
             u_r(r) / r * outer_product(e_t, e_t);
    }
  };
} // namespace glissade_tests
