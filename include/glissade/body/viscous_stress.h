#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/material/material.h>

#include <vector>

namespace glissade
{
  class CellEvaluator;

  /**
   * Stiffness-proportional Rayleigh damping for finite motions (Time
   * integration/Stiffness damping = a_K): a Kelvin-Voigt viscous stress on
   * the rate of the Green-Lagrange strain,
   *   S_v = a_K D_0 : dE/dt,   dE/dt = sym(F^T Grad v),
   * with D_0 the material's tangent at rest (and, axisymmetric, the hoop
   * rate dE_33/dt = F_33 v_r / r with D_0's hoop terms). For small motions
   * its force is a_K K_0 v, Rayleigh's C = a_K K; unlike a_K K_0 v it
   * vanishes for a rigid motion at any rotation (dE/dt = 0), so a spinning
   * or tumbling body is not braked (ctest dynamics_stiffness_damping_*).
   * A mode of frequency omega is damped at the ratio a_K omega / 2.
   *
   * The tangent is the symmetric part of the exact one: dS_v/du = a_K D_0 :
   * (c_v dE_j + sym(Grad N_j^T Grad v)) keeps its first term (c_v = dv/du
   * of the scheme) and drops the second, which is unsymmetric and of the
   * order of the strain increment of a step against the first; the
   * geometric term Grad N_i . S_v Grad N_j is kept. Newton then converges
   * linearly at that small rate, and the bodies' Cholesky factorisation
   * is kept. (A small-strain body takes a_K K_e v_e from its kept cell
   * stiffness instead: CellIntegration.)
   */
  struct ViscousStressPoint
  {
    /** The material's response at rest (D_0 and its hoop terms). */
    const MaterialPointResponse &at_rest;
    /** The deformation gradient in the plane, and F_33 (a body of
     *  revolution). */
    const dealii::Tensor<2, 2> &F;
    double                      hoop_stretch;
    /** The reference radius of the point (a body of revolution only). */
    double radius;
    /** Hypothesis::strains_the_hoop() */
    bool strains_the_hoop;
    /** The volume the point stands for (2 pi r dA or thickness dA). */
    double dV;
  };

  /**
   * Adds the viscous stress's terms at quadrature point q of a cell:
   * `cell_rhs` loses the viscous force, which `cell_viscous_force` gains
   * (for the energy account), and the lower triangle of `cell_matrix`
   * gains its tangent. `grad`, `dE` (sym(F^T Grad N_i)) and `dE33` (F_33
   * N_i / r, axisymmetric) are the assembly's, `cell_velocity` the cell's
   * velocity dofs and `velocity_factor` dv/du of the step.
   */
  void
  add_viscous_stress_terms(const double                     a_K,
                           const double                     velocity_factor,
                           const ViscousStressPoint        &point,
                           const CellEvaluator             &evaluator,
                           const unsigned int               q,
                           const std::vector<unsigned int> &component,
                           const std::vector<dealii::Tensor<1, 2>> &grad,
                           const std::vector<dealii::SymmetricTensor<2, 2>> &dE,
                           const std::vector<double>  &dE33,
                           const std::vector<double>  &cell_velocity,
                           dealii::FullMatrix<double> &cell_matrix,
                           dealii::Vector<double>     &cell_rhs,
                           dealii::Vector<double>     &cell_viscous_force);
} // namespace glissade
