// A body's matrix factorised by all the processes of a run together
// (include/glissade/lac/mumps_factorization.h).

#include <glissade/base/input_error.h>
#include <glissade/lac/lapack.h>
#include <glissade/lac/mumps_factorization.h>

#include <dmumps_c.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>


// MUMPS's controls and results, numbered as in its user's guide.
#define ICNTL(I) icntl[(I)-1]
#define INFOG(I) infog[(I)-1]

namespace glissade
{
  namespace
  {
    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

    /** Where the factorisations made from now on write their factors
     *  (keep_factors_out_of_core(); empty: in memory). */
    std::string out_of_core_directory;
  } // namespace



  void
  MumpsFactorization::keep_factors_out_of_core(const std::string &directory,
                                               const std::string &entry)
  {
    namespace fs = std::filesystem;
    // (MUMPS's ooc_tmpdir holds 255 characters)
    if (directory.empty() || directory.size() > 200)
      throw InputError(entry,
                       "'" + directory +
                         "' is empty or longer than 200 characters, "
                         "which MUMPS cannot take as its out-of-core "
                         "directory");
    std::error_code error;
    fs::create_directories(directory, error);
    if (!fs::is_directory(directory))
      throw InputError(entry,
                       "cannot make the out-of-core directory '" + directory +
                         "'" + (error ? ": " + error.message() : ""));
    // (written by this process: on a cluster each node has its own)
    std::string probe = directory + "/glissade-probe-XXXXXX";
    const int   file  = mkstemp(probe.data());
    if (file < 0)
      throw InputError(entry,
                       "cannot write in the out-of-core directory '" +
                         directory + "': " + std::strerror(errno));
    close(file);
    std::remove(probe.c_str());
    out_of_core_directory = directory;
  }



  void
  MumpsFactorization::remove_out_of_core_files() const
  {
    namespace fs = std::filesystem;
    if (out_of_core_prefix.empty())
      return;
    const fs::path    file_prefix = fs::path(out_of_core_prefix);
    const fs::path    directory   = file_prefix.parent_path();
    const std::string name        = file_prefix.filename().string() + "_";
    std::error_code   error;
    for (const auto &file : fs::directory_iterator(directory, error))
      if (file.path().filename().string().rfind(name, 0) == 0)
        fs::remove(file.path(), error);
  }

  struct MumpsFactorization::Instance
  {
    DMUMPS_STRUC_C id{};
  };



  MumpsFactorization::MumpsFactorization(MPI_Comm comm)
  {
    // A communicator of its own (MUMPS's messages never meet another
    // factorisation's or the program's), whose process 0, MUMPS's host,
    // holds S, its factor and the right-hand sides: the factorisations take
    // the processes as host in turn (made in the same order on every
    // process), so that two bodies' S do not both sit on one process (82 MB
    // each at 3,200 contact dofs).
    static unsigned int factorizations_made = 0;
    int                 rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    if (!out_of_core_directory.empty())
      out_of_core_prefix = out_of_core_directory + "/glissade-" +
                           std::to_string(getpid()) + "-" +
                           std::to_string(factorizations_made);
    const int host = factorizations_made++ % size;
    MPI_Comm_split(comm, 0, (rank - host + size) % size, &communicator);
    // (each process forms its share of the columns of C: the whole block
    // on every process would be 82 MB per body at 3,200 contact dofs)
    keep_only_asked_columns = true;
  }



  MumpsFactorization::~MumpsFactorization()
  {
    // Ending MUMPS is collective: skipped while an exception unwinds the
    // stack, which one process alone may be doing (the others would never
    // join); the program then ends, and MPI_Abort stops the others
    // (applications/glissade/main.cc). Its out-of-core files are this
    // process's own: removed here.
    if (std::uncaught_exceptions() > 0)
      {
        remove_out_of_core_files();
        return;
      }
    if (mumps)
      {
        mumps->id.job = -2;
        dmumps_c(&mumps->id);
      }
    MPI_Comm_free(&communicator);
  }



  void
  MumpsFactorization::call(const int job, const char *phase) const
  {
    mumps->id.job = job;
    dmumps_c(&mumps->id);
    const int error = mumps->id.INFOG(1);
    if (error >= 0)
      return;
    // (INFOG is the same on every process: all of them throw)
    std::string message = std::string("MUMPS ") + phase +
                          " failed with INFOG(1) = " + std::to_string(error) +
                          ", INFOG(2) = " + std::to_string(mumps->id.INFOG(2));
    if (error == -10)
      message += " (singular tangent matrix: is every body held against "
                 "rigid-body motion by its supports?)";
    if (error == -9 || error == -8 || error == -13)
      message += " (out of memory)";
    if (error <= -90 && error >= -99)
      message += " (writing or reading the out-of-core files in '" +
                 out_of_core_directory + "': is the disk full?)";
    throw std::runtime_error(message);
  }



