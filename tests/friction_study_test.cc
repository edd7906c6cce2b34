// The friction study (issue 22): case 3's rings with Coulomb friction.

#include <paper_studies/friction_study.h>

#include <algorithm>
#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace glissade_tests;

// Case 3 with mu = 0.1 on the B-spline master, compressed in 10 increments
// and turned through 1.8 degrees in 10 more. Closed forms: the radial
// compression of round rings loads the interface normally only, so every
// closed node sticks (r_t = 0 by symmetry, inside the cone); once the turn
// drives the inner ring every node slides in the same direction, so each
// carries |r_t| = mu r_n and the sums obey sum |r_t| = mu sum r_n exactly.
// Coulomb's law holds at every node at every increment (cone excess at
// round-off).
GLISSADE_TEST(friction_study_case3_stick_then_slip)
{
  const FrictionRun run =
    FrictionStudy::run_variant(source_path("prm/case3_rings.prm"),
                               "bspline",
                               0.1,
                               "friction_study_test",
                               {"Load program/Stage end times=1, 1.01",
                                "Load program/Stage increments=10, 10",
                                "Output/VTU interval=0",
                                "Output/History="});
  check(run.time.size() == 20, "20 increments");
  for (unsigned int i = 0; i < 10; ++i)
    check(run.sticking[i] == 40 && run.slipping[i] == 0,
          "compression: every node sticks (increment " + std::to_string(i + 1) +
            ": " + std::to_string(run.sticking[i]) + " sticking)");
  std::cout << "  stick -> slip at increments:";
  for (unsigned int i = 10; i < 20; ++i)
    std::cout << ' ' << run.sticking[i] << '/' << run.slipping[i];
  std::cout << std::endl;
  check(run.slipping.back() == 40, "the turn: every node slides at the end");
  check_relative(run.tangential_force.back() / run.normal_force.back(),
                 0.1,
                 1e-9,
                 "sum |r_t| / sum r_n once every node slides");
  std::cout << "  worst cone excess " << run.worst_cone_excess << std::endl;
  check(run.worst_cone_excess < 1e-10, "Coulomb's cone violated");
}
