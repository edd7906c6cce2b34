#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/contact_port.h>
#include <glissade/body/rigid_motion_springs.h>
#include <glissade/fe/element_space.h>
#include <glissade/lac/direct_solver.h>

#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The linear system of one body at a Newton iteration: the constraints
   * of the iteration, the tangent and right-hand side that Body::assemble
   * adds to through them, their direct factorisation (CHOLMOD Cholesky with
   * the contact dofs last, or UMFPACK LU) and the solves with it. Bodies
   * meet only through contact forces, so the global system is
   * block-diagonal by body and each block is factorised here alone.
   *
   * Contact reads the system through two parts it owns: the ContactPort
   * (the contact dofs and the compliance between them) and, for a body its
   * supports leave free, the RigidMotionSprings added to the tangent before
   * it is factorised.
   */
  class BodyLinearSystem
  {
  public:
    using CellList = std::vector<dealii::DoFHandler<2>::active_cell_iterator>;

    /**
     * The system on `dofs` under `constraints`: which dofs they constrain
     * never changes during a run (only the prescribed values do), so the
     * sparsity pattern is built once. Cholesky where `symmetric` (no
     * follower pressure), LU otherwise. `cells_here` are the cells whose
     * integrals this process adds (Body::own_cells): its tangent holds
     * their couplings alone, and on several processes MUMPS sums the
     * shares (on one process they are all the cells, the tangent whole).
     */
    BodyLinearSystem(const dealii::DoFHandler<2>        &dofs,
                     const ElementSpace                 &space,
                     dealii::AffineConstraints<double> &&constraints,
                     const bool                          symmetric,
                     RigidMotionSprings                &&springs,
                     const CellList                     &cells_here);

    /**
     * The constraints of the current iteration (the element's own and the
     * Dirichlet data, with the inhomogeneity this correction must bring),
     * which each assembly writes anew (BoundaryConditions::
     * make_constraints): a step computed outside the body is completed by
     * their distribute().
     */
    const dealii::AffineConstraints<double> &
    constraints() const;
    dealii::AffineConstraints<double> &
    constraints();

    /**
     * Tangent and right-hand side to zero, before an assembly (the
     * tangent's entries made again if release_tangent() let them go).
     * Without the tangent (with_tangent false), the right-hand side alone:
     * add_cell() then adds the cells' vectors, the cell matrices serving
     * only the constraints' inhomogeneities, and the tangent is neither
     * made nor touched (a correction with the last factorisation, or a
     * residual that only tests convergence, needs no new one).
     */
    void
    clear(const bool with_tangent = true);

    /**
     * Lets the tangent's entries go until the next assembly, once the
     * factorisation holds what it needs of them: the condensed contact
     * method reads the factor alone, and the dense contact algebra that
     * follows is where a run's memory peaks (74 MB per body of the
     * million-dof rings). The sparsity pattern stays.
     */
    void
    release_tangent();

    /** Adds a cell's matrix and right-hand side, through the constraints
     *  (the right-hand side alone after clear(false)). */
    void
    add_cell(const dealii::FullMatrix<double>                   &cell_matrix,
             const dealii::Vector<double>                       &cell_rhs,
             const std::vector<dealii::types::global_dof_index> &local_dofs);

    /**
     * In a run on several processes, where each assembled its share of the
     * cells: the right-hand side summed over the processes, so that every
     * process holds it whole. The tangent stays each process's share (the
     * integrals of its cells), which MUMPS sums as it reads them: no
     * process holds the whole matrix.
     */
    void
    sum_right_hand_side_over_processes();

    /**
     * The diagonal of the whole tangent (on several processes, the shares'
     * diagonals summed: collective).
     */
    std::vector<double>
    tangent_diagonal() const;

    /** Adds nodal forces to the right-hand side, through the constraints. */
    void
    add_nodal_forces(const dealii::Vector<double> &forces);

    /**
     * The tangent of the last assembly (benchmarks factorise it again;
     * empty after release_tangent() until the next assembly); on
     * several processes, this process's share of it
     * (sum_right_hand_side_over_processes).
     */
    const dealii::SparseMatrix<double> &
    tangent_matrix() const;

    /** F_ext - F_int of the last assembly, condensed. */
    const dealii::Vector<double> &
    right_hand_side() const;

    /**
     * Factorises the tangent with the springs of regularization() added
     * (the tangent itself is left as assembled).
     */
    void
    factorize();

    /** The factorisation (method used, timings). */
    const DirectSolver &
    direct_solver() const;

    /** Solves K du = rhs; constrained dofs get their prescribed increment. */
    void
    solve(const dealii::Vector<double> &rhs,
          dealii::Vector<double>       &increment) const;

    /**
     * The response to an external force vector f with the supports held:
     * K x = f condensed, constrained dofs following their free ones with no
     * prescribed part. The contact compliance columns K^-1 H^T.
     */
    void
    solve_homogeneous(const dealii::Vector<double> &force,
                      dealii::Vector<double>       &x) const;

    /**
     * True for a dof whose value the boundary conditions prescribe (fixed
     * or driven): no force moves it.
     */
    bool
    dof_is_prescribed(const dealii::types::global_dof_index dof) const;

    /**
     * The dofs that contact may load (declared contact areas): eliminated
     * last where the tangent is symmetric (ContactPort), and, for a body
     * with free rigid motions, the candidates for its springs.
     */
    void
    set_contact_dofs(
      const std::vector<dealii::types::global_dof_index> &contact_dofs);

    /**
     * What compliance_block() reads, formed and kept without reading it:
     * ContactPort::prepare_compliance(), and its first two steps.
     */
    void
    prepare_compliance(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns);

    void
    ask_for_compliance(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns)
    {
      port.ask_for_compliance(rows, columns, factorization);
    }

    void
    form_asked_compliance()
    {
      port.form_asked_compliance(factorization);
    }

    /** The contact block of K^-1: ContactPort::compliance_block(). */
    void
    compliance_block(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns,
      std::vector<double>                                &block);

    /**
     * The rigid motions that the body's supports leave free, which contact
     * must hold (ContactProblem checks that it can before computing).
     */
    const std::vector<RigidMotion> &
    free_rigid_motions() const;

    /** Under a dynamic scheme the mass holds every motion: none is free. */
    void
    hold_rigid_motions_by_inertia();

    /** The springs added to the tangent, as (dof, k): RigidMotionSprings. */
    const std::vector<std::pair<dealii::types::global_dof_index, double>> &
    regularization() const;

  private:
    const dealii::DoFHandler<2> &dofs;
    const ElementSpace          &space;
    /** Dofs no cell has (a NURBS space's numbering): 1 on the diagonal. */
    std::vector<dealii::types::global_dof_index> numbering_only_dofs;
    const bool                                   symmetric;
    dealii::AffineConstraints<double>            iteration_constraints;
    dealii::SparsityPattern                      sparsity;
    dealii::SparseMatrix<double>                 tangent;
    /** Whether the assembly under way adds to the tangent (clear()). */
    bool                   assembling_tangent = true;
    dealii::Vector<double> system_rhs;
    DirectSolver           factorization;
    RigidMotionSprings     springs;
    ContactPort            port;
  };



  inline const dealii::AffineConstraints<double> &
  BodyLinearSystem::constraints() const
  {
    return iteration_constraints;
  }



  inline dealii::AffineConstraints<double> &
  BodyLinearSystem::constraints()
  {
    return iteration_constraints;
  }



  inline const dealii::SparseMatrix<double> &
  BodyLinearSystem::tangent_matrix() const
  {
    return tangent;
  }



  inline const dealii::Vector<double> &
  BodyLinearSystem::right_hand_side() const
  {
    return system_rhs;
  }



  inline const DirectSolver &
  BodyLinearSystem::direct_solver() const
  {
    return factorization;
  }



  inline const std::vector<RigidMotion> &
  BodyLinearSystem::free_rigid_motions() const
  {
    return springs.free_motions();
  }



  inline void
  BodyLinearSystem::hold_rigid_motions_by_inertia()
  {
    springs.hold_by_inertia();
  }



  inline const std::vector<std::pair<dealii::types::global_dof_index, double>> &
  BodyLinearSystem::regularization() const
  {
    return springs.springs();
  }
} // namespace glissade
