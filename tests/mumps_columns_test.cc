// MUMPS's block of A^-1 on the contact dofs, shared out: each
// factorisation's host forms the columns every process asks for (by
// triangular solves for a few, the whole block in place of the factor of
// the Schur complement for many) and sends each its own; the host then
// solves through that block. Every column and solve is checked against
// A^-1 by Gauss-Jordan on the whole matrix, dense, on each process: no
// MUMPS, no LAPACK. Discovered as one process; also run under mpirun on 2
// and 3 processes (tests/CMakeLists.txt), where the two factorisations
// have different hosts and form their columns at once.

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <glissade/lac/mumps_factorization.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "test_tools.h"

using namespace dealii;
using namespace glissade;
using glissade_tests::check;

namespace
{
  /** MPI for this test program's run (ended when the program ends). */
  struct MpiForThisRun
  {
    MpiForThisRun()
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (initialized == 0)
        MPI_Init(nullptr, nullptr);
    }
    ~MpiForThisRun()
    {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (finalized == 0)
        MPI_Finalize();
    }
  };

  /**
   * A 5-point Laplacian on a k x k grid plus shift times the identity, as
   * a sum of edge terms (e_i - e_j)(e_i - e_j)^T: this process's matrix
   * holds the edges numbered rank, rank + P, ... (and the shift on process
   * 0), every process the whole pattern, as cells shared out would; `whole`
   * is the sum, dense.
   */
  void
  make_shared_matrix(const unsigned int    k,
                     const double          shift,
                     const int             rank,
                     const int             n_processes,
                     SparsityPattern      &pattern,
                     SparseMatrix<double> &share,
                     FullMatrix<double>   &whole)
  {
    const unsigned int                                 n = k * k;
    std::vector<std::pair<unsigned int, unsigned int>> edges;
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < k; ++j)
        {
          if (i + 1 < k)
            edges.emplace_back(i * k + j, (i + 1) * k + j);
          if (j + 1 < k)
            edges.emplace_back(i * k + j, i * k + j + 1);
        }
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      dsp.add(i, i);
    for (const auto &[a, b] : edges)
      {
        dsp.add(a, b);
        dsp.add(b, a);
      }
    pattern.copy_from(dsp);
    share.reinit(pattern);
    whole.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        whole(i, i) += shift;
        if (rank == 0)
          share.add(i, i, shift);
      }
    for (std::size_t e = 0; e < edges.size(); ++e)
      {
        const auto [a, b] = edges[e];
        for (const auto &[i, j, value] : {std::tuple(a, a, 1.),
                                          std::tuple(b, b, 1.),
                                          std::tuple(a, b, -1.),
                                          std::tuple(b, a, -1.)})
          {
            whole(i, j) += value;
            if (int(e % n_processes) == rank)
              share.add(i, j, value);
          }
      }
  }

  /** The largest of `value` over the processes. */
  double
  largest_over_processes(const double value)
  {
    double largest = value;
    MPI_Allreduce(
      MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return largest;
  }
} // namespace



