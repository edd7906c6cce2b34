#pragma once

#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * Supernodal Cholesky factorisation (CHOLMOD) of a symmetric positive
   * definite matrix, with a chosen set of unknowns -- the contact dofs --
   * eliminated last, and the block of A^-1 on those unknowns.
   *
   * Why: the condensed contact problem needs W = H A^-1 H^T, that is the
   * block C of A^-1 on the m contact dofs. Forming it column by column
   * costs one full back-substitution per contact dof, m nnz(L), which at
   * 500 active nodes was 23 times the factorisation itself. With the
   * contact dofs ordered last (constrained AMD), P A P^T = L L^T has the
   * trailing m x m block L_cc, and since L^-1 is lower triangular,
   *   C = (L^-1)_cc^T (L^-1)_cc = (L_cc L_cc^T)^-1,
   * which LAPACK's dpotri forms in (2/3) m^3 flops, independent of the size
   * of the body. The price is a dense trailing block in the factor (the
   * Schur complement on the contact dofs is dense anyway).
   *
   * The matrix is handed over in compressed-column form with the full
   * (symmetric) pattern, sorted; only its upper triangle is read.
   */
  class SchurCholesky
  {
  public:
    SchurCholesky();
    SchurCholesky(const SchurCholesky &) = delete;
    SchurCholesky &
    operator=(const SchurCholesky &) = delete;
    ~SchurCholesky();

    /** The unknowns to eliminate last; a change redoes the analysis. */
    void
    set_last_unknowns(const std::vector<long> &unknowns);

    /**
     * Analysis (first call, or after the pattern or the last unknowns
     * changed) and numeric factorisation. Returns false, keeping no factor,
     * if the matrix is not positive definite: the caller then falls back on
     * an LU factorisation.
     */
    bool
    factorize(const long                 n,
              const std::vector<long>   &column_start,
              const std::vector<long>   &row_index,
              const std::vector<double> &values,
              const bool                 new_pattern);

    bool
    factorized() const;

    /** x <- A^-1 x. */
    void
    solve(dealii::Vector<double> &x) const;

    /**
     * Makes the columns of C, the block of A^-1 on the last unknowns, at
     * the given positions available (after factorize). When contact
     * touches only part of the declared area, few columns are needed: each
     * costs two triangular solves with L_cc (LAPACK dpotrs, 2 m^2 flops).
     * From a third of the m columns on, the whole block by dpotri
     * ((2/3) m^3) is cheaper and is formed instead. Columns already formed
     * for this factorisation are kept.
     */
    void
    compute_inverse_columns(const std::vector<long> &positions);

    /** Position of an unknown among the last unknowns, or -1. */
    long
    last_position(const long unknown) const
    {
      return unknown < static_cast<long>(position.size()) ? position[unknown] :
                                                            -1;
    }

    /** C between the last unknowns at positions i and j (column j formed). */
    double
    inverse_entry(const long i, const long j) const
    {
      return inverse_block[i + column_of[j] * n_last];
    }

    /** Columns of C formed for the current factorisation. */
    long
    n_inverse_columns() const
    {
      return n_last > 0 ? inverse_block.size() / n_last : 0;
    }

    double analysis_seconds      = 0.;
    double factorization_seconds = 0.;
    double inverse_seconds       = 0.;

  private:
    struct Cholmod;
    std::unique_ptr<Cholmod> cholmod;
    std::vector<long>        last_unknowns;
    std::vector<long>        position;
    long                     n_last   = 0;
    bool                     analysed = false;
    /** Formed columns of C, column major, n_last rows. */
    std::vector<double> inverse_block;
    /** Column of inverse_block holding C's column j, or -1. */
    std::vector<long> column_of;
  };
} // namespace glissade
