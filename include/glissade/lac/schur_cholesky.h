#pragma once

#include <deal.II/lac/vector.h>

#include <glissade/lac/trailing_block_inverse.h>

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
  class SchurCholesky : public TrailingBlockInverse
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

    double analysis_seconds      = 0.;
    double factorization_seconds = 0.;

  private:
    /**
     * The columns of C asked for, from L_cc (trailing_factor): on one
     * process, formed and handed over as they are (the whole block kept
     * when it is formed).
     */
    void
    take_request(const std::vector<long> &wanted) override;

    void
    form_requested_columns() override;

    void
    hand_over_columns(std::vector<long>   &wanted,
                      std::vector<double> &columns) override;

    /** L_cc, copied out of the supernodes that hold it. */
    void
    trailing_factor(std::vector<double> &factor) const;

    struct Cholmod;
    std::unique_ptr<Cholmod> cholmod;
    std::vector<long>        last_unknowns;
    bool                     analysed = false;
    /** The positions asked for, and their columns once formed. */
    std::vector<long>   asked_positions;
    std::vector<double> formed_columns;
  };
} // namespace glissade
