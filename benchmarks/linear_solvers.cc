// Benchmark (issue 37's choices of solver, measured): one ring's tangent at
// the converged state of the peers' rings, on one process or under mpirun,
// solved
// - by glissade's own factorisation (CHOLMOD on one process, MUMPS through
//   its C interface on several, with the contact dofs' Schur complement,
//   which gives the block of K^-1 on them without a solve): its figures
//   from the run;
// - by Trilinos: Amesos_Mumps through TrilinosWrappers::SolverDirect (no
//   Schur complement: the compliance would take one solve per contact
//   dof), and CG with ML's AMG (one process);
// each timed, and its solution compared with a reference solve.
//
//   [mpirun -np N] glissade_linear_solver_benchmark AROUND RADIAL

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <glissade/base/processes.h>
#include <glissade/body/body.h>
#include <glissade/lac/direct_solver.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
  using namespace dealii;

  /** Process 0 prints. */
  template <typename... Args>
  void
  say(const char *format, Args... args)
  {
    if (glissade::processes::rank() == 0)
      std::printf(format, args...);
  }

  /** max |x - y| / max |y| of two vectors on every process. */
  double
  relative_difference(const TrilinosWrappers::MPI::Vector &x,
                      const Vector<double>                &y)
  {
    double error = 0., size = 0.;
    for (const auto i : x.locally_owned_elements())
      {
        error = std::max(error, std::abs(x[i] - y(i)));
        size  = std::max(size, std::abs(y(i)));
      }
    return Utilities::MPI::max(error, MPI_COMM_WORLD) /
           Utilities::MPI::max(size, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace glissade;
  if (argc != 3)
    {
      std::fprintf(stderr,
                   "usage: [mpirun -np N] glissade_linear_solver_benchmark "
                   "AROUND RADIAL\n");
      return 1;
    }
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                around = argv[1], radial = argv[2];
  const std::string                rings =
    std::string(GLISSADE_SOURCE_DIR) + "/benchmarks/peers/glissade_rings.prm";
  Simulation simulation(SceneReader::read_file(
    rings,
    {"Body inner/Mesh/Subdivisions=" + around + "," + radial,
     "Body outer/Mesh/Subdivisions=" + around + "," + radial,
     "Body outer/Boundary conditions/Nodal loads=outer: -0.4/" + around +
       "*x/sqrt(x^2+y^2)*t, -0.4/" + around + "*y/sqrt(x^2+y^2)*t",
     "Output/VTU interval=0",
     "Output/Directory=/tmp/glissade_linear_solver_benchmark"}));
  simulation.advance_to(1., "increment 1");

  // glissade's own factorisation of the inner ring, from the run.
  Body               &body        = simulation.body("inner");
  const DirectSolver &own         = body.system().direct_solver();
  const unsigned int  n_dofs      = body.n_dofs();
  const unsigned int  n_processes = processes::count();
  say("inner ring: %u dofs, %u process(es)\n", n_dofs, n_processes);
  const double n_contact_columns =
    Utilities::MPI::sum(double(own.inverse_block().n_inverse_columns()),
                        MPI_COMM_WORLD);
  say("own solver (%s): %.3f s per factorisation (%u, the analysis "
      "included); the block of K^-1 on the %.0f contact dofs %.3f s in "
      "all\n",
      n_processes > 1 ? "MUMPS, Schur complement on the contact dofs" :
                        "CHOLMOD, contact dofs last",
      (own.numeric_seconds + own.symbolic_seconds) /
        std::max(1u, own.n_cholesky + own.n_lu),
      own.n_cholesky + own.n_lu,
      n_contact_columns,
      own.inverse_block().inverse_seconds);

  // The tangent of the converged state, whole (one process) or this
  // process's share (several), and its right-hand side.
  body.assemble();
  const SparseMatrix<double> &share = body.system().tangent_matrix();
  const Vector<double>       &rhs   = body.system().right_hand_side();
  Vector<double>              reference(rhs);
  body.system().factorize();
  Timer timer;
  body.system().solve_homogeneous(rhs, reference);
  say("own solver: one solve %.4f s\n", timer.wall_time());

  // The same matrix in Trilinos: rows in contiguous ranges, each process
  // adding its share's entries, summed by compress(add).
  const unsigned int rank = processes::rank();
  IndexSet           owned(n_dofs);
  owned.add_range(std::size_t(n_dofs) * rank / n_processes,
                  std::size_t(n_dofs) * (rank + 1) / n_processes);
  timer.restart();
  TrilinosWrappers::SparsityPattern pattern(owned,
                                            owned,
                                            complete_index_set(n_dofs),
                                            MPI_COMM_WORLD);
  for (unsigned int i = 0; i < share.m(); ++i)
    for (auto entry = share.begin(i); entry != share.end(i); ++entry)
      pattern.add(i, entry->column());
  pattern.compress();
  TrilinosWrappers::SparseMatrix K;
  K.reinit(pattern);
  for (unsigned int i = 0; i < share.m(); ++i)
    for (auto entry = share.begin(i); entry != share.end(i); ++entry)
      K.add(i, entry->column(), entry->value());
  K.compress(VectorOperation::add);
  TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b);
  for (const auto i : owned)
    b[i] = rhs(i);
  b.compress(VectorOperation::insert);
  say("Trilinos: matrix made in %.3f s\n", timer.wall_time());

  {
    SolverControl                  control(1, 0.);
    TrilinosWrappers::SolverDirect amesos(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
    timer.restart();
    amesos.initialize(K);
    const double factorisation = timer.wall_time();
    timer.restart();
    amesos.solve(x, b);
    const double solve = timer.wall_time();
    say("Amesos_Mumps: analysis + factorisation %.3f s, one solve %.4f s "
        "(the block of K^-1 on the %.0f contact dofs by solves: %.1f s); "
        "max |x - x_own| / max |x_own| = %.2e\n",
        factorisation,
        solve,
        n_contact_columns,
        solve * n_contact_columns,
        relative_difference(x, reference));
  }

  if (n_processes == 1)
    {
      timer.restart();
      TrilinosWrappers::PreconditionAMG                 amg;
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      DoFTools::extract_constant_modes(body.dof_handler(),
                                       ComponentMask(2, true),
                                       data.constant_modes);
      amg.initialize(K, data);
      const double setup = timer.wall_time();
      x                  = 0.;
      SolverControl control(20000, 1e-10 * b.l2_norm());
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      timer.restart();
      cg.solve(K, x, b, amg);
      say("CG + ML (relative residual 1e-10): AMG set-up %.3f s, %u "
          "iterations %.3f s; max |x - x_own| / max |x_own| = "
          "%.2e\n",
          setup,
          control.last_step(),
          timer.wall_time(),
          relative_difference(x, reference));
    }
  return 0;
}
