#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/lac/trailing_block_inverse.h>

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * A body's matrix factorised by all the processes of the run together,
   * with MUMPS (its C interface, distributed assembled input): the
   * factorisation of a run on several processes, where one process uses
   * CHOLMOD or UMFPACK (DirectSolver chooses).
   *
   * Each process hands MUMPS the entries of its own matrix, which holds
   * the integrals of its share of the cells (BodyLinearSystem): MUMPS sums
   * the entries that several processes hand it, so no process holds the
   * whole matrix, and the factor, the largest object of a solve, is
   * shared out too. A symmetric matrix is factorised as LDL^T
   * with the contact dofs kept out of the factor: MUMPS returns their
   * Schur complement S, whose dense Cholesky factor gives the block of
   * A^-1 on them (TrailingBlockInverse) as the trailing block of CHOLMOD's
   * factor does on one process. A solve then goes through S: MUMPS
   * condenses the right-hand side on the contact dofs, S is solved on
   * MUMPS's host, and MUMPS expands the solution. (The host is process 0
   * of the factorisation's own communicator: the factorisations take the
   * processes of the run as host in turn.) An unsymmetric matrix is
   * factorised LU, with no Schur complement.
   *
   * Right-hand sides and solutions are whole vectors, the same on every
   * process (the host's are broadcast). Every member is collective:
   * every process calls it, in the same order.
   *
   * Out of core (keep_factors_out_of_core()), each process writes its
   * share of the factor to files as MUMPS makes it and reads it back at
   * each solve, and holds in memory only MUMPS's working space: at the
   * million-dof rings on two processes, a peak of 1.36 GB per process
   * against 2.09 GB, in the same time while the machine's page cache holds
   * the files.
   */
  class MumpsFactorization : public TrailingBlockInverse
  {
  public:
    explicit MumpsFactorization(MPI_Comm communicator);
    MumpsFactorization(const MumpsFactorization &) = delete;
    MumpsFactorization &
    operator=(const MumpsFactorization &) = delete;
    ~MumpsFactorization() override;

    /**
     * The factorisations made from now on keep their factors in files in
     * `directory` (MUMPS's out-of-core mode) rather than in memory; the
     * directory is made if it does not exist. Throws an InputError naming
     * `entry` where this process cannot make or write it. The files are
     * removed when the factorisation ends.
     */
    static void
    keep_factors_out_of_core(const std::string &directory,
                             const std::string &entry);

    /**
     * The unknowns to keep out of the factor (sorted, unique), whose Schur
     * complement is formed; a change redoes the analysis.
     */
    void
    set_last_unknowns(const std::vector<long> &unknowns);

    /**
     * Takes this process's entries of `matrix` (its share; those with
     * column >= row where `symmetric`). Returns true where every process's
     * entries are, bit for bit, those of the last factorisation, which
     * then need not be done again.
     */
    bool
    take_entries(const dealii::SparseMatrix<double> &matrix,
                 const bool                          symmetric,
                 const bool                          new_pattern);

    /**
     * Analysis (first call, a new pattern, other last unknowns, or the
     * other symmetry) and numeric factorisation of the entries taken.
     * Symmetric: LDL^T with the Schur complement on the last unknowns;
     * otherwise LU, with no last unknowns.
     */
    void
    factorize(const bool new_pattern);

    /** x <- A^-1 x. */
    void
    solve(dealii::Vector<double> &x) const;

    /**
     * True if the Schur complement on the last unknowns is positive
     * definite, so that the block of A^-1 on them is available.
     */
    bool
    has_inverse_block() const
    {
      return schur_is_positive;
    }

    double analysis_seconds      = 0.;
    double factorization_seconds = 0.;

  private:
    /**
     * Each process's columns of C, formed on the host from its factor of
     * S and sent to it: only the host holds L_S, each process receives
     * its own columns (at 3,200 contact dofs on two processes 41 MB
     * rather than the 82 MB of L_S), and the whole block is formed once,
     * by the host, in place of L_S (which then no longer is: the host's
     * solves read the whole block). take_request() gathers the positions
     * asked for on the host and has the others wait for their columns;
     * form_requested_columns() is the host's work, done while the hosts
     * of the other bodies do theirs; hand_over_columns() sends them.
     */
    void
    take_request(const std::vector<long> &wanted) override;

    void
    form_requested_columns() override;

    void
    hand_over_columns(std::vector<long>   &wanted,
                      std::vector<double> &columns) override;

    bool
    on_any_process(const bool value) const override;

    /**
     * Removes this process's out-of-core files of this factorisation (a
     * run ending on an error, where MUMPS cannot end collectively).
     */
    void
    remove_out_of_core_files() const;

    /** Calls MUMPS for `job`; throws with its error, on every process. */
    void
    call(const int job, const char *phase) const;

    /**
     * The host: S from MUMPS, its Cholesky factor, and its LU only if S
     * is not positive definite.
     */
    void
    factorize_schur_complement();

    struct Instance;
    std::unique_ptr<Instance> mumps;
    MPI_Comm                  communicator;
    /** MUMPS's out-of-core files: "<prefix>_<rank>_XXXXXX" (empty: in core).
     */
    std::string       out_of_core_prefix;
    bool              symmetric_instance = false;
    bool              analysed           = false;
    std::vector<long> last_unknowns;
    bool              schur_is_positive = false;

    /** This process's entries: 1-based indices, and the values. */
    long                n                 = 0;
    bool                symmetric_entries = false;
    std::vector<int>    row_of_entry, column_of_entry;
    std::vector<double> local_values;
    /** The last unknowns, 1-based, as MUMPS reads them. */
    std::vector<int> schur_list;
    /**
     * The host: S (column major, m x m), where MUMPS writes it, its
     * Cholesky factor L_S then in the lower triangle (in place: a second
     * m x m array per body is 82 MB at 3,200 contact dofs), until the
     * whole inverse block is formed in its place (then empty); S's LU and
     * pivots if S is not positive definite (empty otherwise).
     */
    std::vector<double> schur, schur_lu;
    std::vector<int>    schur_pivots;

    /**
     * The columns of C asked for. The host: every process's positions in
     * rank order (counts and offsets by rank), the positions it forms
     * (sorted, each once), their columns, and whether LAPACK failed. The
     * others: the columns being received.
     */
    std::vector<long>           asked_by_all;
    std::vector<int>            asked_counts, asked_offsets;
    std::vector<long>           formed_positions;
    std::vector<double>         formed_columns;
    bool                        forming_failed = false;
    std::vector<double>         columns_on_the_way;
    MPI_Request                 receipt = MPI_REQUEST_NULL;
    mutable std::vector<double> rhs, reduced_rhs;
  };
} // namespace glissade
