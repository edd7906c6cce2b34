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
   * factorised densely on MUMPS's host (MumpsFactorization, several
   * processes); the columns of C are formed from it alike
   * (columns_of_inverse).
   *
   * Columns are formed on demand: each costs two triangular solves (LAPACK
   * dpotrs, 2 m^2 flops); from a third of the m columns on, the whole
   * block by dpotri ((2/3) m^3) is cheaper and is formed instead. Columns
   * already formed for the current factorisation are kept: all of the
   * whole block on one process; on several, each process keeps the
   * columns it asked for (its share of the contact's columns), which the
   * host forms and sends it (holding the whole block, or L_S, on every
   * process would be 82 MB per body at 3,200 contact dofs).
   */
  class TrailingBlockInverse
  {
  public:
    virtual ~TrailingBlockInverse() = default;

    /**
     * Makes the columns of C at the given positions (among the m
     * unknowns) available: the three steps below at once. Collective
     * where several processes share the factorisation.
     */
    void
    compute_inverse_columns(const std::vector<long> &positions)
    {
      ask_for_inverse_columns(positions);
      form_asked_inverse_columns();
      receive_inverse_columns();
    }

    /**
     * The steps of compute_inverse_columns(), taken for every body's
     * factorisation in turn, so that the hosts of several factorisations
     * form their columns at once: the columns at `positions` asked for
     * (collective), ...
     */
    void
    ask_for_inverse_columns(const std::vector<long> &positions);

    /**
     * ... formed, by this process alone (on several processes, by the
     * host of the factorisation, for all of them; the others do nothing
     * here), ...
     */
    void
    form_asked_inverse_columns();

    /** ... and received (collective), readable then by inverse_entry(). */
    void
    receive_inverse_columns();

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
     * The three steps of forming columns of C, as the factorisation takes
     * them. take_request(): the positions `wanted` (sorted, each once; none
     * on a process that needs no new column) that this process asks for
     * (collective where several processes share the factorisation).
     */
    virtual void
    take_request(const std::vector<long> &wanted) = 0;

    /** form_requested_columns(): the work of forming them (local). */
    virtual void
    form_requested_columns() = 0;

    /**
     * hand_over_columns(): this process's columns, column major, n_last
     * rows, in the order of `wanted` (collective). A factorisation that
     * forms the whole block may keep all of it: it then widens `wanted` to
     * every position.
     */
    virtual void
    hand_over_columns(std::vector<long>   &wanted,
                      std::vector<double> &columns) = 0;

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
     * The columns at `wanted` of (L_S L_S^T)^-1, L_S in the lower triangle
     * of `factor` (m x m, column major): by two triangular solves per
     * column (`factor` only read), or from a third of the m columns on by
     * the whole block (dpotri), formed in `factor`'s array and handed over
     * whole (`factor` left empty, `wanted` widened to every position).
     * Throws if LAPACK fails.
     */
    static void
    columns_of_inverse(std::vector<double> &factor,
                       const long           m,
                       std::vector<long>   &wanted,
                       std::vector<double> &columns);

    /**
     * The whole of C, column major, where this process holds every column
     * (nullptr otherwise): MUMPS's host solves with it once it has formed
     * the whole block in place of the factor of S.
     */
    const double *
    whole_inverse_block() const
    {
      return n_last > 0 && n_inverse_columns() == n_last ?
               inverse_block.data() :
               nullptr;
    }

    /** A new factorisation: the columns formed are stale. */
    void
    forget_inverse_columns()
    {
      // (released, not only emptied: the next factorisation needs the room)
      std::vector<double>().swap(inverse_block);
      column_of.clear();
      requested.clear();
      request_pending = false;
    }

    /** Per unknown of A, its position among the m last ones, or -1. */
    std::vector<long> position;
    long              n_last = 0;

  private:
    /** Formed columns of C, column major, n_last rows. */
    std::vector<double> inverse_block;
    /** Column of inverse_block holding C's column j, or -1. */
    std::vector<long> column_of;
    /** The positions asked for and not yet received (this process's). */
    std::vector<long> requested;
    /** Whether any process asked for a column not yet received. */
    bool request_pending = false;
  };
} // namespace glissade
