// Prototype (issue 37): one body's tangent at the converged state of the
// peers' rings, solved by CHOLMOD (factorisation + solve) and by CG with
// ML's AMG (set-up + solve), timed, and the two solutions compared.
//
//   glissade_iterative_benchmark AROUND RADIAL [BODY]

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <glissade/body/body.h>
#include <glissade/lac/direct_solver.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  using namespace glissade;
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                around = argv[1], radial = argv[2];
  const std::string                body_name = argc > 3 ? argv[3] : "inner";
  const std::string                rings =
    std::string(GLISSADE_SOURCE_DIR) + "/benchmarks/peers/glissade_rings.prm";
  Simulation simulation(SceneReader::read_file(
    rings,
    {"Body inner/Mesh/Subdivisions=" + around + "," + radial,
     "Body outer/Mesh/Subdivisions=" + around + "," + radial,
     "Body outer/Boundary conditions/Nodal loads=outer: -0.4/" + around +
       "*x/sqrt(x^2+y^2)*t, -0.4/" + around + "*y/sqrt(x^2+y^2)*t",
     "Output/VTU interval=0",
     "Output/Directory=/tmp/itb/out"}));
  simulation.advance_to(1., "increment 1");
  Body &body = simulation.body(body_name);
  body.assemble();
  const SparseMatrix<double> &K   = body.system().tangent_matrix();
  const Vector<double>       &rhs = body.system().right_hand_side();
  std::printf("%s ring: %u dofs, %zu entries, |rhs| %.3e\n",
              body_name.c_str(),
              K.m(),
              K.n_nonzero_elements(),
              rhs.l2_norm());

  Timer        timer;
  DirectSolver direct;
  direct.use_cholesky(true, {});
  direct.factorize(K);
  const double first = timer.wall_time();
  // (the same matrix is not factorised again: one entry changed by a
  // rounding's worth, for the numeric factorisation of a Newton iteration)
  SparseMatrix<double> K_again(K.get_sparsity_pattern());
  K_again.copy_from(K);
  K_again.diag_element(0) *= 1. + 1e-15;
  timer.restart();
  direct.factorize(K_again);
  const double   numeric = timer.wall_time();
  Vector<double> x_direct(rhs);
  timer.restart();
  direct.solve(x_direct);
  const double direct_solve = timer.wall_time();
  std::printf(
    "CHOLMOD: analysis+numeric %.3f s, numeric %.3f s, solve %.4f s\n",
    first,
    numeric,
    direct_solve);

  timer.restart();
  TrilinosWrappers::SparseMatrix A;
  A.reinit(K);
  const double copy = timer.wall_time();
  timer.restart();
  TrilinosWrappers::PreconditionAMG                 amg;
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic              = true;
  data.higher_order_elements = false;
  data.smoother_sweeps       = 2;
  data.aggregation_threshold = 0.02;
  const auto &dofs           = body.dof_handler();
  DoFTools::extract_constant_modes(dofs,
                                   ComponentMask(2, true),
                                   data.constant_modes);
  amg.initialize(A, data);
  const double setup = timer.wall_time();
  for (const double tolerance : {1e-8, 1e-10, 1e-12})
    {
      TrilinosWrappers::MPI::Vector b(complete_index_set(K.m()), MPI_COMM_SELF),
        x(complete_index_set(K.m()), MPI_COMM_SELF);
      for (unsigned int i = 0; i < K.m(); ++i)
        b[i] = rhs(i);
      b.compress(VectorOperation::insert);
      SolverControl control(20000, tolerance * b.l2_norm());
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      timer.restart();
      cg.solve(A, x, b, amg);
      const double solve = timer.wall_time();
      double       error = 0., size = 0.;
      for (unsigned int i = 0; i < K.m(); ++i)
        {
          error = std::max(error, std::abs(x[i] - x_direct(i)));
          size  = std::max(size, std::abs(x_direct(i)));
        }
      std::printf("CG+ML (rel. residual %.0e): copy %.3f s, AMG set-up %.3f "
                  "s, %u iterations %.3f s; max |x - x_direct| / max|x| = "
                  "%.2e\n",
                  tolerance,
                  copy,
                  setup,
                  control.last_step(),
                  solve,
                  error / size);
    }
  return 0;
}
