// The Newton rate with contact: on one large sliding increment of each
// master kind, the last iterations converge with order >= 1.8 (the contact
// tangent is consistent; without it the contact iteration is a fixed
// point, order 1).

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /**
   * The order fitted on the last three residuals above the round-off
   * floor: p = log(r_k / r_k-1) / log(r_k-1 / r_k-2).
   */
  double
  fitted_order(const std::vector<double> &residuals, const std::string &label)
  {
    std::vector<double> above;
    std::cout << "  " << label << ": scaled residuals";
    for (const double r : residuals)
      {
        std::cout << ' ' << r;
        if (r > 1e-12)
          above.push_back(r);
      }
    std::cout << std::endl;
    check(above.size() >= 3,
          label + ": fewer than three residuals above 1e-12");
    const std::size_t k = above.size() - 1;
    const double      order =
      std::log(above[k] / above[k - 1]) / std::log(above[k - 1] / above[k - 2]);
    std::cout << "  " << label << ": fitted order " << order << " from "
              << above[k - 2] << ", " << above[k - 1] << ", " << above[k]
              << std::endl;
    return order;
  }

  /** The last increment of a run, with its residual history. */
  std::vector<double>
  last_increment_residuals(const SceneDescription &scene)
  {
    Simulation   simulation(scene);
    const auto  &program = scene.load_program;
    double       t0      = 0.;
    unsigned int number  = 0;
    for (unsigned int s = 0; s < program.stage_end_times.size(); ++s)
      {
        const unsigned int n = program.stage_increments[s];
        for (unsigned int k = 1; k <= n; ++k)
          simulation.advance_to(t0 + (program.stage_end_times[s] - t0) * k / n,
                                "increment " + std::to_string(++number));
        t0 = program.stage_end_times[s];
      }
    return simulation.last_residuals();
  }

  /**
   * Case 3's rings (E = 1e4), loaded in two increments, the inner ring
   * turned by half an element (4.5 degrees) in three, so that its nodes
   * face the middle of the master's segments, then by a third of an
   * element (3 degrees) in one.
   */
  void
  check_rings(const std::string &surface,
              const std::string &discretisation = "node-to-segment",
              const unsigned int degree         = 2,
              const bool         nurbs_inner    = false)
  {
    const std::string label =
      surface + (surface == "nurbs" ? " p = " + std::to_string(degree) : "") +
      " master" + (nurbs_inner ? ", NURBS slave" : "") + ", " + discretisation +
      ", 3 degrees of sliding";
    std::vector<std::string> overrides = {
      "Contact interface/Surface=" + surface,
      "Contact interface/Discretisation=" + discretisation,
      "Load program/Stage end times=1, 1.025, " +
        std::to_string(1. + 7.5 / 180.),
      "Load program/Stage increments=2, 3, 1",
      "Newton/Residual tolerance=1e-12",
      "Newton/Displacement tolerance=1e-12",
      "Output/Progress=false",
      "Output/VTU interval=0",
      "Output/Directory=newton_rate_" + surface + "_" + discretisation +
        std::to_string(degree) + (nurbs_inner ? "_nurbs_inner" : "")};
    if (surface == "hermite")
      overrides.push_back("Body outer/Element/Space=hermite");
    // (a NURBS outer ring keeps the scene's point supports and nodal
    // loads, through its functions at the points)
    if (surface == "nurbs")
      {
        overrides.push_back("Body outer/Element/Space=nurbs");
        overrides.push_back("Body outer/Element/Degree=" +
                            std::to_string(degree));
      }
    if (nurbs_inner)
      {
        overrides.push_back("Body inner/Element/Space=nurbs");
        overrides.push_back("Body inner/Element/Degree=" +
                            std::to_string(degree));
      }
    const double order =
      fitted_order(last_increment_residuals(SceneReader::read_file(
                     source_path("prm/case3_rings.prm"), overrides)),
                   label);
    check(order >= 1.8, label + ": Newton order below 1.8");
  }

  /**
   * A block pressed on a rigid obstacle in two increments, then its top
   * slid by a tenth of its width in one.
   */
  void
  check_rigid(const std::string &obstacle, const double friction)
  {
    std::string geometry;
    if (obstacle == "line")
      geometry = "  set Point = 0, 0\n  set Normal = 0.1, 1\n";
    else if (obstacle == "disk")
      geometry = "  set Point = 0.5, -2\n  set Radius = 2\n";
    else
      geometry = "  set Point = 0.5, 3\n  set Radius = 3\n";
    const std::string prm =
      "subsection Scene\n set Bodies = block\n set Contact pairs = floor\nend\n"
      "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
      "  set Corner 1 = 0, 0\n  set Corner 2 = 1, 0.5\n"
      "  set Subdivisions = 8, 4\n end\n subsection Material\n"
      "  set Young modulus = 1000\n  set Poisson ratio = 0.3\n end\n"
      " subsection Boundary conditions\n"
      "  set Prescribed displacement = top: x: 0.1*max(t - 1, 0); top: y: "
      "-0.03*min(t, 1)\n end\nend\n"
      "subsection Contact floor\n set Slave body = block\n"
      " set Slave boundary = bottom\n set Alert distance = 0.2\n"
      " set Friction coefficient = " +
      std::to_string(friction) +
      "\n set Tolerance = 1e-13\n"
      " subsection Obstacle\n  set Type = " +
      obstacle + "\n" + geometry +
      " end\nend\n"
      "subsection Load program\n set Stage end times = 1, 2\n"
      " set Stage increments = 2, 1\nend\n"
      "subsection Newton\n set Residual tolerance = 1e-12\n"
      " set Displacement tolerance = 1e-12\nend\n"
      "subsection Output\n set Progress = false\n set VTU interval = 0\n"
      " set Directory = newton_rate_" +
      obstacle + "\nend\n";
    const std::string label = "rigid " + obstacle +
                              ", mu = " + std::to_string(friction) +
                              ", slid by 0.1";
    const double order = fitted_order(
      last_increment_residuals(SceneReader::read_string(prm, label)), label);
    check(order >= 1.8, label + ": Newton order below 1.8");
  }
} // namespace