  void
  MumpsFactorization::set_last_unknowns(const std::vector<long> &unknowns)
  {
    if (unknowns != last_unknowns)
      {
        last_unknowns = unknowns;
        analysed      = false;
      }
  }



  bool
  MumpsFactorization::take_entries(const dealii::SparseMatrix<double> &matrix,
                                   const bool symmetric,
                                   const bool new_pattern)
  {
    // (every entry of this process's matrix, the zeros of its pattern too:
    // the entries' positions stay those of the analysis)
    const bool same_entries =
      !new_pattern && symmetric == symmetric_entries && n == long(matrix.m());
    n                 = matrix.m();
    symmetric_entries = symmetric;
    if (!same_entries)
      {
        row_of_entry.clear();
        column_of_entry.clear();
        local_values.clear();
        for (long i = 0; i < n; ++i)
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
            if (!symmetric || long(entry->column()) >= i)
              {
                row_of_entry.push_back(i + 1);
                column_of_entry.push_back(entry->column() + 1);
                local_values.push_back(entry->value());
              }
      }
    int unchanged = same_entries ? 1 : 0;
    if (same_entries)
      {
        std::size_t k = 0;
        for (long i = 0; i < n; ++i)
          for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
            if (!symmetric || long(entry->column()) >= i)
              {
                unchanged = unchanged && local_values[k] == entry->value();
                local_values[k++] = entry->value();
              }
      }
    MPI_Allreduce(MPI_IN_PLACE, &unchanged, 1, MPI_INT, MPI_MIN, communicator);
    return unchanged != 0;
  }



  void
  MumpsFactorization::factorize(const bool new_pattern)
  {
    const bool symmetric = symmetric_entries;
    int        rank      = 0;
    MPI_Comm_rank(communicator, &rank);
    if (!mumps || symmetric != symmetric_instance)
      {
        if (mumps)
          {
            mumps->id.job = -2;
            dmumps_c(&mumps->id);
          }
        mumps                  = std::make_unique<Instance>();
        mumps->id.comm_fortran = MPI_Comm_c2f(communicator);
        mumps->id.par          = 1; // the host works too
        mumps->id.sym          = symmetric ? 2 : 0;
        call(-1, "initialisation");
        symmetric_instance = symmetric;
        analysed           = false;
        auto &id           = mumps->id;
        id.ICNTL(1)        = -1; // no messages: errors are thrown
        id.ICNTL(2)        = -1;
        id.ICNTL(3)        = -1;
        id.ICNTL(4)        = 0;
        id.ICNTL(18)       = 3; // distributed assembled matrix
        id.ICNTL(20)       = 0; // dense right-hand side, on the host
        id.ICNTL(21)       = 0; // solution on the host
        if (!out_of_core_prefix.empty())
          {
            // (each process's share of the factor in its own files; MUMPS
            // removes them when the instance ends)
            const std::filesystem::path prefix(out_of_core_prefix);
            id.ICNTL(22) = 1;
            std::strncpy(id.ooc_tmpdir,
                         prefix.parent_path().c_str(),
                         sizeof(id.ooc_tmpdir) - 1);
            std::strncpy(id.ooc_prefix,
                         prefix.filename().c_str(),
                         sizeof(id.ooc_prefix) - 1);
          }
      }
    const std::vector<long> &kept_out =
      symmetric ? last_unknowns : std::vector<long>();

    auto &id   = mumps->id;
    id.n       = n;
    id.nnz_loc = row_of_entry.size();
    id.irn_loc = row_of_entry.data();
    id.jcn_loc = column_of_entry.data();
    id.a_loc   = local_values.data();

    const auto start = std::chrono::steady_clock::now();
    if (new_pattern || !analysed)
      {
        n_last = kept_out.size();
        schur_list.assign(kept_out.begin(), kept_out.end());
        for (int &i : schur_list)
          ++i;
        id.ICNTL(19)     = n_last > 0 ? 1 : 0;
        id.size_schur    = n_last;
        id.listvar_schur = n_last > 0 ? schur_list.data() : nullptr;
        schur.assign(rank == 0 ? std::size_t(n_last) * n_last : 0, 0.);
        id.schur = rank == 0 && n_last > 0 ? schur.data() : nullptr;
        call(1, "analysis");
        position.assign(n, -1);
        for (long k = 0; k < n_last; ++k)
          position[kept_out[k]] = k;
        analysed = true;
        analysis_seconds += seconds_since(start);
      }
    const auto numeric_start = std::chrono::steady_clock::now();
    call(2, "factorisation");
    factorize_schur_complement();
    factorization_seconds += seconds_since(numeric_start);
    forget_inverse_columns();
    std::vector<double>().swap(received_cholesky);
  }



