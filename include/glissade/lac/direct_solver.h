#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/lac/mumps_factorization.h>
#include <glissade/lac/schur_cholesky.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * UMFPACK, called directly rather than through deal.II's
   * SparseDirectUMFPACK, for two savings that matter in a Newton loop with
   * contact:
   * - the symbolic analysis (ordering) depends only on the sparsity
   *   pattern, which never changes during a run: it is done once and kept;
   * - a solve skips UMFPACK's iterative refinement: Newton and the contact
   *   loop correct the residual anyway, and the compliance matrix needs one
   *   back-substitution per contact dof and iteration, so each one counts.
   *
   * A symmetric matrix (no follower loads) is factorised by Cholesky with
   * the contact dofs eliminated last (SchurCholesky), which also yields the
   * block of A^-1 on those dofs without any back-substitution; if Cholesky
   * finds the matrix not positive definite (a tangent past a limit point),
   * that factorisation falls back on LU.
   *
   * In a run on several processes (mpirun), the matrix is factorised by
   * all of them together with MUMPS instead (MumpsFactorization): LDL^T
   * with the contact dofs' Schur complement where it is symmetric, LU
   * otherwise; the interface is the same, but each process's matrix is its
   * share of the whole one, which MUMPS sums (BodyLinearSystem).
   */
  class DirectSolver
  {
  public:
    DirectSolver()                     = default;
    DirectSolver(const DirectSolver &) = delete;
    DirectSolver &
    operator=(const DirectSolver &) = delete;
    ~DirectSolver();

    /**
     * Whether the matrices to come are symmetric, so that Cholesky may be
     * tried, and which unknowns it should eliminate last.
     */
    void
    use_cholesky(const bool symmetric, const std::vector<long> &last_unknowns);

    /**
     * LU only, with UMFPACK's unsymmetric ordering (COLAMD on A) rather than
     * the one it would choose: for the sparse contact system, a saddle
     * point whose pattern is nearly symmetric, the symmetric ordering's
     * analysis took twice the time of the whole factorisation with the
     * unsymmetric one (8,000 active nodes: 1.73 s against 0.79 s per
     * Newton iteration).
     */
    void
    use_unsymmetric_ordering()
    {
      symmetric            = false;
      unsymmetric_ordering = true;
    }

    /**
     * Cholesky or LU of A (analysis reused while the pattern is the same).
     * A matrix equal, entry for entry, to the one last factorised (a linear
     * body's dynamic tangent at a constant time step, step after step) is
     * not factorised again: returns false then, true after a new
     * factorisation.
     */
    bool
    factorize(const dealii::SparseMatrix<double> &matrix);

    /** x <- A^-1 x. */
    void
    solve(dealii::Vector<double> &rhs_and_solution) const;

    /**
     * True if the last factorisation was Cholesky: the block of A^-1 on the
     * last unknowns is then available through cholesky().
     */
    bool
    has_inverse_block() const
    {
      return cholesky_used ||
             (distributed != nullptr && distributed->has_inverse_block());
    }

    /** The block of A^-1 on the last unknowns (has_inverse_block()). */
    TrailingBlockInverse &
    inverse_block()
    {
      if (distributed != nullptr)
        return *distributed;
      return schur;
    }

    const TrailingBlockInverse &
    inverse_block() const
    {
      if (distributed != nullptr)
        return *distributed;
      return schur;
    }

    SchurCholesky &
    cholesky()
    {
      return schur;
    }

    const SchurCholesky &
    cholesky() const
    {
      return schur;
    }

    /** Seconds spent in the analysis and numeric phases so far (both methods).
     */
    double symbolic_seconds = 0.;
    double numeric_seconds  = 0.;
    /** Factorisations by each method (LU counts the Cholesky fall-backs). */
    unsigned int n_cholesky = 0, n_lu = 0;
    /** Matrices found equal to the last factorised one (kept). */
    unsigned int n_reused = 0;

  private:
    void
    free_numeric();

    void
    factorize_lu();

    /** factorize() on several processes: MUMPS, from this process's share. */
    bool
    factorize_on_processes(const dealii::SparseMatrix<double> &matrix);

    const dealii::SparsityPattern *pattern        = nullptr;
    std::size_t                    n_entries_seen = 0;
    std::vector<long>              row_start, column_index;
    std::vector<double>            values;
    void                          *symbolic = nullptr;
    void                          *numeric  = nullptr;
    mutable std::vector<double>    solution;

    bool symmetric = false;
    /** Whether a factorisation of `values` in the current elimination
     *  order (the last unknowns) is held. */
    bool              factorization_current = false;
    std::vector<long> last_unknowns_sorted;
    bool              unsymmetric_ordering = false;
    bool              cholesky_used        = false;
    SchurCholesky     schur;
    /** The factorisation of a run on several processes. */
    std::unique_ptr<MumpsFactorization> distributed;
  };
} // namespace glissade
