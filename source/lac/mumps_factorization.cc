// A body's matrix factorised by all the processes of a run together
// (include/glissade/lac/mumps_factorization.h).

#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
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
    /** Where the factorisations made from now on write their factors
     *  (keep_factors_out_of_core(); empty: in memory). */
    std::string out_of_core_directory;

    /** The tag of the columns of C the host sends (not one of MUMPS's
     *  own, in the factorisation's communicator). */
    constexpr int inverse_columns_tag = 31001;
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
        analysis_seconds += timing::seconds_since(start);
      }
    const auto numeric_start = std::chrono::steady_clock::now();
    // (the last factorisation's inverse block let go; S's array made again
    // where that block had taken its place)
    forget_inverse_columns();
    if (rank == 0 && n_last > 0)
      {
        schur.resize(std::size_t(n_last) * n_last);
        id.schur = schur.data();
      }
    call(2, "factorisation");
    factorize_schur_complement();
    factorization_seconds += timing::seconds_since(numeric_start);
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
  MumpsFactorization::take_request(const std::vector<long> &wanted)
  {
    int rank = 0, size = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &size);
    const int n_wanted = wanted.size();
    asked_counts.assign(size, 0);
    asked_offsets.assign(size + 1, 0);
    MPI_Gather(
      &n_wanted, 1, MPI_INT, asked_counts.data(), 1, MPI_INT, 0, communicator);
    for (int p = 0; p < size; ++p)
      asked_offsets[p + 1] = asked_offsets[p] + asked_counts[p];
    asked_by_all.resize(rank == 0 ? asked_offsets[size] : 0);
    MPI_Gatherv(wanted.data(),
                n_wanted,
                MPI_LONG,
                asked_by_all.data(),
                asked_counts.data(),
                asked_offsets.data(),
                MPI_LONG,
                0,
                communicator);
    if (rank != 0 && n_wanted > 0)
      {
        columns_on_the_way.resize(std::size_t(n_last) * n_wanted);
        MPI_Irecv(columns_on_the_way.data(),
                  static_cast<int>(columns_on_the_way.size()),
                  MPI_DOUBLE,
                  0,
                  inverse_columns_tag,
                  communicator,
                  &receipt);
      }
  }



  void
  MumpsFactorization::form_requested_columns()
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    if (rank != 0)
      return; // (the host forms every process's columns)
    formed_positions = asked_by_all;
    std::sort(formed_positions.begin(), formed_positions.end());
    formed_positions.erase(std::unique(formed_positions.begin(),
                                       formed_positions.end()),
                           formed_positions.end());
    forming_failed = false;
    if (formed_positions.empty() || whole_inverse_block() != nullptr)
      return; // (none asked for, or all formed already: sent from there)
    // (the whole block is formed in S's array, in place of L_S: a copy
    // would be a second m x m array on the host)
    try
      {
        columns_of_inverse(schur, n_last, formed_positions, formed_columns);
      }
    catch (const std::runtime_error &)
      {
        forming_failed = true;
      }
  }



  void
  MumpsFactorization::hand_over_columns(std::vector<long>   &wanted,
                                        std::vector<double> &columns)
  {
    int rank = 0, size = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &size);
    // (every process stops alike where LAPACK failed on the host)
    int failed = forming_failed ? 1 : 0;
    MPI_Bcast(&failed, 1, MPI_INT, 0, communicator);
    if (failed != 0 && receipt != MPI_REQUEST_NULL)
      {
        MPI_Cancel(&receipt);
        MPI_Request_free(&receipt);
      }
    if (failed != 0)
      throw std::runtime_error("LAPACK could not form the inverse of the "
                               "Schur complement on the contact dofs");
    if (rank != 0)
      {
        if (!wanted.empty())
          {
            MPI_Wait(&receipt, MPI_STATUS_IGNORE);
            columns.swap(columns_on_the_way);
          }
        std::vector<double>().swap(columns_on_the_way);
        return;
      }

    // The host: sent from the whole block it holds already, or from the
    // columns just formed.
    const double     *kept_block = whole_inverse_block();
    const double     *source = kept_block ? kept_block : formed_columns.data();
    std::vector<long> column_in_source(n_last, -1);
    for (std::size_t c = 0; c < formed_positions.size(); ++c)
      column_in_source[formed_positions[c]] =
        kept_block ? formed_positions[c] : long(c);
    for (int p = 1; p < size; ++p)
      if (asked_counts[p] > 0)
        {
          // (p's columns sent straight from where they are: a datatype
          // that picks them, no copy)
          std::vector<MPI_Aint> picked_bytes(asked_counts[p]);
          for (int c = 0; c < asked_counts[p]; ++c)
            picked_bytes[c] =
              column_in_source[asked_by_all[asked_offsets[p] + c]] * n_last *
              MPI_Aint(sizeof(double));
          MPI_Datatype picked;
          MPI_Type_create_hindexed_block(
            asked_counts[p], n_last, picked_bytes.data(), MPI_DOUBLE, &picked);
          MPI_Type_commit(&picked);
          MPI_Send(source, 1, picked, p, inverse_columns_tag, communicator);
          MPI_Type_free(&picked);
        }
    if (!kept_block && formed_positions.size() == std::size_t(n_last))
      {
        // (the whole block, formed in place of L_S, is kept whole: the
        // host's solves read it from now on)
        wanted = formed_positions;
        columns.swap(formed_columns);
      }
    else if (!kept_block)
      {
        columns.resize(std::size_t(n_last) * wanted.size());
        for (std::size_t c = 0; c < wanted.size(); ++c)
          std::copy_n(
            &formed_columns[std::size_t(column_in_source[wanted[c]]) * n_last],
            n_last,
            &columns[c * n_last]);
      }
    std::vector<double>().swap(formed_columns);
    std::vector<long>().swap(asked_by_all);
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
            if (schur_lu.empty() && schur.empty())
              {
                // (the whole inverse formed in place of L_S: C b)
                const double        all = 1., none = 0.;
                std::vector<double> b(reduced_rhs);
                dgemv_("N",
                       &size,
                       &size,
                       &all,
                       whole_inverse_block(),
                       &size,
                       b.data(),
                       &one,
                       &none,
                       reduced_rhs.data(),
                       &one);
              }
            else if (schur_lu.empty())
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
