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
