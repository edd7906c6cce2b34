// Newton-Raphson with the consistent tangent converges quadratically: the
// residual sequence r_k satisfies r_{k+1} ~ C r_k^2 in the asymptotic phase.
// The measured order p_k = log(r_{k+1}/r_k) / log(r_k/r_{k-1}) is printed
// for every step above round-off and the best of the last ones is asserted.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <memory>
#include <tuple>

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

// Newton/Last correction with previous tangent: where the residual already
// meets its tolerance, the correction that the displacement test waits for
// is solved with the last factorisation. Case 3's rings (B-spline master,
// 3 degrees of sliding, Coulomb friction 0.1) run both ways must take
// Newton iterations equal or within one in every increment (round-off
// decides the last one) and end at the same state to
// the displacement tolerance, with one factorisation fewer per body and
// increment where the shortcut applied.
GLISSADE_TEST(newton_last_correction_with_previous_tangent)
{
  const auto run = [](const bool previous_tangent) {
    const std::string flag  = previous_tangent ? "true" : "false";
    const auto        scene = SceneReader::read_file(
      source_path("prm/case3_rings.prm"),
      {"Contact interface/Surface=bspline",
              "Contact interface/Friction coefficient=0.1",
              "Load program/Stage end times=1, " + std::to_string(1. + 3. / 180.),
              "Load program/Stage increments=3, 2",
              "Newton/Residual tolerance=1e-10",
              "Newton/Displacement tolerance=1e-10",
              "Newton/Last correction with previous tangent=" + flag,
              "Output/Progress=false",
              "Output/VTU interval=0",
              "Output/Directory=newton_previous_tangent_" + flag});
    auto                      simulation = std::make_unique<Simulation>(scene);
    std::vector<unsigned int> iterations;
    unsigned int              before = 0;
    simulation->on_increment         = [&](unsigned int, double) {
      const unsigned int total = simulation->statistics().newton_iterations;
      iterations.push_back(total - before);
      before = total;
    };
    simulation->run();
    return std::make_tuple(std::move(simulation), iterations);
  };
  const auto [full, full_iterations]         = run(false);
  const auto [shortcut, shortcut_iterations] = run(true);

  const RunStatistics a = full->statistics(), b = shortcut->statistics();
  std::cout << "  full Newton: " << a.newton_iterations << " iterations, "
            << a.n_cholesky + a.n_lu << " factorisations" << std::endl
            << "  last correction with the previous tangent: "
            << b.newton_iterations << " iterations, " << b.n_cholesky + b.n_lu
            << " factorisations, " << b.n_reused_factorizations
            << " solves with the previous one" << std::endl;
  check_iterations_within_one(full_iterations,
                              shortcut_iterations,
                              "full Newton; previous tangent");
  check(a.n_reused_factorizations == 0, "the full run reused a factorisation");
  check(b.n_reused_factorizations > 0, "the shortcut never applied");
  // Every correction of each body (two bodies, no cut-back) either
  // factorised or reused the last factorisation.
  for (const RunStatistics *s : {&a, &b})
    check(s->n_cholesky + s->n_lu + s->n_reused_factorizations ==
            2 * s->newton_iterations,
          "a correction neither factorised nor reused a factorisation");
  check(b.n_cholesky + b.n_lu < a.n_cholesky + a.n_lu,
        "the shortcut saved no factorisation");

  double difference = 0., size = 0.;
  for (const std::string name : {"inner", "outer"})
    {
      Vector<double> d = full->body(name).displacement();
      size += d.norm_sqr();
      d -= shortcut->body(name).displacement();
      difference += d.norm_sqr();
    }
  const double relative = std::sqrt(difference / size);
  std::cout << "  |u_shortcut - u_full| / |u| = " << relative << std::endl;
  check(relative <= 1e-10,
        "the end states differ by more than the "
        "displacement tolerance");
}
