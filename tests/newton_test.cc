// Newton-Raphson with the consistent tangent converges quadratically: the
// residual sequence r_k satisfies r_{k+1} ~ C r_k^2 in the asymptotic phase.
// The measured order p_k = log(r_{k+1}/r_k) / log(r_k/r_{k-1}) is printed
// for every step above round-off and the best of the last ones is asserted.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  void
  check_quadratic(const std::vector<double> &r)
  {
    std::cout << "  scaled residuals:";
    for (const double x : r)
      std::cout << ' ' << x;
    std::cout << std::endl;
    // Only steps whose result is well above the round-off floor say
    // anything about the rate.
    const double floor = 1e-12;
    double       best  = 0.;
    for (unsigned int k = 1; k + 1 < r.size(); ++k)
      if (r[k + 1] > floor && r[k] < 1e-2)
        {
          const double p =
            std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
          std::cout << "  order estimate at iteration " << k + 1 << ": " << p
                    << std::endl;
          best = std::max(best, p);
        }
    check(r.size() >= 4, "too few iterations to measure a rate");
    std::cout << "  best asymptotic order " << best << " (expected 2)"
              << std::endl;
    check(best >= 1.8, "Newton does not converge quadratically");
  }
} // namespace

// The Table 1 beam under twice its load (100 kN) in one increment: a tip
// deflection near half the length, so that Newton needs several iterations
// before its quadratic phase.
GLISSADE_TEST(newton_quadratic_beam)
{
  const auto scene = SceneReader::read_file(
    source_path("prm/table1_beam.prm"),
    {"Body beam/Mesh/Subdivisions=60,4",
     "Body beam/Boundary conditions/Tractions=right: 0, -100000/0.186*t",
     "Newton/Residual tolerance=1e-12",
     "Newton/Displacement tolerance=1e-12",
     "Output/Progress=false"});
  Simulation simulation(scene);
  simulation.advance_to(1., "increment 1");
  check_quadratic(simulation.last_residuals());
}

// A block under follower pressure on two sides: checks the load stiffness
// of the pressure (an unsymmetric tangent), which a wrong sign or a missing
// term would reduce to linear convergence.
GLISSADE_TEST(newton_quadratic_follower_pressure)
{
  const std::string prm = R"(
subsection Scene
  set Bodies = block
end
subsection Body block
  subsection Mesh
    set Type = rectangle
    set Corner 2 = 1, 1
    set Subdivisions = 6, 6
  end
  subsection Material
    set Young modulus = 1000
    set Poisson ratio = 0.3
  end
  subsection Boundary conditions
    set Fixed = bottom: y; left: x
    set Pressure = top: 150*t; right: 60*t
  end
end
subsection Newton
  set Residual tolerance = 1e-12
  set Displacement tolerance = 1e-12
end
subsection Output
  set Progress = false
end
)";
  Simulation simulation(SceneReader::read_string(prm, "follower pressure"));
  simulation.advance_to(1., "increment 1");
  check_quadratic(simulation.last_residuals());
}
