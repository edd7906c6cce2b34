#pragma once

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/boundary_conditions.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/cell_evaluator.h>
#include <glissade/material/body_materials.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The loads a body's assembly integrates cell by cell: tractions and
   * follower pressure on its boundary faces (Boundary conditions/Traction,
   * Pressure), its weight (Gravity) and its elastic foundation, springs
   * -k u per unit volume (Elastic foundation). Point loads are nodal forces,
   * which BoundaryConditions::add_point_loads gives directly.
   *
   * They are added in the assembly's sequential copier, cell after cell:
   * their muParser functions hold a time and are not safe to share between
   * threads.
   */
  class DistributedLoads
  {
  public:
    /** `where` names the body for messages ("file: Body name"). */
    DistributedLoads(const BodyDescription    &description,
                     const BoundaryConditions &conditions,
                     const BodyMaterials      &materials,
                     const std::string        &where);

    /**
     * Adds the loads of `cell` at time t under the displacement u to its
     * right-hand side, and the follower pressure's tangent to its matrix.
     * `evaluator` is reinitialised on the cell and its faces.
     */
    void
    add_cell_loads(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      const std::vector<dealii::types::global_dof_index>         &local_dofs,
      const dealii::Vector<double>                               &u,
      const double                                                time,
      CellEvaluator                                              &evaluator,
      dealii::FullMatrix<double>                                 &cell_matrix,
      dealii::Vector<double> &cell_rhs) const;

  private:
    /** Tractions and pressure on the cell's boundary faces. */
    void
    add_surface_loads(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      const std::vector<dealii::types::global_dof_index>         &local_dofs,
      const dealii::Vector<double>                               &u,
      const double                                                time,
      CellEvaluator                                              &evaluator,
      dealii::FullMatrix<double>                                 &cell_matrix,
      dealii::Vector<double> &cell_rhs) const;

    /** The elastic foundation's forces -k u of the cell and their tangent
     *  k N N^T (a mass matrix times k). */
    void
    add_foundation(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      const std::vector<dealii::types::global_dof_index>         &local_dofs,
      const dealii::Vector<double>                               &u,
      CellEvaluator                                              &evaluator,
      dealii::FullMatrix<double>                                 &cell_matrix,
      dealii::Vector<double> &cell_rhs) const;

    /** The weight rho g of the cell. */
    void
    add_weight(const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
               const double                                                time,
               CellEvaluator          &evaluator,
               dealii::Vector<double> &cell_rhs) const;

    const BoundaryConditions &conditions;
    const BodyMaterials      &materials;
    /** The body's plane strain, plane stress or revolution. */
    const Hypothesis hypothesis;
    const bool       small_strain;
    /** Boundary conditions/Gravity: an acceleration of x, y, t, or none. */
    std::unique_ptr<dealii::Function<2>> gravity;
    /** Boundary conditions/Elastic foundation: k, or 0 for none. */
    const double foundation_stiffness;
  };
} // namespace glissade
