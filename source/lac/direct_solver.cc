#include <deal.II/base/timer.h>

#include <glissade/base/processes.h>
#include <glissade/lac/direct_solver.h>

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    void
    check(const long status, const char *phase)
    {
      if (status != UMFPACK_OK)
        throw std::runtime_error(
          std::string("UMFPACK ") + phase + " failed with status " +
          std::to_string(status) +
          (status == UMFPACK_WARNING_singular_matrix ?
             " (singular tangent matrix: is every body held against "
             "rigid-body motion by its supports?)" :
             ""));
    }
  } // namespace



  DirectSolver::~DirectSolver()
  {
    free_numeric();
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
  }



  void
  DirectSolver::free_numeric()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
  }



  bool
  DirectSolver::factorize(const SparseMatrix<double> &matrix)
  {
    if (processes::shared_out())
      return factorize_on_processes(matrix);
    // deal.II stores rows (diagonal first); UMFPACK wants sorted columns.
    // We hand it the rows as the columns of A^T and solve with A^T later.
    const SparsityPattern &sp = matrix.get_sparsity_pattern();
    const long             n  = matrix.m();
    const bool             same_pattern =
      (&sp == pattern && row_start.size() == static_cast<size_t>(n + 1) &&
       static_cast<size_t>(row_start.back()) == matrix.n_nonzero_elements());
    if (!same_pattern)
      {
        row_start.assign(n + 1, 0);
        column_index.resize(matrix.n_nonzero_elements());
        values.resize(matrix.n_nonzero_elements());
      }
    long                                 k         = 0;
    bool                                 unchanged = same_pattern;
    std::vector<std::pair<long, double>> row;
    for (long i = 0; i < n; ++i)
      {
        row.clear();
        for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
          row.emplace_back(it->column(), it->value());
        std::sort(row.begin(), row.end(), [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        row_start[i] = k;
        for (const auto &[j, v] : row)
          {
            unchanged = unchanged && values[k] == v && column_index[k] == j;
            column_index[k] = j;
            values[k]       = v;
            ++k;
          }
      }
    row_start[n] = k;
    pattern      = &sp;
    if (unchanged && factorization_current)
      {
        ++n_reused;
        return false;
      }
    // (set again once a factorisation has succeeded: a failed one, which
    // throws, must not be kept for the same matrix)
    factorization_current = false;
    if (!same_pattern && symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);

    // The pattern is symmetric (it comes from a DoFHandler), so the rows are
    // also the columns of A: Cholesky reads the arrays as they are.
    cholesky_used = false;
    if (symmetric)
      {
        const double before =
          schur.analysis_seconds + schur.factorization_seconds;
        const bool ok =
          schur.factorize(n, row_start, column_index, values, !same_pattern);
        numeric_seconds +=
          schur.analysis_seconds + schur.factorization_seconds - before;
        if (ok)
          {
            cholesky_used = true;
            ++n_cholesky;
            free_numeric();
            factorization_current = true;
            return true;
          }
      }
    factorize_lu();
    factorization_current = true;
    return true;
  }



  bool
  DirectSolver::factorize_on_processes(const SparseMatrix<double> &matrix)
  {
    // Each process's matrix is its share (the integrals of its cells):
    // MUMPS takes the entries straight from it and sums them over the
    // processes, and no process copies or holds the whole matrix.
    if (distributed == nullptr)
      distributed =
        std::make_unique<MumpsFactorization>(processes::communicator());
    const SparsityPattern &sp = matrix.get_sparsity_pattern();
    // (a new pattern on any process is one for all: the analysis is
    // collective)
    const bool new_pattern =
      processes::maximum(&sp != pattern ||
                             matrix.n_nonzero_elements() != n_entries_seen ?
                           1 :
                           0) != 0;
    pattern                     = &sp;
    n_entries_seen              = matrix.n_nonzero_elements();
    const bool symmetric_matrix = symmetric && !unsymmetric_ordering;
    const bool unchanged =
      distributed->take_entries(matrix, symmetric_matrix, new_pattern);
    if (unchanged && factorization_current)
      {
        ++n_reused;
        return false;
      }
    factorization_current = false;
    distributed->set_last_unknowns(symmetric_matrix ? last_unknowns_sorted :
                                                      std::vector<long>());
    const double before =
      distributed->analysis_seconds + distributed->factorization_seconds;
    distributed->factorize(new_pattern);
    numeric_seconds += distributed->analysis_seconds +
                       distributed->factorization_seconds - before;
    ++(symmetric_matrix ? n_cholesky : n_lu);
    factorization_current = true;
    return true;
  }



  void
  DirectSolver::factorize_lu()
  {
    ++n_lu;
    const long n = row_start.size() - 1;
    double     control[UMFPACK_CONTROL];
    umfpack_dl_defaults(control);
    if (unsymmetric_ordering)
      control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_UNSYMMETRIC;
    Timer timer;
    if (symbolic == nullptr)
      {
        check(umfpack_dl_symbolic(n,
                                  n,
                                  row_start.data(),
                                  column_index.data(),
                                  values.data(),
                                  &symbolic,
                                  control,
                                  nullptr),
              "symbolic analysis");
        symbolic_seconds += timer.wall_time();
        timer.restart();
      }
    free_numeric();
    check(umfpack_dl_numeric(row_start.data(),
                             column_index.data(),
                             values.data(),
                             symbolic,
                             &numeric,
                             control,
                             nullptr),
          "factorization");
    numeric_seconds += timer.wall_time();
  }



  void
  DirectSolver::use_cholesky(const bool               symmetric_matrices,
                             const std::vector<long> &last_unknowns)
  {
    std::vector<long> sorted = last_unknowns;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    // (another elimination order, or method: the held factorisation is not
    // the one asked for)
    if (symmetric_matrices != symmetric || sorted != last_unknowns_sorted)
      factorization_current = false;
    last_unknowns_sorted = sorted;
    symmetric            = symmetric_matrices;
    schur.set_last_unknowns(last_unknowns);
  }



  void
  DirectSolver::solve(Vector<double> &x) const
  {
    if (distributed != nullptr)
      {
        distributed->solve(x);
        return;
      }
    if (cholesky_used)
      {
        schur.solve(x);
        return;
      }
    double control[UMFPACK_CONTROL];
    umfpack_dl_defaults(control);
    control[UMFPACK_IRSTEP] = 0;
    solution.resize(x.size());
    check(umfpack_dl_solve(UMFPACK_At,
                           row_start.data(),
                           column_index.data(),
                           values.data(),
                           solution.data(),
                           x.begin(),
                           numeric,
                           control,
                           nullptr),
          "solve");
    std::copy(solution.begin(), solution.end(), x.begin());
  }
} // namespace glissade
