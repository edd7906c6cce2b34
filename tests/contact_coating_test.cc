// An abradable coating on a casing (Contact/Obstacle/Coating ...): a stiff
// blade tip pushed 0.5 into a coating of thickness 2 on a circular casing
// of radius 100 (its surface at 98) while the casing turns once round it,
// quasi-statically: the coating, rigid and perfectly plastic at a low
// yield pressure, gives way wherever the tip presses on it, and the area
// removed is the ring the tip's outermost points sweep, pi (r_c^2 - 98^2)
// with r_c = sqrt(98.5^2 + 1) the tip's corners (its elastic shortening
// under a force of 2 per unit thickness is 2e-5 of the incursion): within
// 1 %. With a yield pressure that the tip cannot reach, nothing is removed
// and the casing holds the tip back as a rigid one does.

#include <glissade/contact/surfaces/abradable_coating.h>
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
  const std::string rubbed_tip = R"(
subsection Scene
  set Bodies        = tip
  set Contact pairs = rub
end
subsection Body tip
  subsection Mesh
    set Type         = rectangle
    set Corner 1     = -1, 90
    set Corner 2     = 1, 97.9
    set Subdivisions = 4, 8
  end
  subsection Material
    set Young modulus = 200000
    set Poisson ratio = 0.3
  end
  subsection Boundary conditions
    set Prescribed displacement = bottom: y: 0.6*min(t/0.1, 1)
    set Fixed                   = bottom: x
  end
end
subsection Contact rub
  set Slave body     = tip
  set Slave boundary = top
  set Master body    = rigid
  set Alert distance = 1
  subsection Obstacle
    set Type                   = casing
    set Point                  = 0, 0
    set Radius                 = 100
    set Lobes                  = 2
    set Lobe depth             = 0
    set Rotation               = 2*pi*max(t - 0.1, 0)/0.9
    set Coating thickness      = 2
    set Coating yield pressure = 1
  end
end
subsection Load program
  set Stage end times  = 1
  set Stage increments = 400
end
subsection Output
  set VTU interval = 0
  set Progress     = false
  set History      = contact_force(rub); wear(rub)
end
)";
} // namespace

GLISSADE_TEST(contact_coating_removed_area)
{
  Simulation simulation(SceneReader::read_string(
    rubbed_tip,
    "rubbed_tip.prm",
    {"Output/Directory=contact_coating_removed_area"}));
  simulation.run();
  const ContactPair &pair     = *simulation.contact().contact_pairs()[0];
  const double       corner   = std::hypot(98.5, 1.);
  const double       expected = M_PI * (corner * corner - 98. * 98.);
  const auto        &profile  = pair.coating()->profile();
  double             least = 1e300, most = 0.;
  for (const double w : profile)
    {
      least = std::min(least, w);
      most  = std::max(most, w);
    }
  std::cout << std::setprecision(8) << "  removed area " << pair.removed_area()
            << " (the swept ring " << expected << "); worn depth from " << least
            << " to " << most << " (the corners reach " << corner - 98. << ")"
            << std::endl;
  check_relative(pair.removed_area(), expected, 0.01, "the removed area");
  check(least >= 0.99 * (corner - 98.),
        "a part of the casing the tip swept is not worn");
  // (the tip bends a little under the worn surface's slope: 1e-4 of play)
  check(most <= corner - 98. + 1e-4, "the coating is worn beyond the tip");
}

GLISSADE_TEST(contact_coating_too_strong_to_wear)
{
  Simulation simulation(SceneReader::read_string(
    rubbed_tip,
    "rubbed_tip.prm",
    {"Output/Directory=contact_coating_too_strong",
     "Contact rub/Obstacle/Coating yield pressure=1e12",
     "Load program/Stage end times=0.2",
     "Load program/Stage increments=20"}));
  simulation.run();
  const ContactPair &pair    = *simulation.contact().contact_pairs()[0];
  double             deepest = 0.;
  for (const ContactNode &node : pair.nodes())
    if (node.active)
      deepest = std::min(deepest, node.gap);
  std::cout << std::setprecision(8) << "  removed area " << pair.removed_area()
            << ", deepest gap " << deepest << ", force on the tip "
            << pair.total_force()[1] << std::endl;
  check(pair.removed_area() == 0., "a coating that does not yield was worn");
  check(deepest >= -1e-10, "a node went behind a coating that does not yield");
  check(pair.total_force()[1] < -1., "the casing does not hold the tip back");
}
