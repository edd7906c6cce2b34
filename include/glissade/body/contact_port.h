#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <glissade/lac/direct_solver.h>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * Where contact reads a body's linear system: the dofs contact may load
   * (the declared contact areas) and the compliance between them, the
   * block of the body's K^-1 with its supports held that the condensed
   * contact step assembles W = H K^-1 H^T from (CondensedProblem).
   *
   * When the tangent is symmetric the contact dofs are eliminated last
   * (SchurCholesky), and the compliance between any two of them comes from
   * the inverse of the factor's trailing block; otherwise each column
   * takes one solve, kept for as long as the factorisation is.
   */
  class ContactPort
  {
  public:
    /** A solve with the supports held: K x = f, condensed. */
    using HomogeneousSolve =
      std::function<void(const dealii::Vector<double> &force,
                         dealii::Vector<double>       &x)>;

    /** For a body of `n_dofs` dofs, with no contact dof declared yet. */
    explicit ContactPort(const dealii::types::global_dof_index n_dofs);

    /**
     * Declares the contact dofs: each follows free unknowns (itself, or
     * the entries of its constraint line; none for a fixed dof) with
     * weights. Returns those unknowns, which the factorisation is to
     * eliminate last.
     */
    std::vector<long>
    declare(const std::vector<dealii::types::global_dof_index> &contact_dofs,
            const dealii::AffineConstraints<double>            &constraints);

    /**
     * The compliance between contact dofs: block[i + j rows.size()] is
     * entry `rows[i]` of solve(e_{columns[j]}). With a Cholesky
     * factorisation (contact dofs last), the entries between declared
     * contact dofs from the inverse of the factor's trailing block, whose
     * columns at `columns` only are formed, and those of a dof not
     * declared from one solve for it (its column, and by symmetry its
     * row); otherwise one solve per column. Solves are kept for the
     * current factorisation. Collective on several
     * processes: every process calls it, each with its own `columns` (its
     * share of the loads), the same `rows`.
     */
    void
    compliance_block(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns,
      DirectSolver                                       &factorization,
      const HomogeneousSolve                             &solve,
      std::vector<double>                                &block);

    /**
     * Forms and keeps what compliance_block() for these `rows` and
     * `columns` reads (the factor's inverse columns, or the solves),
     * without reading it: where every body's columns are formed before
     * any is used (CondensedProblem). Collective as compliance_block().
     * Where ask_for_compliance() and form_asked_compliance() were called
     * for the same `rows` and `columns` (every body's in turn, so that the
     * hosts of several bodies' factorisations form their columns at once),
     * it completes what they began.
     */
    void
    prepare_compliance(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns,
      DirectSolver                                       &factorization,
      const HomogeneousSolve                             &solve);

    /** The first step of prepare_compliance(): what is wanted, asked for
     *  (collective). */
    void
    ask_for_compliance(
      const std::vector<dealii::types::global_dof_index> &rows,
      const std::vector<dealii::types::global_dof_index> &columns,
      DirectSolver                                       &factorization);

    /** The second: the columns of the factor's inverse asked for, formed
     *  where this process forms them (alone, not collective). */
    void
    form_asked_compliance(DirectSolver &factorization);

    /** The factorisation changed: the compliance kept is stale. */
    void
    forget_compliance()
    {
      contact_rows_resolved.clear();
      compliance_columns.clear();
      compliance_asked = false;
    }

  private:
    /**
     * Whether the declared contact dofs' compliance comes from the
     * Cholesky factor's inverse (contact dofs declared, an inverse block
     * held) rather than from solves; the same on every process
     * (collective).
     */
    bool
    reads_factor(const DirectSolver &factorization) const;

    /** Whether `dof` is among the declared contact dofs. */
    bool
    declared(const dealii::types::global_dof_index dof) const
    {
      return !contact_position.empty() && contact_position[dof] >= 0;
    }

    /** The positions among the factor's last unknowns that `columns`
     *  follow. */
    std::vector<long>
    factor_positions(
      const std::vector<dealii::types::global_dof_index> &columns,
      const TrailingBlockInverse                         &cholesky);

    /** The compliance between two declared contact dofs, from the
     *  Cholesky factor's inverse, the column's positions formed. */
    double
    entry_from_factor(const dealii::types::global_dof_index row,
                      const dealii::types::global_dof_index column,
                      const TrailingBlockInverse           &cholesky) const;

    const dealii::types::global_dof_index n_dofs;
    /**
     * Per dof, its index among the declared contact dofs (-1 if it is
     * not one), and per contact dof the free unknowns it follows with
     * weights: as dofs, and as positions among the factorisation's last
     * unknowns once it has been prepared.
     */
    std::vector<long>                                 contact_position;
    std::vector<std::vector<std::pair<long, double>>> contact_rows;
    std::vector<std::vector<std::pair<long, double>>> contact_rows_resolved;
    /** solve(e_dof) of the current factorisation, by dof. */
    std::map<dealii::types::global_dof_index, dealii::Vector<double>>
      compliance_columns;
    /**
     * Between ask_for_compliance() and prepare_compliance(): the dofs
     * whose columns take a solve, and whether the declared ones' were
     * asked of the factor.
     */
    std::vector<unsigned long> lacking_columns;
    bool                       compliance_asked = false;
    bool                       asked_of_factor  = false;
  };
} // namespace glissade
