// Benchmark (not a test): the contact search against the number of bodies
// under automatic contact (issue 53). n identical annuli on a square grid,
// each 0.02 from its neighbours (up to four touch within the alert
// distance), all listed in Scene/Contact bodies with two passes. Printed
// per n (10, 100, 1,000 by default): the pairs made (those of the couples
// the broad phase finds within reach; the couples are n (n - 1) / 2), the
// boundary segments, the time of one detection over every pair
// (ContactProblem::begin_step: broad phase, then the pairs' projections)
// and the growth exponent between successive n. A search that grows like
// the segments (n log n) has an exponent near 1; one that searches every
// couple, near 2.
//
//   glissade_many_bodies_benchmark [largest n = 1000] [segments per ring = 48]

#include <deal.II/base/timer.h>

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
  using namespace glissade;

  /** n rings on a square grid, 0.02 apart, each held at its inner edge. */
  std::string
  grid_of_rings(const unsigned int n, const unsigned int segments)
  {
    const unsigned int columns =
      static_cast<unsigned int>(std::ceil(std::sqrt(double(n))));
    std::string names, listed, bodies;
    for (unsigned int i = 0; i < n; ++i)
      {
        const std::string name = "r" + std::to_string(i);
        names += (i ? ", " : "") + name;
        listed += (i ? ", " : "") + name + ": outer";
        bodies += "subsection Body " + name +
                  "\n subsection Mesh\n  set Type = ring\n  set Center = " +
                  std::to_string(2.02 * (i % columns)) + ", " +
                  std::to_string(2.02 * (i / columns)) +
                  "\n  set Inner radius = 0.5\n  set Outer radius = 1\n"
                  "  set Subdivisions = " +
                  std::to_string(segments) +
                  ", 1\n end\n"
                  " subsection Boundary conditions\n"
                  "  set Fixed = inner: xy\n end\nend\n";
      }
    return "subsection Scene\n set Bodies = " + names +
           "\n set Contact bodies = " + listed + "\nend\n" + bodies +
           "subsection Automatic contact\n set Surface = bspline\n"
           " set Alert distance = 0.05\nend\n"
           "subsection Output\n set Progress = false\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned int largest  = argc > 1 ? std::atoi(argv[1]) : 1000;
  const unsigned int segments = argc > 2 ? std::atoi(argv[2]) : 48;
  std::printf("contact search under automatic contact: n rings of %u "
              "boundary segments on a square grid, two passes\n",
              segments);
  std::printf("%6s %8s %10s %14s %14s %9s\n",
              "rings",
              "pairs",
              "segments",
              "set-up (s)",
              "detection (s)",
              "exponent");
  double previous_time = 0., previous_segments = 0.;
  for (unsigned int n = 10; n <= largest; n *= 10)
    {
      dealii::Timer set_up;
      Simulation    simulation(
        SceneReader::read_string(grid_of_rings(n, segments), "rings"));
      const double set_up_time = set_up.wall_time();
      // The detection of a step, repeated until it has taken 0.5 s.
      dealii::Timer timer;
      unsigned int  repeats = 0;
      do
        {
          simulation.contact().begin_step(0., 0.);
          ++repeats;
        }
      while (timer.wall_time() < 0.5);
      const double time        = timer.wall_time() / repeats;
      const double n_segments  = double(n) * segments;
      const auto   n_pairs     = simulation.contact().contact_pairs().size();
      const bool   has_earlier = previous_time > 0.;
      std::printf("%6u %8zu %10.0f %14.3f %14.6f ",
                  n,
                  n_pairs,
                  n_segments,
                  set_up_time,
                  time);
      if (has_earlier)
        std::printf("%9.2f\n",
                    std::log(time / previous_time) /
                      std::log(n_segments / previous_segments));
      else
        std::printf("%9s\n", "-");
      previous_time     = time;
      previous_segments = n_segments;
    }
  return 0;
}
