#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/body_inertia.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/cell_evaluator.h>
#include <glissade/fe/element_space.h>
#include <glissade/fe/evaluator_pool.h>
#include <glissade/material/body_materials.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * What the material of one cell adds to a body's tangent and internal
   * forces: the worker of Body::assemble's WorkStream, as step-44's
   * assemble_system_one_cell, with its per-thread Scratch and the
   * CellContribution it hands to the sequential copier.
   *
   * At each quadrature point: the stress of the displacement gradient and
   * its tangent, with the geometric stiffness at large strain; the hoop
   * terms of an axisymmetric body; the viscous stress of stiffness damping
   * (viscous_stress.h). A small-strain cell's stiffness K_e does not depend
   * on u: it is integrated once and kept, and its forces are K_e u_e. A
   * dynamic body's inertia terms (BodyInertia) come last.
   */
  class CellIntegration
  {
  public:
    /**
     * What one thread keeps from cell to cell: the evaluator and, at a
     * quadrature point, each dof's shape gradient and strain variation.
     */
    struct Scratch
    {
      Scratch(EvaluatorPool &evaluators, const unsigned int n_local);
      Scratch(const Scratch &other);

      EvaluatorPool                             &evaluators;
      BorrowedEvaluator                          evaluator;
      std::vector<dealii::Tensor<1, 2>>          grad;
      std::vector<dealii::SymmetricTensor<2, 2>> dE, D_dE;
      // (axisymmetric: each dof's hoop strain variation dE_33 and the hoop
      // stress variation dS_33 it causes)
      std::vector<double> dE33, dS33;
      // (stiffness damping: the cell's velocity dofs)
      std::vector<double> cell_velocity;
      // (small strain: the cell's displacement or velocity dofs, and K_e
      // times them)
      dealii::Vector<double> cell_values, cell_product;
      // (a dynamic body: the cell's accelerations, BodyInertia)
      std::vector<double> inertia_work;
    };

    /** What one cell hands to the copier, which adds it to the body. */
    struct CellContribution
    {
      explicit CellContribution(const unsigned int n_local);

      // The surface loads are added to them in the (sequential) copier,
      // which WorkStream hands a const reference.
      mutable dealii::FullMatrix<double>           cell_matrix;
      mutable dealii::Vector<double>               cell_rhs;
      dealii::Vector<double>                       viscous_force;
      std::vector<dealii::types::global_dof_index> local_dofs;
      std::string rejection; // why, if inadmissible
      typename dealii::DoFHandler<2>::active_cell_iterator cell;
    };

    /** For the `n_cells` cells of a body of `space` and `materials`. */
    CellIntegration(const ElementSpace        &space,
                    const BodyMaterials       &materials,
                    const MaterialDescription &material,
                    const unsigned int         n_cells);

    /** The shape functions of a cell. */
    unsigned int
    dofs_per_cell() const
    {
      return component.size();
    }

    /**
     * Integrates `cell` at the displacement u, with the terms of `inertia`
     * if it is not null: `data` gets the cell's tangent (both triangles),
     * F_ext - F_int without loads, the viscous force and, if a point is
     * inadmissible (an inverted element, a stress beyond double
     * precision), why. May run on several threads at once: each cell
     * writes only its own slot of the kept stiffness.
     */
    void
    integrate(const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
              const dealii::Vector<double>                               &u,
              const BodyInertia *inertia,
              Scratch           &scratch,
              CellContribution  &data);

    /**
     * Small strain: the stiffness K_e of the cell with this active index,
     * once an assembly has integrated it; null at large strain or before.
     * 1/2 u_e . K_e u_e is then the cell's strain energy, the quadrature
     * of 1/2 eps : D_0 : eps with the same rule.
     */
    const dealii::FullMatrix<double> *
    kept_stiffness(const unsigned int active_cell_index) const
    {
      if (!small_strain || kept_linear_stiffness[active_cell_index].empty())
        return nullptr;
      return &kept_linear_stiffness[active_cell_index];
    }

  private:
    /** Stiffness damping's a_K, dv/du and the material at rest (D_0). */
    struct Damping
    {
      double                a_K             = 0.;
      double                velocity_factor = 0.;
      MaterialPointResponse at_rest;
    };

    /**
     * The terms of quadrature point q to the lower triangle of the cell's
     * matrix and to its right-hand side; none, and data.rejection set,
     * where the state is inadmissible.
     */
    void
    add_point_terms(const unsigned int            q,
                    const Material               &cell_material,
                    const Damping                &damping,
                    const dealii::Vector<double> &u,
                    Scratch                      &scratch,
                    CellContribution             &data) const;

    /**
     * The stress's work and its tangent at an admissible point: F (the
     * identity at small strain), the hoop strain u_r / r at the reference
     * radius r, and the volume dV the point stands for.
     */
    void
    add_stress_terms(const unsigned int           q,
                     const dealii::Tensor<2, 2>  &F,
                     const double                 hoop,
                     const double                 r,
                     const double                 dV,
                     const MaterialPointResponse &response,
                     Scratch                     &scratch,
                     CellContribution            &data) const;

    /**
     * Small strain: keeps K_e once integrated; later, F_int = K_e u_e
     * exactly. With stiffness damping, a_K K_e v_e and its tangent.
     */
    void
    add_kept_stiffness_terms(dealii::FullMatrix<double>   &kept,
                             const bool                    just_integrated,
                             const Damping                &damping,
                             const dealii::Vector<double> &u,
                             Scratch                      &scratch,
                             CellContribution             &data) const;

    const ElementSpace  &space;
    const BodyMaterials &materials;
    /** The body's plane strain, plane stress or revolution. */
    const Hypothesis hypothesis;
    /** The virtual strains and the equilibrium on the undeformed body. */
    const bool small_strain;
    /** The displacement component of each shape function. */
    std::vector<unsigned int> component;
    /** Small strain: each cell's stiffness K_e, integrated once (empty
     *  until then; at large strain unused). */
    std::vector<dealii::FullMatrix<double>> kept_linear_stiffness;
  };
} // namespace glissade
