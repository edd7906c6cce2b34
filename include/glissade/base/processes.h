#pragma once

#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The processes of a run: one (plain `glissade`), or those `mpirun -np N`
   * started. A scene is then solved by all of them together: each holds
   * the whole state and contact, its share of the bodies' meshes
   * (distribute_mesh) and of their tangents, and the bodies' linear systems
   * are factorised by all of them at once (MumpsFactorization, which sums
   * the shares), so every decision the program takes from its numbers is
   * taken the same way everywhere. Each process writes its piece of the
   * bodies' VTU; the other files and the progress lines are written by
   * process 0 alone (doc/parallel.md).
   *
   * Without MPI initialised (the test programs), there is one process.
   */
  namespace processes
  {
    /** The number of processes of the run (1 without MPI). */
    unsigned int
    count();

    /** This process's rank, 0 to count() - 1. */
    unsigned int
    rank();

    /** True on the one process that writes files and prints progress. */
    inline bool
    writes_files()
    {
      return rank() == 0;
    }

    /**
     * True when the run's work is shared out over several processes: each
     * then holds its share of the bodies' meshes (distribute_mesh) and
     * integrates its share of the cells, and the tangents are factorised
     * by all of them together (MUMPS). The one question the layer answers
     * where one process and many take different roads; everything else
     * (sums, shares, gathers) reads the same for one process or many.
     */
    inline bool
    shared_out()
    {
      return count() > 1;
    }

    /**
     * True on the one process that adds the terms the scene holds once (a
     * body's rigid-motion springs, the contact's own entries, a known
     * vector) to its share of a matrix or vector that is then summed over
     * the processes (by sum, or by MUMPS): every process adds its share,
     * and the sum counts those terms once.
     */
    inline bool
    adds_terms_held_once()
    {
      return rank() == 0;
    }

    /**
     * How much of a body's mesh this process holds, for the progress line
     * that announces the body: "" on one process, else ", mesh shared out
     * (N cells held here)" or ", whole mesh on every process".
     */
    std::string
    mesh_held_here(const bool mesh_is_distributed, const unsigned int n_cells);

    /**
     * The files a VTU written by every process's share of the cells goes to
     * (the stem without extension): one process writes "stem.vtu"; several
     * write a piece each, "stem.RRRR.vtu", and the writer the record
     * "stem.pvtu" that names them, which is then the file to cite.
     */
    struct VtuFiles
    {
      /** The file this process writes. */
      std::string own_piece;
      /** Every process's piece, in rank order (empty on one process). */
      std::vector<std::string> pieces;
      /** The record of the pieces, "" on one process. */
      std::string record;
      /** The file that holds the whole: the record, or the one piece. */
      const std::string &
      whole() const
      {
        return record.empty() ? own_piece : record;
      }
    };

    VtuFiles
    vtu_files(const std::string &stem);

    /** The communicator of the run (MPI_COMM_SELF without MPI). */
    MPI_Comm
    communicator();

    /**
     * The values summed over the processes, in place, the same bits on
     * every process (summed on process 0, then sent to all: an all-reduce
     * may round differently on different processes, and the processes must
     * take the same decisions from their numbers).
     */
    void
    sum(double *values, const std::size_t n);

    inline void
    sum(std::vector<double> &values)
    {
      sum(values.data(), values.size());
    }

    /**
     * This process's share of n items numbered 0 to n - 1: the contiguous
     * range [first, second), the ranges in rank order (all of them on one
     * process).
     */
    std::pair<std::size_t, std::size_t>
    share(const std::size_t n);

    /**
     * A column-major matrix of `rows` rows and `columns` columns of which
     * each process has computed its share(columns) of the columns: every
     * process's columns sent to all, in place. Each entry is then the bits
     * of the one process that computed it, on every process.
     */
    void
    gather_columns(double           *matrix,
                   const std::size_t rows,
                   const std::size_t columns);

    /** The first non-empty message of the processes (by rank), or "". */
    std::string
    first_message(const std::string &message);

    /** The largest of `value` over the processes. */
    int
    maximum(const int value);

    /** The items of every process's `items`, sorted, each once. */
    std::vector<unsigned long>
    union_of(const std::vector<unsigned long> &items);

    /**
     * Throws, with the same message on every process, unless `value` is
     * the same bits on all of them: the check that the processes still
     * take the same decisions (`what` names the quantity checked).
     */
    void
    check_identical(const double value, const char *what);
  } // namespace processes
} // namespace glissade
