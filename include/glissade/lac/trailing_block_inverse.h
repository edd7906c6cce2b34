#pragma once

#include <vector>

namespace glissade
{
  /**
   * The block C of A^-1 on a chosen set of m unknowns (the contact dofs),
   * from the Cholesky factor L_S of the Schur complement S of A on them:
   * C = S^-1 = (L_S L_S^T)^-1. Both factorisations that eliminate the
   * contact dofs last provide L_S: CHOLMOD's trailing block of the whole
   * factor (SchurCholesky, one process) and MUMPS's Schur complement,
   * factorised densely (MumpsFactorization, several processes); the
   * columns of C are formed here alike.
   *
   * Columns are formed on demand: each costs two triangular solves (LAPACK
   * dpotrs, 2 m^2 flops); from a third of the m columns on, the whole
   * block by dpotri ((2/3) m^3) is cheaper and is formed instead. Columns
   * already formed for the current factorisation are kept: all of the
   * whole block, or only those asked for where `keep_only_asked_columns`
   * (on several processes each asks for its share of the columns, and
   * keeping the whole block would hold it on every process).
   */
  class TrailingBlockInverse
  {
  public:
    virtual ~TrailingBlockInverse() = default;

    /**
     * Makes the columns of C at the given positions (among the m
     * unknowns) available.
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

    double inverse_seconds = 0.;

  protected:
    /**
     * L_S, lower triangle, column major, m x m (the strict upper triangle
     * is not read). `last_use`: the whole block is being formed, so that a
     * copy kept only for the columns may be handed over instead of copied
     * (a later call must then make it again).
     */
    virtual void
    trailing_factor(std::vector<double> &factor, const bool last_use) const = 0;

    /**
     * Whether `value` holds on any of the processes that share the
     * factorisation (collective there; one process: `value`).
     */
    virtual bool
    on_any_process(const bool value) const
    {
      return value;
    }

    /**
     * Collective where several processes share the factorisation, before
     * trailing_factor() on any of them: each is made to hold L_S. (Each
     * asks for its own columns of C, so not every process that takes part
     * forms any.)
     */
    virtual void
    share_trailing_factor() const
    {}

    /** A new factorisation: the columns formed are stale. */
    void
    forget_inverse_columns()
    {
      // (released, not only emptied: the next factorisation needs the room)
      std::vector<double>().swap(inverse_block);
      column_of.clear();
    }

    /** Per unknown of A, its position among the m last ones, or -1. */
    std::vector<long> position;
    long              n_last = 0;

    /** Keep only the columns asked for when the whole block is formed. */
    bool keep_only_asked_columns = false;

  private:
    /** Formed columns of C, column major, n_last rows. */
    std::vector<double> inverse_block;
    /** Column of inverse_block holding C's column j, or -1. */
    std::vector<long> column_of;
  };
} // namespace glissade
