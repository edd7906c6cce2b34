// Coulomb friction in steady sliding, solved in the true frame: against a
// rigid flat the friction force is mu times the normal force, whether the
// pad moves or the flat moves under it; along a deformable B-spline master
// the ratio is a property of the sliding state, not of the increment size.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>
#include <iomanip>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** F_x / F_y of the pad at the end of a run, and the Newton iterations. */
  double
  friction_ratio(const std::string              &file,
                 const std::vector<std::string> &overrides,
                 const std::string              &label)
  {
    std::vector<std::string> all = overrides;
    all.push_back("Output/Progress=false");
    all.push_back("Output/Directory=friction_" + label);
    Simulation simulation(SceneReader::read_file(source_path(file), all));
    simulation.run();
    const Tensor<1, 2> force =
      simulation.contact().contact_pairs()[0]->total_force();
    const auto   statistics = simulation.statistics();
    const double ratio      = -force[0] / force[1];
    std::cout << "  " << label << ": F = (" << force
              << "), F_x / F_y = " << std::setprecision(12) << ratio
              << std::setprecision(10) << ", " << statistics.increments
              << " increments, "
              << double(statistics.newton_iterations) / statistics.increments
              << " Newton iterations per increment" << std::endl;
    return ratio;
  }
} // namespace

GLISSADE_TEST(contact_friction_steady_sliding_rigid_flat)
{
  const double mu = 0.2;
  const double moving_pad =
    friction_ratio("tests/data/pad_on_flat.prm", {}, "pad_slid_on_flat");
  check_relative(moving_pad, mu, 1e-6, "F_x / F_y, the pad slid");
  // The flat moved under the held pad: the slip is measured against the
  // obstacle's motion (before, it counted the bodies' displacements only,
  // and the friction force came out as 2.6e-10 N).
  const double moving_flat = friction_ratio(
    "tests/data/pad_on_flat.prm",
    {"Body pad/Boundary conditions/Prescribed displacement=top: x: 0; top: y: "
     "-0.01*min(t, 1)",
     "Contact sliding/Obstacle/Motion=-2*max(t - 1, 0), 0"},
    "flat_moved_under_pad");
  check_relative(moving_flat, mu, 1e-6, "F_x / F_y, the flat moved");
}

GLISSADE_TEST(contact_friction_steady_sliding_bspline_strip)
{
  const double n      = friction_ratio("tests/data/pad_on_strip.prm",
                                  {"Load program/Stage increments=2, 25"},
                                  "strip_25_increments");
  const double four_n = friction_ratio("tests/data/pad_on_strip.prm",
                                       {"Load program/Stage increments=2, 100"},
                                       "strip_100_increments");
  check_relative(n, four_n, 1e-3, "F_x / F_y with N against 4N increments");
  // Every node slips: the ratio differs from mu only by the tilt of the
  // indented strip under the pad.
  check(std::abs(four_n - 0.2) < 0.01, "F_x / F_y within 5 % of mu");
}

// The rubber block of prm/rubber_block_drag.prm (issue 33), its bottom
// corners rounded (a fillet of radius 2 mm): dragged 10 mm on the rigid
// flat with mu = 0.3, it reaches full sliding, where Coulomb's law gives
// F_x / F_y = mu exactly (every node in contact slips on the flat), and
// keeps sliding to the end with no cut-back. (Its sharp-cornered version
// stops where the leading corner folds: test rubber_block_sharp_corner_folds.)
GLISSADE_TEST(contact_friction_rubber_block_with_rounded_corners_slides)
{
  std::vector<double> drag, ratio;
  Simulation          simulation(SceneReader::read_file(
    source_path("prm/rubber_block_drag.prm"),
    {"Body block/Mesh/Type=gmsh",
              "Body block/Mesh/File=meshes/rubber_block_fillet_r2.msh",
              "Output/Progress=false",
              "Output/Plots=false",
              "Output/VTU interval=0",
              "Output/Directory=friction_rubber_block_rounded"}));
  simulation.on_increment = [&](unsigned int, double t) {
    const Tensor<1, 2> force =
      simulation.contact().contact_pairs()[0]->total_force();
    drag.push_back(10. * std::max(t - 1., 0.));
    ratio.push_back(force[1] != 0. ? -force[0] / force[1] : 0.);
  };
  simulation.run();
  double full_sliding_from = -1.;
  for (unsigned int i = 0; i < ratio.size(); ++i)
    if (full_sliding_from < 0. && ratio[i] >= 0.297)
      full_sliding_from = drag[i];
  std::cout << "  F_x / F_y " << std::setprecision(12) << ratio.back()
            << " at the end, >= 0.297 from " << full_sliding_from
            << " mm of drag; " << simulation.statistics().cut_backs
            << " cut-backs" << std::endl;
  check_relative(ratio.back(), 0.3, 1e-8, "F_x / F_y in full sliding");
  check(full_sliding_from > 0. && full_sliding_from < 8.,
        "full sliding reached before 8 mm of drag");
  check(simulation.statistics().cut_backs == 0, "no increment cut back");
}