GLISSADE_TEST(contact_newton_rate_faceted)
{
  check_rings("faceted");
}

GLISSADE_TEST(contact_newton_rate_bspline)
{
  check_rings("bspline");
}

GLISSADE_TEST(contact_newton_rate_mortar)
{
  check_rings("faceted", "mortar");
}

GLISSADE_TEST(contact_newton_rate_mortar_bspline)
{
  check_rings("bspline", "mortar");
}

GLISSADE_TEST(contact_newton_rate_hermite)
{
  check_rings("hermite");
}

GLISSADE_TEST(contact_newton_rate_rigid_line)
{
  check_rigid("line", 0.);
}

GLISSADE_TEST(contact_newton_rate_rigid_disk)
{
  check_rigid("disk", 0.);
}

GLISSADE_TEST(contact_newton_rate_rigid_hole)
{
  check_rigid("hole", 0.);
}

GLISSADE_TEST(contact_newton_rate_rigid_disk_coulomb)
{
  check_rigid("disk", 0.3);
}

GLISSADE_TEST(contact_newton_rate_mortar_hermite)
{
  check_rings("hermite", "mortar");
}

GLISSADE_TEST(contact_newton_rate_nurbs)
{
  check_rings("nurbs", "node-to-segment", 2);
  check_rings("nurbs", "node-to-segment", 3);
}

GLISSADE_TEST(contact_newton_rate_mortar_nurbs)
{
  check_rings("nurbs", "mortar", 2);
}

// Both rings NURBS, mortar on the inner ring's own boundary
// (nurbs_slave_mortar.cc).
GLISSADE_TEST(contact_newton_rate_mortar_nurbs_on_nurbs)
{
  check_rings("nurbs", "mortar", 2, true);
  check_rings("nurbs", "mortar", 3, true);
}