GLISSADE_TEST(solver_mumps_inverse_columns_shared_out)
{
  static MpiForThisRun mpi;
  int                  rank = 0, n_processes = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_processes);
  // (every verdict is taken over all processes: process 0 prints it)
  if (rank != 0 && std::freopen("/dev/null", "w", stdout) == nullptr)
    throw std::runtime_error("stdout could not be silenced");
  std::cout << "  " << n_processes << " process(es)" << std::endl;

  // Two "bodies": factorisations made one after the other take the
  // processes as host in turn.
  const unsigned int k = 16;
  // The last unknowns ("contact dofs"): the grid's first row and a few
  // scattered ones, m = 21.
  std::vector<long> last;
  for (unsigned int j = 0; j < k; ++j)
    last.push_back(j);
  for (const long extra : {37L, 90L, 128L, 200L, 255L})
    last.push_back(extra);
  const long m = last.size();

  struct Body
  {
    SparsityPattern                     pattern;
    SparseMatrix<double>                share;
    FullMatrix<double>                  inverse;
    std::unique_ptr<MumpsFactorization> factor;
  };
  std::array<Body, 2> bodies;
  for (unsigned int b = 0; b < 2; ++b)
    {
      Body &body = bodies[b];
      make_shared_matrix(k,
                         b == 0 ? 0.01 : 0.5,
                         rank,
                         n_processes,
                         body.pattern,
                         body.share,
                         body.inverse);
      body.inverse.gauss_jordan();
      body.factor = std::make_unique<MumpsFactorization>(MPI_COMM_WORLD);
      body.factor->set_last_unknowns(last);
      body.factor->take_entries(body.share, true, true);
      body.factor->factorize(true);
      check(body.factor->has_inverse_block(), "S is positive definite");
    }

  // The columns at `positions` that this process holds, against A^-1.
  const auto column_error = [&](const Body              &body,
                                const std::vector<long> &positions) {
    double worst = 0.;
    for (const long j : positions)
      for (long i = 0; i < m; ++i)
        worst = std::max(worst,
                         std::abs(body.factor->inverse_entry(i, j) -
                                  body.inverse(last[i], last[j])) /
                           body.inverse(last[j], last[j]));
    return largest_over_processes(worst);
  };
  const auto solve_error = [&](Body &body) {
    const unsigned int n = body.share.m();
    Vector<double>     b(n), x(n), exact(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = std::sin(0.1 * i) + 0.5;
    x = b;
    body.factor->solve(x);
    body.inverse.vmult(exact, b);
    x -= exact;
    return largest_over_processes(x.linfty_norm() / exact.linfty_norm());
  };
  const auto check_figure = [](const double error, const std::string &what) {
    std::cout << "  " << what << ": largest relative error " << error
              << std::endl;
    check(error < 1e-12, what + " differs from Gauss-Jordan's A^-1");
  };
  for (auto &body : bodies)
    check_figure(solve_error(body), "a solve through S's factor");

  // A few columns (fewer than a third of m asked for by all processes):
  // the host forms them by triangular solves, each process keeps its own.
  const std::vector<long> few = {rank, rank + n_processes};
  bodies[0].factor->compute_inverse_columns(few);
  check(largest_over_processes(
          std::abs(bodies[0].factor->n_inverse_columns() - 2.)) == 0.,
        "each process holds the 2 columns it asked for");
  check_figure(column_error(bodies[0], few), "2 columns a process");

  // Each process its share of the columns, for both bodies in three steps
  // (asked, formed by each host at once, received): the whole block.
  std::vector<long> share;
  for (long j = rank * m / n_processes; j < (rank + 1) * m / n_processes; ++j)
    share.push_back(j);
  for (auto &body : bodies)
    body.factor->ask_for_inverse_columns(share);
  for (auto &body : bodies)
    body.factor->form_asked_inverse_columns();
  for (auto &body : bodies)
    body.factor->receive_inverse_columns();
  for (unsigned int b = 0; b < 2; ++b)
    {
      check_figure(column_error(bodies[b], share),
                   "body " + std::to_string(b) + ", each process's share");
      // (the host of body b is process b % P, the test's factorisations
      // being the program's first: it keeps the whole block; the others
      // their share, and body 0's the few columns asked for before)
      std::vector<long> held_positions = share;
      if (b == 0)
        held_positions.insert(held_positions.end(), few.begin(), few.end());
      std::sort(held_positions.begin(), held_positions.end());
      held_positions.erase(std::unique(held_positions.begin(),
                                       held_positions.end()),
                           held_positions.end());
      const long held     = bodies[b].factor->n_inverse_columns();
      const bool is_host  = rank == int(b % n_processes);
      const long expected = is_host ? m : long(held_positions.size());
      check(largest_over_processes(std::abs(double(held - expected))) == 0.,
            "body " + std::to_string(b) +
              ": the host holds the whole block, the others the columns "
              "they asked for");
      check_figure(solve_error(bodies[b]),
                   "body " + std::to_string(b) +
                     ", a solve through the whole block on the host");
    }

  // One more column asked for by the last process alone (a column of
  // process 0's share): sent from the whole block the host holds.
  const std::vector<long> more =
    rank == n_processes - 1 ? std::vector<long>{4} : std::vector<long>{};
  bodies[0].factor->compute_inverse_columns(more);
  check_figure(column_error(bodies[0], more),
               "a column asked for later by one process");

  // Factorised again (S's array made anew where the block had taken its
  // place): the solves go through the new factor.
  bodies[0].factor->take_entries(bodies[0].share, true, false);
  bodies[0].factor->factorize(false);
  check_figure(solve_error(bodies[0]), "a solve after a new factorisation");
  bodies[0].factor->compute_inverse_columns(share);
  check_figure(column_error(bodies[0], share),
               "each process's share after a new factorisation");
}
