#pragma once

// Scenes and measures of the NURBS tests (nurbs_test.cc,
// nurbs_multipatch_test.cc).

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>

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
} // namespace glissade_tests
