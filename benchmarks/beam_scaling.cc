// Benchmark (not a test): the Table 1 beam at one mesh size, solved with the
// full 50 kN in two increments. Prints dofs, assembly and factorisation time
// per Newton iteration, Newton iterations, time per increment and peak
// memory, one line, so that a loop over sizes gives a table. Each size runs
// in its own process so that "peak memory" belongs to that size alone.

#include <glissade/base/memory_use.h>
#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cstdio>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  using namespace glissade;
  using namespace dealii;
  if (argc != 3)
    {
      std::cerr
        << "usage: glissade_benchmark <prm/table1_beam.prm> <n_across>\n";
      return 1;
    }
  const unsigned int across = std::stoi(argv[2]);
  // Near-square cells on the 1 x 0.186 beam.
  const unsigned int along = static_cast<unsigned int>(across / 0.186 + 0.5);
  try
    {
      const auto scene = SceneReader::read_file(
        argv[1],
        {"Body beam/Mesh/Subdivisions=" + std::to_string(along) + "," +
           std::to_string(across),
         "Load program/Stage increments=2",
         "Output/Progress=false"});
      Simulation simulation(scene);
      Timer      wall;
      for (unsigned int k = 1; k <= 2; ++k)
        simulation.advance_to(0.5 * k, "increment " + std::to_string(k));
      const double         total = wall.wall_time();
      const RunStatistics &s     = simulation.statistics();
      const unsigned int   n     = std::max(1u, s.newton_iterations);

      std::printf("%9u dofs  %5ux%-4u  assembly %8.3f s/it  factorization "
                  "%8.3f s/it  Newton its %2u  %8.2f s/increment  peak "
                  "memory %7.1f MB  max|u| %.4f\n",
                  simulation.body("beam").n_dofs(),
                  along,
                  across,
                  s.assembly_seconds / (n + 2), // n updates + 1 check/increment
                  s.factorization_seconds / n,
                  s.newton_iterations,
                  total / 2.,
                  memory_use().peak / (1024. * 1024.),
                  max_displacement(simulation.body("beam")));
    }
  catch (const std::exception &e)
    {
      std::cerr << "glissade_benchmark: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}
