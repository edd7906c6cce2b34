// Table 1 of the paper, Q4 column: the cantilever's largest displacement
// norm on four meshes, each within 2 % of the published figure. The beam
// size and nu are our documented choice (prm/table1_beam.prm); two values
// fitted, four figures checked, so the test measures the Q4 convergence
// curve and not only its end point.

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  double
  beam_max_displacement(const std::string              &space,
                        const unsigned int              along,
                        const unsigned int              across,
                        const std::vector<std::string> &more = {})
  {
    std::vector<std::string> overrides = {"Body beam/Element/Space=" + space,
                                          "Body beam/Mesh/Subdivisions=" +
                                            std::to_string(along) + "," +
                                            std::to_string(across),
                                          "Output/Progress=false"};
    overrides.insert(overrides.end(), more.begin(), more.end());
    const auto scene =
      SceneReader::read_file(source_path("prm/table1_beam.prm"), overrides);
    Simulation         simulation(scene);
    const unsigned int n = scene.load_program.stage_increments[0];
    for (unsigned int k = 1; k <= n; ++k)
      simulation.advance_to(double(k) / n, "increment " + std::to_string(k));
    // Balance law on the way: the clamp carries the whole 50 kN.
    const Tensor<1, 2> R = support_reaction(simulation.body("beam"), "left");
    check_relative(R[1], 50000., 1e-9, "clamp reaction (N)");
    return max_displacement(simulation.body("beam"));
  }
} // namespace

GLISSADE_TEST(table1_q4)
{
  const unsigned int along[]  = {30, 60, 120, 240};
  const unsigned int across[] = {2, 4, 8, 16};
  const double       paper[]  = {0.259, 0.282, 0.288, 0.290};
  for (unsigned int i = 0; i < 4; ++i)
    check_relative(beam_max_displacement("q1", along[i], across[i]),
                   paper[i],
                   0.02,
                   "Q4 (" + std::to_string(along[i]) + "," +
                     std::to_string(across[i]) + ") max |u| (m)");
}

// The NURBS rows (issue 52): degree 2 and 3 (C1 and C2 along the beam) on
// the paper's three first meshes, each within 0.5 % of the paper's
// converged 0.290 (Q4 is 10.7 % below it on the coarsest), the clamp's
// reaction 50 kN on the way (the residual of the clamped control points).
GLISSADE_TEST(table1_nurbs)
{
  const unsigned int along[]  = {30, 60, 120};
  const unsigned int across[] = {2, 4, 8};
  for (const unsigned int degree : {2u, 3u})
    for (unsigned int i = 0; i < 3; ++i)
      check_relative(beam_max_displacement(
                       "nurbs",
                       along[i],
                       across[i],
                       {"Body beam/Element/Degree=" + std::to_string(degree),
                        "Output/Directory=output/table1_nurbs"}),
                     0.290,
                     0.005,
                     "NURBS p = " + std::to_string(degree) + " (" +
                       std::to_string(along[i]) + "," +
                       std::to_string(across[i]) + ") max |u| (m)");
}
