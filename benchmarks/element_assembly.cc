// Benchmark (not a test): assembly cost of each element space at equal
// element count (32 x 32 cells of a unit square under a small tension),
// and the dofs it takes. One line per space.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cstdio>
#include <iostream>

int
main()
{
  using namespace glissade;
  using namespace dealii;
  std::printf("%-8s %8s %8s %14s %14s\n",
              "space",
              "cells",
              "dofs",
              "assembly/cell",
              "assembly/dof");
  for (const std::string space : {"q1", "q2", "q3", "q8", "q12", "hermite"})
    {
      const std::string prm =
        "subsection Scene\n set Bodies = block\nend\n"
        "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
        "  set Corner 2 = 1, 1\n  set Subdivisions = 32, 32\n end\n"
        " subsection Element\n  set Space = " +
        space +
        "\n end\n"
        " subsection Material\n  set Young modulus = 1000\n end\n"
        " subsection Boundary conditions\n  set Fixed = left: xy\n"
        "  set Tractions = right: 1*t, 0\n end\nend\n"
        "subsection Output\n set Progress = false\nend\n";
      Simulation simulation(SceneReader::read_string(prm, space));
      simulation.advance_to(1., "increment 1");
      const RunStatistics &s = simulation.statistics();
      const Body          &b = simulation.body("block");
      // One assembly per Newton iteration plus the final check.
      const double per_assembly =
        s.assembly_seconds / (s.newton_iterations + 1);
      std::printf("%-8s %8u %8u %11.2f us %11.3f us\n",
                  space.c_str(),
                  b.triangulation().n_active_cells(),
                  b.n_dofs(),
                  1e6 * per_assembly / b.triangulation().n_active_cells(),
                  1e6 * per_assembly / b.n_dofs());
    }
  return 0;
}