  void
  MumpsFactorization::factorize_schur_complement()
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    // (the host's verdicts sent to all, so that every process throws or
    // none does)
    int positive = 0, singular = 0;
    if (rank == 0 && n_last > 0)
      {
        // MUMPS returns one triangle of a symmetric S (by rows: the lower
        // one, that is the upper one column major): mirror it.
        const long m = n_last;
        for (long j = 0; j < m; ++j)
          for (long i = j + 1; i < m; ++i)
            schur[i + j * m] = schur[j + i * m];
        // Cholesky first: a positive S needs nothing else (its factor gives
        // the inverse block and the solves); an LU only for an indefinite
        // one (a tangent that is not positive definite).
        const int size = m;
        int       info = 0;
        // (in place; S's diagonal kept, so that S can be made again from
        // it and the strict upper triangle, which dpotrf leaves alone)
        std::vector<double> diagonal(m);
        for (long i = 0; i < m; ++i)
          diagonal[i] = schur[i + i * m];
        dpotrf_("L", &size, schur.data(), &size, &info);
        positive = info == 0;
        if (positive)
          std::vector<double>().swap(schur_lu);
        else
          {
            schur_lu = schur;
            for (long j = 0; j < m; ++j)
              {
                schur_lu[j + j * m] = diagonal[j];
                for (long i = j + 1; i < m; ++i)
                  schur_lu[i + j * m] = schur_lu[j + i * m];
              }
            schur_pivots.resize(m);
            dgetrf_(
              &size, &size, schur_lu.data(), &size, schur_pivots.data(), &info);
            singular = info;
          }
      }
    int verdicts[2] = {positive, singular};
    MPI_Bcast(verdicts, 2, MPI_INT, 0, communicator);
    if (verdicts[1] != 0)
      throw std::runtime_error(
        "the Schur complement on the contact dofs is singular (LAPACK "
        "dgetrf info " +
        std::to_string(verdicts[1]) +
        "): is every body held against rigid-body motion by its supports?");
    schur_is_positive = verdicts[0] != 0;
  }



  bool
  MumpsFactorization::on_any_process(const bool value) const
  {
    int any = value ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, communicator);
    return any != 0;
  }



  void
  MumpsFactorization::share_trailing_factor() const
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    int lacking = rank != 0 && received_cholesky.empty() ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &lacking, 1, MPI_INT, MPI_MAX, communicator);
    if (lacking == 0)
      return;
    // (those that hold it already receive the same bits again)
    if (rank != 0)
      received_cholesky.resize(std::size_t(n_last) * n_last);
    MPI_Bcast(rank == 0 ? const_cast<double *>(schur.data()) :
                          received_cholesky.data(),
              std::size_t(n_last) * n_last,
              MPI_DOUBLE,
              0,
              communicator);
  }



  void
  MumpsFactorization::trailing_factor(std::vector<double> &factor,
                                      const bool           last_use) const
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    if (rank == 0)
      {
        factor = schur;
        return;
      }
    if (received_cholesky.empty())
      throw std::logic_error("MumpsFactorization: the factor of the Schur "
                             "complement was asked for before it was shared");
    // (at the whole block: handed over, not copied; the host keeps its
    // own for the solves)
    if (last_use)
      factor.swap(received_cholesky);
    else
      factor = received_cholesky;
  }



  void
  MumpsFactorization::solve(dealii::Vector<double> &x) const
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    auto &id = mumps->id;
    rhs.assign(x.begin(), x.end());
    id.rhs  = rank == 0 ? rhs.data() : nullptr;
    id.nrhs = 1;
    id.lrhs = x.size();
    if (n_last > 0)
      {
        // Condensed on the contact dofs, S solved here, then expanded.
        reduced_rhs.assign(n_last, 0.);
        id.redrhs    = rank == 0 ? reduced_rhs.data() : nullptr;
        id.lredrhs   = n_last;
        id.ICNTL(26) = 1;
        call(3, "solve (condensation)");
        if (rank == 0)
          {
            const int size = n_last, one = 1;
            int       info = 0;
            if (schur_lu.empty())
              dpotrs_("L",
                      &size,
                      &one,
                      schur.data(),
                      &size,
                      reduced_rhs.data(),
                      &size,
                      &info);
            else
              dgetrs_("N",
                      &size,
                      &one,
                      schur_lu.data(),
                      &size,
                      schur_pivots.data(),
                      reduced_rhs.data(),
                      &size,
                      &info);
          }
        id.ICNTL(26) = 2;
        call(3, "solve (expansion)");
        id.ICNTL(26) = 0;
      }
    else
      call(3, "solve");
    MPI_Bcast(rhs.data(), rhs.size(), MPI_DOUBLE, 0, communicator);
    std::copy(rhs.begin(), rhs.end(), x.begin());
  }
} // namespace glissade
