// The loads a body's assembly integrates cell by cell: tractions, follower
// pressure, weight, elastic foundation
// (include/glissade/body/distributed_loads.h).

#include <glissade/base/user_function.h>
#include <glissade/body/distributed_loads.h>

#include <array>
#include <cmath>

namespace glissade
{
  using namespace dealii;

  DistributedLoads::DistributedLoads(const BodyDescription    &description,
                                     const BoundaryConditions &conditions,
                                     const BodyMaterials      &materials,
                                     const std::string        &where)
    : conditions(conditions)
    , materials(materials)
    , hypothesis(description.material.hypothesis,
                 description.material.thickness)
    , small_strain(description.material.kinematics == Kinematics::small_strain)
    , foundation_stiffness(description.elastic_foundation)
  {
    if (!description.gravity.empty())
      gravity =
        std::make_unique<UserFunction>(description.gravity,
                                       where + "/Boundary conditions/Gravity");
  }



  void
  DistributedLoads::add_cell_loads(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>         &local_dofs,
    const Vector<double>                               &u,
    const double                                        time,
    CellEvaluator                                      &evaluator,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_rhs) const
  {
    if (cell->at_boundary())
      add_surface_loads(
        cell, local_dofs, u, time, evaluator, cell_matrix, cell_rhs);
    if (gravity)
      add_weight(cell, time, evaluator, cell_rhs);
    if (foundation_stiffness > 0.)
      add_foundation(cell, local_dofs, u, evaluator, cell_matrix, cell_rhs);
  }



  void
  DistributedLoads::add_foundation(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>         &local_dofs,
    const Vector<double>                               &u,
    CellEvaluator                                      &evaluator,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_rhs) const
  {
    // Springs to the reference position: -k u per unit reference volume,
    // at the cell's quadrature points, so that its tangent is k times the
    // consistent mass matrix (what GetFEM's mass brick adds).
    evaluator.reinit(cell);
    const unsigned int  n_local = evaluator.dofs_per_cell();
    std::vector<double> cell_values(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      cell_values[i] = u(local_dofs[i]);
    for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
      {
        const Point<2> X    = evaluator.quadrature_point(q);
        const double   k_dV = foundation_stiffness * evaluator.JxW(q) *
                            hypothesis.out_of_plane_measure(X);
        const Tensor<1, 2> displacement = evaluator.value(cell_values, q);
        for (unsigned int i = 0; i < n_local; ++i)
          {
            const unsigned int ci = evaluator.displacement_component(i);
            const double       Ni = evaluator.shape_value(i, q);
            cell_rhs(i) -= k_dV * Ni * displacement[ci];
            for (unsigned int j = 0; j < n_local; ++j)
              if (evaluator.displacement_component(j) == ci)
                cell_matrix(i, j) += k_dV * Ni * evaluator.shape_value(j, q);
          }
      }
  }



  void
  DistributedLoads::add_surface_loads(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>         &local_dofs,
    const Vector<double>                               &u,
    const double                                        time,
    CellEvaluator                                      &evaluator,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_rhs) const
  {
    const auto &loads = conditions.surface_loads();
    if (loads.empty())
      return;
    const unsigned int n_local = evaluator.dofs_per_cell();

    for (const unsigned int f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        for (const auto &load : loads)
          {
            if (load.boundary != cell->face(f)->boundary_id())
              continue;
            evaluator.reinit(cell, f);
            load.function->set_time(time);
            std::vector<double> cell_values(n_local);
            for (unsigned int i = 0; i < n_local; ++i)
              cell_values[i] = u(local_dofs[i]);
            for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
              {
                const Point<2>     X  = evaluator.quadrature_point(q);
                const Tensor<1, 2> N0 = evaluator.normal_vector(q);
                // (a body of revolution: the ring of the reference surface,
                // 2 pi R dS; a traction is per unit reference area)
                const double dA =
                  evaluator.JxW(q) * hypothesis.out_of_plane_measure(X);
                if (!load.is_pressure)
                  {
                    // Dead traction per unit reference length.
                    const Tensor<1, 2> t(
                      {load.function->value(X, 0), load.function->value(X, 1)});
                    for (unsigned int i = 0; i < n_local; ++i)
                      cell_rhs(i) += evaluator.shape_value(i, q) *
                                     t[evaluator.displacement_component(i)] *
                                     dA;
                    continue;
                  }
                // Follower pressure: f = -p n da = -p cof(F) N0 dA (Nanson),
                // with cof(F) linear in F in 2D, hence the simple tangent.
                // Axisymmetric: da is the current ring, 2 pi x_r ds, that
                // is F_33 = x_r / R times the reference one (3D Nanson).
                // (small strain: on the undeformed body, a dead load)
                const Tensor<2, 2> F =
                  small_strain ? Tensor<2, 2>(unit_symmetric_tensor<2>()) :
                                 unit_symmetric_tensor<2>() +
                                   evaluator.gradient(cell_values, q);
                const double       p = load.function->value(X);
                const Tensor<1, 2> cof_F_N0(
                  {F[1][1] * N0[0] - F[1][0] * N0[1],
                   -F[0][1] * N0[0] + F[0][0] * N0[1]});
                const double hoop_stretch =
                  !small_strain && hypothesis.strains_the_hoop() ?
                    1. +
                      hypothesis.hoop_ratio(evaluator.value(cell_values, q)[0],
                                            X) :
                    1.;
                for (unsigned int i = 0; i < n_local; ++i)
                  {
                    const unsigned int ci = evaluator.displacement_component(i);
                    const double       Ni = evaluator.shape_value(i, q);
                    cell_rhs(i) -= p * Ni * cof_F_N0[ci] * hoop_stretch * dA;
                    for (unsigned int j = 0; j < n_local && !small_strain; ++j)
                      {
                        const unsigned int cj =
                          evaluator.displacement_component(j);
                        const Tensor<1, 2> g = evaluator.shape_grad(j, q);
                        double             d = 0.;
                        if (ci == 1 && cj == 0)
                          d = -g[1] * N0[0] + g[0] * N0[1];
                        else if (ci == 0 && cj == 1)
                          d = g[1] * N0[0] - g[0] * N0[1];
                        d *= hoop_stretch;
                        if (hypothesis.strains_the_hoop() && cj == 0)
                          d +=
                            cof_F_N0[ci] * evaluator.shape_value(j, q) / X[0];
                        cell_matrix(i, j) += p * Ni * d * dA;
                      }
                  }
              }
          }
      }
  }



  void
  DistributedLoads::add_weight(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const double                                        time,
    CellEvaluator                                      &evaluator,
    Vector<double>                                     &cell_rhs) const
  {
    // rho g per unit reference volume: the mass is the reference one
    // (total Lagrangian), so the weight is a dead load.
    const double rho = materials.density_of_cell(cell->material_id());
    if (!(rho > 0.))
      return;
    gravity->set_time(time);
    evaluator.reinit(cell);
    for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
      {
        const Point<2> X = evaluator.quadrature_point(q);
        const double dV = evaluator.JxW(q) * hypothesis.out_of_plane_measure(X);
        const std::array<double, 2> g = {
          {gravity->value(X, 0), gravity->value(X, 1)}};
        for (unsigned int i = 0; i < evaluator.dofs_per_cell(); ++i)
          cell_rhs(i) += rho * g[evaluator.displacement_component(i)] *
                         evaluator.shape_value(i, q) * dV;
      }
  }
} // namespace glissade
