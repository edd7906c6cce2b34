// Benchmark (not a test): the contact part of a Newton iteration against
// the number of active contact nodes and the number of dofs. A strip of
// Q4 elements is pushed onto a rigid flat, so every bottom node is active.
// Per Newton iteration: factorisation, detection (projection), compliance
// matrix W = H K^-1 H^T, local bi-potential solve. With `faceted` or
// `bspline` the flat is a deformable base block (the master), and the
// cost of the contact tangent in the condensed problem is measured
// against the factorisation.

#include <deal.II/base/timer.h>

#include <glissade/contact/step/condensed_problem.h>
#include <glissade/lac/direct_solver.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace
{
  using namespace glissade;
  using namespace dealii;

  /**
   * At the converged state: the condensed problem formed with and without
   * the contact tangent's terms, timed, against one factorisation.
   */
  void
  time_contact_tangent(Simulation &simulation)
  {
    const auto                 &bodies = simulation.bodies();
    std::vector<Vector<double>> predictor(bodies.size());
    dealii::Timer               timer;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        bodies[b]->assemble();
        bodies[b]->system().factorize();
        bodies[b]->system().solve(bodies[b]->system().right_hand_side(),
                                  predictor[b]);
      }
    const double factorisation = timer.wall_time();
    simulation.contact().update_state();
    std::vector<ContactNode *> active;
    ActiveNodes nodes = simulation.contact().active_nodes(active);
    timer.restart();
    {
      const CondensedProblem with(nodes, Augmentation(), bodies, predictor);
    }
    const double      with_tangent = timer.wall_time();
    const std::size_t n_terms      = nodes.terms.size();
    nodes.terms.clear();
    timer.restart();
    {
      const CondensedProblem without(nodes, Augmentation(), bodies, predictor);
    }
    const double without_tangent = timer.wall_time();
    std::printf("       contact tangent at %zu active nodes (%zu rank-one "
                "terms): condensed problem %.4f s with it, %.4f s without: "
                "the tangent costs %.4f s, against %.4f s for the "
                "factorisation and solve of every body\n",
                active.size(),
                n_terms,
                with_tangent,
                without_tangent,
                with_tangent - without_tangent,
                factorisation);
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace glissade;
  using namespace dealii;
  const std::string mode = argc == 4 ? argv[3] : "";
  if (!(argc == 3 || (argc == 4 && (mode == "indenter" || mode == "faceted" ||
                                    mode == "bspline"))))
    {
      std::fprintf(stderr,
                   "usage: glissade_contact_benchmark <nx> <ny> "
                   "[indenter|faceted|bspline]\n");
      return 1;
    }
  const unsigned int nx = std::stoi(argv[1]), ny = std::stoi(argv[2]);
  // indenter: a rigid disk of radius 5 under the middle in place of the
  // flat, and a small alert distance, so that only a patch of the declared
  // bottom touches (the case where forming only the touching columns of
  // the compliance pays). faceted, bspline: a deformable base block of
  // nx + 3 by 4 elements under the strip, its top the master surface.
  const bool        indenter   = mode == "indenter";
  const bool        deformable = mode == "faceted" || mode == "bspline";
  const double      length = 1., height = double(ny) / nx;
  const std::string base =
    "subsection Body base\n subsection Mesh\n  set Type = rectangle\n"
    "  set Corner 1 = 0, " +
    std::to_string(-4. / nx) + "\n  set Corner 2 = " + std::to_string(length) +
    ", 0\n  set Subdivisions = " + std::to_string(nx + 3) +
    ", 4\n end\n subsection Material\n"
    "  set Young modulus = 1000\n end\n subsection Boundary conditions\n"
    "  set Fixed = bottom: all\n end\nend\n";
  const std::string prm =
    std::string("subsection Scene\n set Bodies = strip") +
    (deformable ? ", base" : "") + "\n set Contact pairs = floor\nend\n" +
    (deformable ? base : std::string()) +
    "subsection Body strip\n subsection Mesh\n  set Type = rectangle\n"
    "  set Corner 2 = " +
    std::to_string(length) + ", " + std::to_string(height) +
    "\n  set Subdivisions = " + std::to_string(nx) + ", " + std::to_string(ny) +
    "\n end\n subsection Material\n  set Young modulus = 1000\n end\n"
    " subsection Boundary conditions\n  set Fixed = left: x\n"
    "  set Prescribed displacement = top: y: -0.01*" +
    std::to_string(height) +
    "*t\n end\nend\n"
    "subsection Contact floor\n set Slave body = strip\n"
    " set Slave boundary = bottom\n" +
    (deformable ?
       " set Alert distance = 1\n set Master body = base\n"
       " set Master boundary = top\n set Surface = " +
         mode + "\n set Force transfer = spline\nend\n" :
     indenter ?
       std::string(" set Alert distance = 1e-5\n"
                   " subsection Obstacle\n  set Type = disk\n"
                   "  set Point = 0.5, -5\n  set Radius = 5\n end\nend\n") :
       std::string(" set Alert distance = 1\n"
                   " subsection Obstacle\n  set Type = line\n"
                   "  set Point = 0, 0\n  set Normal = 0, 1\n end\nend\n")) +
    "subsection Output\n set Progress = false\nend\n";
  Simulation simulation(SceneReader::read_string(prm, "contact benchmark"));
  simulation.advance_to(1., "increment 1");
  const RunStatistics   s = simulation.statistics();
  const ContactProblem &c = simulation.contact();
  const double          n = s.newton_iterations;
  std::printf("%6u active nodes %9u dofs  Newton its %2u  per iteration: "
              "factorisation %8.4f s  detection %8.5f s  compliance %8.4f s  "
              "local solve %8.4f s (%u sweeps in the last)\n",
              c.n_active(),
              simulation.n_dofs(),
              s.newton_iterations,
              s.factorization_seconds / n,
              s.detection_seconds / n,
              s.compliance_seconds / n,
              s.local_solve_seconds / n,
              c.last_result().sweeps);
  const DirectSolver &solver =
    simulation.body("strip").system().direct_solver();
  std::printf("       factorisations: %u Cholesky (contact dofs last), %u LU; "
              "Cholesky analysis %.4f s, numeric %.4f s per factorisation, "
              "inverse block %.4f s per iteration (%ld of the %zu declared "
              "contact dofs' columns in the last)\n",
              solver.n_cholesky,
              solver.n_lu,
              solver.cholesky().analysis_seconds,
              solver.cholesky().factorization_seconds /
                std::max(1u, solver.n_cholesky),
              solver.cholesky().inverse_seconds / n,
              solver.cholesky().n_inverse_columns(),
              std::size_t(2 * (nx + 1)));

  if (deformable)
    {
      time_contact_tangent(simulation);
      return 0;
    }

  // The same tangent, factorised by a bare UMFPACK LU and by Cholesky with
  // the fill-reducing ordering alone (no contact dofs last): what the
  // contact-last ordering costs in the factorisation itself.
  // (assembled again at the converged state: the run lets each tangent's
  // entries go once factorised)
  simulation.body("strip").assemble();
  const SparseMatrix<double> &K =
    simulation.body("strip").system().tangent_matrix();
  // (the second factorisation is of 2 K: a DirectSolver keeps its factor
  // for a matrix equal to the last, and K again timed nothing)
  SparseMatrix<double> twice(K.get_sparsity_pattern());
  twice.copy_from(K);
  twice *= 2.;
  DirectSolver lu, plain_cholesky;
  plain_cholesky.use_cholesky(true, {});
  for (DirectSolver *other : {&lu, &plain_cholesky})
    {
      other->factorize(K); // analysis + numeric
      const double first = other->numeric_seconds + other->symbolic_seconds;
      other->factorize(twice); // numeric only
      const double again =
        other->numeric_seconds + other->symbolic_seconds - first;
      std::printf("       same matrix, %-34s %.4f s per factorisation\n",
                  other == &lu ? "bare UMFPACK LU:" :
                                 "Cholesky, no contact dofs last:",
                  again);
    }
  return 0;
}
