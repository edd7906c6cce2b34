// What the material of one cell adds to a body's tangent and internal
// forces (include/glissade/body/cell_integration.h).

#include <glissade/body/cell_integration.h>
#include <glissade/body/viscous_stress.h>

#include <cmath>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  CellIntegration::Scratch::Scratch(EvaluatorPool     &evaluators,
                                    const unsigned int n_local)
    : evaluators(evaluators)
    , evaluator(evaluators.borrow())
    , grad(n_local)
    , dE(n_local)
    , D_dE(n_local)
    , dE33(n_local)
    , dS33(n_local)
    , cell_velocity(n_local)
    , cell_values(n_local)
    , cell_product(n_local)
  {}



  CellIntegration::Scratch::Scratch(const Scratch &other)
    : Scratch(other.evaluators, other.grad.size())
  {}



  CellIntegration::CellContribution::CellContribution(
    const unsigned int n_local)
    : cell_matrix(n_local, n_local)
    , cell_rhs(n_local)
    , viscous_force(n_local)
    , local_dofs(n_local)
  {}



  CellIntegration::CellIntegration(const ElementSpace        &space,
                                   const BodyMaterials       &materials,
                                   const MaterialDescription &material,
                                   const unsigned int         n_cells)
    : space(space)
    , materials(materials)
    , hypothesis(material.hypothesis, material.thickness)
    , small_strain(material.kinematics == Kinematics::small_strain)
    , kept_linear_stiffness(small_strain ? n_cells : 0)
  {
    const auto evaluator = space.create_evaluator();
    component.resize(evaluator->dofs_per_cell());
    for (unsigned int i = 0; i < component.size(); ++i)
      component[i] = evaluator->displacement_component(i);
  }



  void
  CellIntegration::integrate(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const Vector<double>                               &u,
    const BodyInertia                                  *inertia,
    Scratch                                            &scratch,
    CellContribution                                   &data)
  {
    const unsigned int n_local     = component.size();
    auto              &cell_matrix = data.cell_matrix;
    auto              &cell_rhs    = data.cell_rhs;
    data.cell                      = cell;
    data.rejection.clear();
    space.cell_dof_indices(cell, data.local_dofs);
    cell_matrix                   = 0.;
    cell_rhs                      = 0.;
    data.viscous_force            = 0.;
    const Material &cell_material = materials.of_cell(cell->material_id());
    // Stiffness damping: the material at rest and the cell's velocity.
    Damping damping;
    damping.a_K = inertia ? inertia->stiffness_damping() : 0.;
    if (damping.a_K > 0.)
      {
        damping.velocity_factor = inertia->velocity_factor();
        if (!small_strain)
          damping.at_rest = cell_material.evaluate(Tensor<2, 2>(), 0.);
        inertia->cell_velocity(data.local_dofs, u, scratch.cell_velocity);
      }
    // A small-strain cell's stiffness K_e does not depend on u: it is
    // integrated once and kept, and its forces are K_e u_e (each cell
    // writes its own slot: safe on every thread).
    FullMatrix<double> &kept =
      small_strain ? kept_linear_stiffness[cell->active_cell_index()] :
                     cell_matrix;
    const bool integrate_points = !small_strain || kept.empty();
    if (integrate_points)
      {
        scratch.evaluator->reinit(cell);
        for (unsigned int q = 0; q < scratch.evaluator->n_quadrature_points();
             ++q)
          add_point_terms(q, cell_material, damping, u, scratch, data);
        for (unsigned int i = 0; i < n_local; ++i)
          for (unsigned int j = i + 1; j < n_local; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
      }
    if (small_strain)
      add_kept_stiffness_terms(
        kept, integrate_points, damping, u, scratch, data);
    // A dynamic scheme's inertia (BodyInertia: read only, so shared by
    // the threads).
    if (inertia)
      inertia->add_cell_terms(cell->active_cell_index(),
                              data.local_dofs,
                              u,
                              cell_matrix,
                              cell_rhs,
                              scratch.inertia_work);
  }



  void
  CellIntegration::add_point_terms(const unsigned int    q,
                                   const Material       &cell_material,
                                   const Damping        &damping,
                                   const Vector<double> &u,
                                   Scratch              &scratch,
                                   CellContribution     &data) const
  {
    const unsigned int n_local   = component.size();
    CellEvaluator     &evaluator = *scratch.evaluator;
    auto              &grad      = scratch.grad;
    // Every shape function is primitive: Grad N_i has a single non-zero
    // row (its component c_i), which makes every contraction below a small
    // dot product.
    Tensor<2, 2> H; // displacement gradient
    for (unsigned int i = 0; i < n_local; ++i)
      {
        grad[i] = evaluator.shape_grad(i, q);
        H[component[i]] += u(data.local_dofs[i]) * grad[i];
      }
    const Tensor<2, 2> F = small_strain ?
                             Tensor<2, 2>(unit_symmetric_tensor<2>()) :
                             unit_symmetric_tensor<2>() + H;
    // A body of revolution: the hoop stretch F_33 = 1 + u_r / r, r the
    // reference radius of the point (> 0 at every quadrature point of a
    // mesh in r >= 0), and the volume of the ring 2 pi r dA.
    double         hoop = 0.;
    const Point<2> X    = evaluator.quadrature_point(q);
    const double   r    = X[0];
    if (hypothesis.strains_the_hoop())
      {
        double u_r = 0.;
        for (unsigned int i = 0; i < n_local; ++i)
          if (component[i] == 0)
            u_r += u(data.local_dofs[i]) * evaluator.shape_value(i, q);
        hoop = hypothesis.hoop_ratio(u_r, X);
      }
    const double J = determinant(unit_symmetric_tensor<2>() + H) * (1. + hoop);
    if (!(J > 0.) || !std::isfinite(J) || !(1. + hoop > 0.))
      {
        std::ostringstream why;
        why << "is inverted, det F = " << J
            << " (an increment too large for the deformation, or a "
               "mesh too coarse for it)";
        if (data.rejection.empty())
          data.rejection = why.str();
        return;
      }
    const MaterialPointResponse response = cell_material.evaluate(H, hoop);
    // The tangent too: at u = 0 the stress is zero however large E is, and
    // only the stiffness overflows.
    if (!std::isfinite(response.stress.norm()) ||
        !std::isfinite(response.tangent.norm()))
      {
        std::ostringstream why;
        const auto [young_modulus, entry] =
          materials.young_modulus_of_cell(data.cell->material_id());
        why << "has a stress or stiffness that is not finite: the " << entry
            << " (" << young_modulus
            << ") times the strain is beyond double precision; "
               "express the scene in other units";
        if (data.rejection.empty())
          data.rejection = why.str();
        return;
      }
    const double dV = evaluator.JxW(q) * hypothesis.out_of_plane_measure(X);
    add_stress_terms(q, F, hoop, r, dV, response, scratch, data);
    if (damping.a_K > 0. && !small_strain)
      add_viscous_stress_terms(
        damping.a_K,
        damping.velocity_factor,
        ViscousStressPoint{
          damping.at_rest, F, 1. + hoop, r, hypothesis.strains_the_hoop(), dV},
        evaluator,
        q,
        component,
        grad,
        scratch.dE,
        scratch.dE33,
        scratch.cell_velocity,
        data.cell_matrix,
        data.cell_rhs,
        data.viscous_force);
  }



  void
  CellIntegration::add_stress_terms(const unsigned int           q,
                                    const Tensor<2, 2>          &F,
                                    const double                 hoop,
                                    const double                 r,
                                    const double                 dV,
                                    const MaterialPointResponse &response,
                                    Scratch                     &scratch,
                                    CellContribution            &data) const
  {
    const unsigned int   n_local     = component.size();
    const CellEvaluator &evaluator   = *scratch.evaluator;
    const auto          &grad        = scratch.grad;
    auto                &dE          = scratch.dE;
    auto                &D_dE        = scratch.D_dE;
    auto                &dE33        = scratch.dE33;
    auto                &dS33        = scratch.dS33;
    auto                &cell_matrix = data.cell_matrix;
    auto                &cell_rhs    = data.cell_rhs;
    const Tensor<2, 2>   P           = F * Tensor<2, 2>(response.stress);

    for (unsigned int i = 0; i < n_local; ++i)
      {
        const unsigned int c = component[i];
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = a; b < 2; ++b)
            dE[i][a][b] = 0.5 * (F[c][a] * grad[i][b] + F[c][b] * grad[i][a]);
        D_dE[i] = response.tangent * dE[i];
        cell_rhs(i) -= (P[c] * grad[i]) * dV;
        if (hypothesis.strains_the_hoop())
          {
            // dE_33 = F_33 du_r / r; the hoop stress works on it.
            dE33[i] = c == 0 ? (small_strain ? 1. : 1. + hoop) *
                                 evaluator.shape_value(i, q) / r :
                               0.;
            D_dE[i] += response.hoop_coupling * dE33[i];
            dS33[i] = response.hoop_coupling * dE[i] +
                      response.hoop_stiffness * dE33[i];
            cell_rhs(i) -= response.hoop_stress * dE33[i] * dV;
          }
      }
    for (unsigned int i = 0; i < n_local; ++i)
      {
        const Tensor<1, 2> S_grad_i = Tensor<2, 2>(response.stress) * grad[i];
        for (unsigned int j = 0; j <= i; ++j)
          {
            double k = dE[j] * D_dE[i];
            if (component[i] == component[j] && !small_strain)
              k += S_grad_i * grad[j];
            if (hypothesis.strains_the_hoop())
              {
                k += dE33[j] * dS33[i];
                // d(dE_33)/du_r = N_i N_j / r^2 (radial dofs)
                if (component[i] == 0 && component[j] == 0 && !small_strain)
                  k += response.hoop_stress * evaluator.shape_value(i, q) *
                       evaluator.shape_value(j, q) / (r * r);
              }
            cell_matrix(i, j) += k * dV;
          }
      }
  }



  void
  CellIntegration::add_kept_stiffness_terms(FullMatrix<double> &kept,
                                            const bool          just_integrated,
                                            const Damping      &damping,
                                            const Vector<double> &u,
                                            Scratch              &scratch,
                                            CellContribution     &data) const
  {
    const unsigned int n_local     = component.size();
    auto              &cell_matrix = data.cell_matrix;
    auto              &cell_rhs    = data.cell_rhs;
    if (just_integrated)
      kept = cell_matrix;
    else
      {
        // F_int = K_e u_e, exactly (linear elasticity). (Entry by entry:
        // FullMatrix's assignment allocates its storage anew.)
        for (unsigned int i = 0; i < n_local; ++i)
          for (unsigned int j = 0; j < n_local; ++j)
            cell_matrix(i, j) = kept(i, j);
        for (unsigned int i = 0; i < n_local; ++i)
          scratch.cell_values(i) = u(data.local_dofs[i]);
        kept.vmult(scratch.cell_product, scratch.cell_values);
        cell_rhs -= scratch.cell_product;
      }
    // The viscous stress a_K D_0 : d(epsilon)/dt: a_K K_e v_e, its tangent
    // a_K c_v K_e.
    if (damping.a_K > 0.)
      {
        for (unsigned int i = 0; i < n_local; ++i)
          scratch.cell_values(i) = scratch.cell_velocity[i];
        kept.vmult(data.viscous_force, scratch.cell_values);
        data.viscous_force *= damping.a_K;
        cell_rhs -= data.viscous_force;
        cell_matrix.add(damping.a_K * damping.velocity_factor, kept);
      }
  }
} // namespace glissade
