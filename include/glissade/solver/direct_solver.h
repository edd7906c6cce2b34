#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace glissade
{
  using namespace dealii;

  /**
   * UMFPACK, called directly rather than through deal.II's
   * SparseDirectUMFPACK, for two savings that matter in a Newton loop with
   * contact:
   * - the symbolic analysis (ordering) depends only on the sparsity
   *   pattern, which never changes during a run: it is done once and kept;
   * - a solve skips UMFPACK's iterative refinement: Newton and the contact
   *   loop correct the residual anyway, and the compliance matrix needs one
   *   back-substitution per contact dof and iteration, so each one counts.
   */
  class DirectSolver
  {
  public:
    DirectSolver() = default;
    DirectSolver(const DirectSolver &) = delete;
    DirectSolver &
    operator=(const DirectSolver &) = delete;
    ~DirectSolver();

    /** LU of A (symbolic analysis reused while the pattern is the same). */
    void
    factorize(const SparseMatrix<double> &matrix);

    /** x <- A^-1 x. */
    void
    solve(Vector<double> &rhs_and_solution) const;

    /** Seconds spent in the symbolic and numeric phases so far. */
    double symbolic_seconds = 0.;
    double numeric_seconds  = 0.;

  private:
    void
    free_numeric();

    const SparsityPattern *pattern = nullptr;
    std::vector<long>      row_start, column_index;
    std::vector<double>    values;
    void                  *symbolic = nullptr;
    void                  *numeric  = nullptr;
    mutable std::vector<double> solution;
  };
} // namespace glissade
