// Benchmark (not a test): a long interface, every node active. A strip of
// nx x ny square Q4 elements is pressed onto a base block of the same mesh
// and material (its top the faceted master), both held at their left
// edges in x and the base at its bottom in y: a uniform compression, so
// the exact contact pressure is uniform (each slave node carries the same
// force, the two end nodes half of it) and sums to the top's reaction.
// Prints the time per Newton iteration, the peak memory and those two
// checks, for Contact solver/Method = sparse or condensed.
//
//   glissade_large_contact_benchmark <nx> <ny> <sparse|condensed> [surface]
//
// surface: the master's Surface entry, faceted (default) or bspline.

#include <glissade/base/memory_use.h>
#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
  using namespace glissade;
  using namespace dealii;

  std::string
  block(const std::string &name,
        const double       y0,
        const double       y1,
        const unsigned int nx,
        const unsigned int ny,
        const std::string &conditions)
  {
    return "subsection Body " + name +
           "\n subsection Mesh\n  set Type = rectangle\n"
           "  set Corner 1 = 0, " +
           std::to_string(y0) + "\n  set Corner 2 = " + std::to_string(nx) +
           ", " + std::to_string(y1) +
           "\n  set Subdivisions = " + std::to_string(nx) + ", " +
           std::to_string(ny) +
           "\n end\n subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n end\n subsection Boundary "
           "conditions\n" +
           conditions + "\n end\nend\n";
  }

  double
  peak_memory_gib()
  {
    return memory_use().peak / (1024. * 1024. * 1024.);
  }
} // namespace

int
main(int argc, char **argv)
{
  const std::string method  = argc >= 4 ? argv[3] : "";
  const std::string surface = argc == 5 ? argv[4] : "faceted";
  if (argc < 4 || argc > 5 || !(method == "sparse" || method == "condensed") ||
      !(surface == "faceted" || surface == "bspline"))
    {
      std::fprintf(stderr,
                   "usage: glissade_large_contact_benchmark <nx> <ny> "
                   "<sparse|condensed> [faceted|bspline]\n");
      return 1;
    }
  const unsigned int nx = std::stoi(argv[1]), ny = std::stoi(argv[2]);
  const double       h = ny; // elements of unit size
  const std::string  prm =
    "subsection Scene\n set Bodies = strip, base\n"
    " set Contact pairs = interface\nend\n" +
    block("strip",
          0.,
          h,
          nx,
          ny,
          "  set Fixed = left: x\n  set Prescribed displacement = top: y: "
          "-0.01*" +
            std::to_string(2. * h) + "*t") +
    block("base", -h, 0., nx, ny, "  set Fixed = left: x; bottom: y") +
    "subsection Contact interface\n set Slave body = strip\n"
    " set Slave boundary = bottom\n set Master body = base\n"
    " set Master boundary = top\n set Surface = " +
    surface +
    "\n"
    " set Alert distance = 0.5\nend\n"
    "subsection Contact solver\n set Method = " +
    method +
    "\nend\n"
    "subsection Output\n set Progress = false\n set VTU interval = 0\n"
    " set Initial state = false\n set Directory = large_contact_" +
    std::to_string(nx) + "_" + method + "\nend\n";

  Simulation    simulation(SceneReader::read_string(prm, "large contact"));
  dealii::Timer timer;
  simulation.advance_to(1., "increment 1");
  const double        wall = timer.wall_time();
  const RunStatistics s    = simulation.statistics();

  // The nodal forces against the uniform pressure, and the balance.
  const auto  &pair     = *simulation.contact().contact_pairs()[0];
  double       interior = 0., sum = 0.;
  unsigned int n_interior = 0;
  for (const auto &node : pair.nodes())
    {
      sum += node.reaction[1];
      const double x = node.reference_position[0];
      if (x > 0.5 && x < nx - 0.5)
        {
          interior += node.reaction[1];
          ++n_interior;
        }
    }
  const double uniform   = interior / n_interior;
  double       deviation = 0.;
  for (const auto &node : pair.nodes())
    {
      const double x     = node.reference_position[0];
      const double share = (x < 0.5 || x > nx - 0.5) ? 0.5 : 1.;
      deviation =
        std::max(deviation, std::abs(node.reaction[1] - share * uniform));
    }
  const double top = support_reaction(simulation.body("strip"), "top")[1];
  std::printf(
    "%s, %s master: %u active nodes, %u dofs, %u Newton iterations, %.2f s "
    "(%.2f s per iteration, of which %.2f s the contact step's "
    "factorisations), peak memory %.2f GiB; nodal forces uniform "
    "to %.1e of the force, sum of r_n %.6g against the top's "
    "reaction %.6g (%.1e)\n",
    method.c_str(),
    surface.c_str(),
    simulation.contact().n_active(),
    simulation.n_dofs(),
    s.newton_iterations,
    wall,
    wall / s.newton_iterations,
    (s.factorization_seconds + s.compliance_seconds + s.local_solve_seconds) /
      s.newton_iterations,
    peak_memory_gib(),
    deviation / uniform,
    sum,
    -top,
    std::abs(sum + top) / std::abs(top));
  return 0;
}
