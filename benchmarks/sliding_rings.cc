// Benchmark (not a test): large sliding, the contact Newton iteration's
// cost. Case 3's rings (prm/case3_rings.prm) at E = 1e3, loaded in 10
// increments, then the inner ring turned through 2 pi in 400, for each
// master kind: Newton iterations per increment (mean and largest over the
// turn), cut-backs, and wall time per increment. doc/performance.md keeps
// the figures of the fixed-point contact iteration (before the consistent
// tangent) beside these.

#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  using namespace glissade;
  using namespace dealii;
  if (argc != 2)
    {
      std::fprintf(stderr,
                   "usage: glissade_sliding_benchmark <case3_rings.prm>\n");
      return 1;
    }
  std::printf("rings (E = 1e3, 40 x 4 each) turned through 2 pi in 400 "
              "increments, frame updated at every Newton iteration:\n");
  for (const std::string surface : {"faceted", "bspline", "hermite"})
    {
      std::vector<std::string> overrides = {
        "Contact interface/Surface=" + surface,
        "Body inner/Material/Young modulus=1e3",
        "Body outer/Material/Young modulus=1e3",
        "Body inner/Boundary conditions/Prescribed rotation=inner: 0, 0: "
        "2*pi*max(t - 1, 0)",
        "Load program/Stage increments=10, 400",
        "Output/Progress=false",
        "Output/VTU interval=0",
        "Output/Directory=sliding_benchmark_" + surface};
      if (surface == "hermite")
        overrides.push_back("Body outer/Element/Space=hermite");
      Simulation    simulation(SceneReader::read_file(argv[1], overrides));
      unsigned int  turned = 0, total = 0, largest = 0, increment = 0;
      double        turn_seconds = 0.;
      dealii::Timer timer;
      try
        {
          for (unsigned int k = 1; k <= 410; ++k)
            {
              const double t = k <= 10 ? 0.1 * k : 1. + (k - 10) / 400.;
              timer.restart();
              const unsigned int its =
                simulation.advance_to(t, "increment " + std::to_string(k));
              increment = k;
              if (k > 10)
                {
                  turn_seconds += timer.wall_time();
                  ++turned;
                  total += its;
                  largest = std::max(largest, its);
                }
            }
        }
      catch (const ConvergenceFailure &failure)
        {
          std::printf("  %-8s stopped at increment %u: %s\n",
                      surface.c_str(),
                      increment + 1,
                      failure.what());
        }
      std::printf("  %-8s %u dofs: %3u turn increments, Newton iterations "
                  "per increment %.2f (largest %u), %u cut-backs, %.1f ms "
                  "per increment\n",
                  surface.c_str(),
                  simulation.n_dofs(),
                  turned,
                  turned ? double(total) / turned : 0.,
                  largest,
                  simulation.statistics().cut_backs,
                  turned ? 1000. * turn_seconds / turned : 0.);
    }
  return 0;
}
