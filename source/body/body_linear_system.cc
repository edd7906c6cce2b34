// The linear system of one body: its factorisation and solves, the springs
// of a body held by contact, and its contact port
// (include/glissade/body/body_linear_system.h).

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <glissade/base/processes.h>
#include <glissade/body/body_linear_system.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  BodyLinearSystem::BodyLinearSystem(const DoFHandler<2>        &dofs,
                                     const ElementSpace         &space,
                                     AffineConstraints<double> &&constraints,
                                     const bool                  symmetric,
                                     RigidMotionSprings        &&springs,
                                     const CellList             &cells_here)
    : dofs(dofs)
    , space(space)
    , symmetric(symmetric)
    , iteration_constraints(std::move(constraints))
    , system_rhs(dofs.n_dofs())
    , springs(std::move(springs))
    , port(dofs.n_dofs())
  {
    // The couplings of this process's cells, as make_sparsity_pattern
    // makes them for all.
    DynamicSparsityPattern               dsp(dofs.n_dofs());
    std::vector<types::global_dof_index> local_dofs;
    std::vector<double>                  touched(dofs.n_dofs(), 0.);
    for (const auto &cell : cells_here)
      {
        space.cell_dof_indices(cell, local_dofs);
        iteration_constraints.add_entries_local_to_global(local_dofs,
                                                          dsp,
                                                          false);
        for (const auto dof : local_dofs)
          touched[dof] = 1.;
      }
    // A space that numbers its unknowns into a finite element's dofs
    // (NURBS) leaves dofs that no cell has, constrained to zero: a 1 on
    // their diagonal keeps the tangent regular. (No cell of any process:
    // on several, a dof that this process's cells leave may be another's,
    // and the 1 would be added to its stiffness. Process 0 puts the 1,
    // which the factorisation sums once.)
    if (!space.capabilities().dofs_are_nodal_values)
      {
        processes::sum(touched);
        if (processes::rank() == 0)
          for (types::global_dof_index i = 0; i < touched.size(); ++i)
            if (touched[i] == 0.)
              {
                dsp.add(i, i);
                numbering_only_dofs.push_back(i);
              }
      }
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    // (a body in contact sets its contact dofs to eliminate last later,
    // set_contact_dofs)
    factorization.use_cholesky(symmetric, {});
  }



  void
  BodyLinearSystem::clear(const bool with_tangent)
  {
    assembling_tangent = with_tangent;
    if (with_tangent)
      {
        if (tangent.empty())
          tangent.reinit(sparsity);
        else
          tangent = 0.;
        for (const auto i : numbering_only_dofs)
          tangent.set(i, i, 1.);
      }
    system_rhs = 0.;
  }



  void
  BodyLinearSystem::release_tangent()
  {
    tangent.clear();
  }



  void
  BodyLinearSystem::add_cell(
    const FullMatrix<double>                   &cell_matrix,
    const Vector<double>                       &cell_rhs,
    const std::vector<types::global_dof_index> &local_dofs)
  {
    if (assembling_tangent)
      iteration_constraints.distribute_local_to_global(
        cell_matrix, cell_rhs, local_dofs, tangent, system_rhs);
    else
      iteration_constraints.distribute_local_to_global(cell_rhs,
                                                       local_dofs,
                                                       system_rhs,
                                                       cell_matrix);
  }



  void
  BodyLinearSystem::sum_right_hand_side_over_processes()
  {
    // (the tangent stays each process's share: MUMPS sums it)
    processes::sum(system_rhs.begin(), system_rhs.size());
  }



  std::vector<double>
  BodyLinearSystem::tangent_diagonal() const
  {
    std::vector<double> diagonal(tangent.m());
    for (types::global_dof_index i = 0; i < tangent.m(); ++i)
      diagonal[i] = tangent.diag_element(i);
    processes::sum(diagonal);
    return diagonal;
  }



  void
  BodyLinearSystem::add_nodal_forces(const Vector<double> &forces)
  {
    std::vector<types::global_dof_index> index(1);
    Vector<double>                       value(1);
    for (types::global_dof_index i = 0; i < forces.size(); ++i)
      if (forces(i) != 0.)
        {
          index[0] = i;
          value(0) = forces(i);
          iteration_constraints.distribute_local_to_global(value,
                                                           index,
                                                           system_rhs);
        }
  }



  void
  BodyLinearSystem::factorize()
  {
    // The springs as stiff as an average dof of the whole tangent (added
    // once, to one process's share).
    double k = 0.;
    if (!springs.springs().empty())
      {
        for (const double d : tangent_diagonal())
          k += std::abs(d);
        k /= tangent.m();
      }
    const std::vector<double> assembled =
      springs.add_to(tangent, k, processes::adds_terms_held_once());
    const bool refactored = factorization.factorize(tangent);
    springs.take_from(tangent, assembled);
    if (refactored)
      port.forget_compliance();
  }



  void
  BodyLinearSystem::solve(const Vector<double> &rhs,
                          Vector<double>       &increment) const
  {
    increment = rhs;
    factorization.solve(increment);
    iteration_constraints.distribute(increment);
  }



  void
  BodyLinearSystem::solve_homogeneous(const Vector<double> &force,
                                      Vector<double>       &x) const
  {
    x = force;
    iteration_constraints.condense(x);
    for (const auto &line : iteration_constraints.get_lines())
      x(line.index) = 0.;
    factorization.solve(x);
    for (const auto &line : iteration_constraints.get_lines())
      {
        double value = 0.;
        for (const auto &[j, w] : line.entries)
          value += w * x(j);
        x(line.index) = value;
      }
  }



  bool
  BodyLinearSystem::dof_is_prescribed(const types::global_dof_index dof) const
  {
    if (!iteration_constraints.is_constrained(dof))
      return false;
    const auto *line = iteration_constraints.get_constraint_entries(dof);
    return line == nullptr || line->empty();
  }



  void
  BodyLinearSystem::set_contact_dofs(
    const std::vector<types::global_dof_index> &contact_dofs)
  {
    factorization.use_cholesky(symmetric,
                               port.declare(contact_dofs,
                                            iteration_constraints));
    if (!springs.free_motions().empty())
      springs.choose_dofs(contact_dofs, iteration_constraints, dofs, space);
  }



  void
  BodyLinearSystem::compliance_block(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns,
    std::vector<double>                        &block)
  {
    port.compliance_block(
      rows,
      columns,
      factorization,
      [this](const Vector<double> &force, Vector<double> &x) {
        solve_homogeneous(force, x);
      },
      block);
  }



  void
  BodyLinearSystem::prepare_compliance(
    const std::vector<types::global_dof_index> &rows,
    const std::vector<types::global_dof_index> &columns)
  {
    port.prepare_compliance(rows,
                            columns,
                            factorization,
                            [this](const Vector<double> &force,
                                   Vector<double>       &x) {
                              solve_homogeneous(force, x);
                            });
  }
} // namespace glissade
