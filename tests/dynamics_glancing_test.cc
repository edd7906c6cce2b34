// A disk thrown at another off its centre (frictionless, automatic
// contact, both free): one deformable body sliding on another under a
// dynamic scheme, where the contact's forces at the step's end alone did
// positive work (a disk thrown at a held one 0.1 off its centre gained 2.5
// times its energy). Against what does not come from the code: the contact
// law's sign (no step whose contact does positive work), the conservation
// of the total momentum (the contact's forces are equal and opposite), and
// rigid-body impact mechanics: without friction the impulse on the struck
// disk is along the line of centres at the impact, its rebound no faster
// than the striker's approach along that line (restitution <= 1).

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** An annulus r in [0.25, 0.5] of 32 x 3 Q4 at (x, y), E = 1000. */
  std::string
  disk(const std::string &name,
       const double       x,
       const double       y,
       const std::string &rest)
  {
    return "subsection Body " + name +
           "\n subsection Mesh\n  set Type = ring\n  set Center = " +
           std::to_string(x) + ", " + std::to_string(y) +
           "\n  set Inner radius = 0.25\n  set Outer radius = 0.5\n"
           "  set Subdivisions = 32, 3\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n  set Density = 1\n end\n" +
           rest + "end\n";
  }

  struct Glance
  {
    std::string  scheme, surface, settings;
    unsigned int increments;
  };
} // namespace

// The striker (centre (0.3, 1.3), velocity (0, -1)) meets the struck disk
// (centre (0, 0), at rest) when their centres are 1 apart: the line of
// centres is then n = (-0.3, -sqrt(0.91)), 17.5 degrees from the striker's
// path. Every scheme with the contact law on the end positions (the mass
// redistributed), faceted and B-spline masters, two passes.
GLISSADE_TEST(dynamics_glancing_impact)
{
  const double offset = 0.3, speed = 1.;
  // (from the striker's centre to the struck disk's)
  const Tensor<1, 2> n({-offset, -std::sqrt(1. - offset * offset)});
  for (const Glance &glance :
       {Glance{"newmark", "faceted", "", 300},
        Glance{"newmark", "bspline", "", 300},
        Glance{"moreau-jean", "bspline", " set Moreau-Jean theta = 1\n", 300},
        Glance{"generalized-alpha", "bspline", "", 300}})
    {
      const std::string label = glance.scheme + ", " + glance.surface;
      const std::string prm =
        "subsection Scene\n set Bodies = struck, striker\n"
        " set Contact bodies = struck: outer, striker: outer\nend\n"
        "subsection Automatic contact\n set Surface = " +
        glance.surface + "\n set Alert distance = 0.05\nend\n" +
        disk("struck", 0., 0., "") +
        disk("striker",
             offset,
             1.3,
             " set Initial velocity = 0, " + std::to_string(-speed) + "\n") +
        "subsection Time integration\n set Scheme = " + glance.scheme + "\n" +
        glance.settings +
        "end\n"
        "subsection Load program\n set Stage end times = 0.9\n"
        " set Stage increments = " +
        std::to_string(glance.increments) +
        "\nend\n"
        "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
        "subsection Newton\n set Residual tolerance = 1e-10\n"
        " set Displacement tolerance = 1e-10\nend\n"
        "subsection Output\n set Progress = false\n set VTU interval = 0\n"
        "end\n";
      Simulation            simulation(SceneReader::read_string(
        prm,
        label,
        own_output_directory("glancing_",
                             glance.scheme + "_" + glance.surface)));
      std::array<double, 2> p0          = {{0., 0.}};
      double                momentum    = 0.;
      bool                  first       = true;
      double                largest_gap = 0.;
      simulation.on_increment           = [&](unsigned int, double) {
        const std::array<double, 2>
          a = simulation.body("struck").inertia()->momentum(),
          b = simulation.body("striker").inertia()->momentum();
        if (first)
          p0 = {{a[0] + b[0], a[1] + b[1]}}, first = false;
        momentum =
          std::max(momentum,
                   std::hypot(a[0] + b[0] - p0[0], a[1] + b[1] - p0[1]));
        for (const auto &pair : simulation.contact().contact_pairs())
          for (const ContactNode &node : pair->nodes())
            if (node.active)
              largest_gap = std::max(largest_gap, -node.gap);
      };
      simulation.run();
      const EnergyAccount &account = *simulation.energies();

      const std::array<double, 2> p =
        simulation.body("struck").inertia()->momentum();
      const double       mass_speed = std::hypot(p0[0], p0[1]);
      const Tensor<1, 2> struck({p[0], p[1]});
      const double       along = struck * n / struck.norm();
      const double       angle = std::acos(std::min(1., along)) * 180. / M_PI;
      // The striker's momentum along n before the impact: the most the
      // struck disk can take (restitution 1 between equal masses).
      const double approach = mass_speed * std::abs(n[1]);
      std::cout << "  " << label << ": steps whose contact created energy "
                << account.contact_creating_steps << " ("
                << account.contact_created << "); contact's work "
                << account.contact_work << " of the energy " << account.initial
                << "; energy balance " << account.balance()
                << "; total momentum's change " << momentum << " of "
                << mass_speed << "; the struck disk's momentum "
                << struck.norm() << " = (" << p[0] << ", " << p[1]
                << ") (at most " << approach << "), " << angle
                << " degrees from the line of centres at the impact"
                << "; deepest slave node " << largest_gap << std::endl;
      check(struck.norm() > 0.2 * approach, label + ": the disks hardly met");
      check(account.contact_creating_steps == 0,
            label + ": the contact created energy");
      check(account.contact_work <= 0., label + ": the contact's work is > 0");
      check(momentum <= 1e-10 * mass_speed,
            label + ": the total momentum changed");
      check(struck.norm() <= approach * (1. + 1e-3),
            label + ": the struck disk left faster than restitution 1 allows");
      check(angle <= 2.,
            label + ": the impulse is not along the line of centres");
    }
}
