// Automatic contact's broad phase (issue 53): the pairs of a couple of
// bodies are made when the bodies come within reach, never for a couple
// that stays apart, and what they carry is what the same pairs written by
// hand carry, quasi-static and under both dynamic schemes.

#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "body_resultant.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /** An output directory of the run's own (own_output_directory). */
  std::vector<std::string>
  own_directory(const std::string &label)
  {
    return own_output_directory("automatic_reach_", label);
  }

  const std::string settings = " set Surface = bspline\n"
                               " set Alert distance = 0.05\n";

  /** A pair written by hand, with automatic contact's settings. */
  std::string
  hand_pair(const std::string &slave, const std::string &master)
  {
    return "subsection Contact " + slave + " on " + master +
           "\n set Slave body = " + slave + "\n set Slave boundary = outer\n" +
           " set Master body = " + master + "\n set Master boundary = outer\n" +
           settings + "end\n";
  }

  /** An annulus r in [0.5, 1] of 32 x 3 Q4 at (x, 0), E = 1000. */
  std::string
  ring(const std::string &name, const double x, const std::string &rest)
  {
    return "subsection Body " + name +
           "\n subsection Mesh\n  set Type = ring\n  set Center = " +
           std::to_string(x) +
           ", 0\n  set Inner radius = 0.5\n  set Outer radius = 1\n"
           "  set Subdivisions = 32, 3\n end\n"
           " subsection Material\n  set Young modulus = 1000\n"
           "  set Poisson ratio = 0.3\n  set Density = 1\n end\n" +
           rest + "end\n";
  }

  /**
   * `contact` is "hand" (the four pairs of the two touching couples
   * written) or "automatic" (Contact bodies = the three rings).
   */
  std::string
  with_contact(const std::string              &contact,
               const std::vector<std::string> &bodies)
  {
    if (contact == "automatic")
      {
        std::string listed;
        for (const auto &b : bodies)
          listed += (listed.empty() ? "" : ", ") + b + ": outer";
        return " set Contact bodies = " + listed + "\nend\n" +
               "subsection Automatic contact\n" + settings + "end\n";
      }
    std::string names, sections;
    for (unsigned int i = 0; i + 1 < bodies.size(); ++i)
      for (const auto &[s, m] : {std::make_pair(bodies[i], bodies[i + 1]),
                                 std::make_pair(bodies[i + 1], bodies[i])})
        {
          names += (names.empty() ? "" : ", ") + s + " on " + m;
          sections += hand_pair(s, m);
        }
    return " set Contact pairs = " + names + "\nend\n" + sections;
  }

  const std::string tolerances =
    "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
    "subsection Newton\n set Residual tolerance = 1e-10\n"
    " set Displacement tolerance = 1e-10\nend\n"
    "subsection Output\n set Progress = false\n set VTU interval = 0\nend\n";

  /**
   * Three rings in a row, 0.5 apart (beyond reach: a face is 0.196, the
   * alert distance 0.05), the middle one held at its inner edge, the outer
   * two pushed onto it by 0.6 t: they close at t = 5/6 and end 0.1 into
   * it. The left and right rings stay 3 apart.
   */
  std::string
  three_rings(const std::string &contact, const unsigned int increments)
  {
    return "subsection Scene\n set Bodies = left, middle, right\n" +
           with_contact(contact, {"left", "middle", "right"}) +
           ring("left",
                -2.5,
                " subsection Boundary conditions\n  set Prescribed "
                "displacement = inner: xy: 0.6*t, 0\n end\n") +
           ring("middle",
                0.,
                " subsection Boundary conditions\n  set Fixed "
                "= inner: xy\n end\n") +
           ring("right",
                2.5,
                " subsection Boundary conditions\n  set Prescribed "
                "displacement = inner: xy: -0.6*t, 0\n end\n") +
           "subsection Load program\n set Stage end times = 1\n"
           " set Stage increments = " +
           std::to_string(increments) + "\nend\n" + tolerances;
  }

  /** The largest difference of two bodies' contact force vectors. */
  double
  largest_difference(const Body &a, const Body &b)
  {
    Vector<double> d = a.get_contact_forces();
    d -= b.get_contact_forces();
    return d.linfty_norm();
  }

  std::vector<std::string>
  pair_names(Simulation &simulation)
  {
    std::vector<std::string> names;
    for (const auto &pair : simulation.contact().contact_pairs())
      names.push_back(pair->name());
    return names;
  }
} // namespace

// Three rings pushed together: no pair at the start (every couple beyond
// reach), the four pairs of the two touching couples at the end and none of
// the couple that stays apart; the forces those of the pairs written, to
// 1e-10, in four increments (the couples come within reach at a step's
// detection) and in one (within reach only once Newton has taken the outer
// rings into the middle one: the pairs are made mid-step); each couple's
// forces equal and opposite, no slave node behind its master.
GLISSADE_TEST(automatic_contact_pairs_made_within_reach)
{
  for (const unsigned int increments : {4u, 1u})
    {
      const std::string label = std::to_string(increments) + " increments";
      Simulation        written(
        SceneReader::read_string(three_rings("hand", increments),
                                 label,
                                 own_directory("hand " + label)));
      Simulation found(
        SceneReader::read_string(three_rings("automatic", increments),
                                 label,
                                 own_directory("automatic " + label)));
      check(found.contact().contact_pairs().empty(),
            label + ": pairs made at the start, with every couple apart");
      written.run();
      found.run();

      const std::vector<std::string> names = pair_names(found);
      std::cout << "  " << label << ": pairs made";
      for (const auto &name : names)
        std::cout << " '" << name << "'";
      std::cout << std::endl;
      check(names.size() == 4, label + ": four pairs expected");
      for (const auto &name : names)
        check(name.find("left") == std::string::npos ||
                name.find("right") == std::string::npos,
              label + ": a pair of the couple that stays apart, " + name);

      double difference = 0., scale = 0.;
      for (const std::string b : {"left", "middle", "right"})
        {
          difference =
            std::max(difference,
                     largest_difference(found.body(b), written.body(b)));
          scale =
            std::max(scale, found.body(b).get_contact_forces().linfty_norm());
        }
      const Tensor<1, 2> on_left =
        resultant(found.body("left"), found.body("left").get_contact_forces());
      const Tensor<1, 2> on_middle =
        resultant(found.body("middle"),
                  found.body("middle").get_contact_forces());
      const Tensor<1, 2> on_right =
        resultant(found.body("right"),
                  found.body("right").get_contact_forces());
      double deepest = 0.;
      for (const auto &pair : found.contact().contact_pairs())
        for (const auto &node : pair->nodes())
          if (node.projected)
            deepest = std::min(deepest, node.gap);
      std::cout << "  forces on left " << on_left << ", middle " << on_middle
                << ", right " << on_right
                << "; largest difference from the pairs written " << difference
                << " (largest nodal force " << scale << "); deepest gap "
                << deepest << std::endl;
      check(on_left.norm() > 1., label + ": the rings do not touch");
      check(difference <= 1e-10 * scale,
            label + ": automatic contact differs from the pairs written");
      check((on_left + on_middle + on_right).norm() <= 1e-10 * on_left.norm(),
            label + ": the contact forces do not balance");
      check(std::abs(on_left[0] + on_right[0]) <= 1e-8 * on_left.norm(),
            label + ": the scene's symmetry about x = 0 is broken");
      check(deepest >= -1e-8, label + ": a slave node behind its master");
    }
}

// Two rings thrown at each other from beyond reach (0.6 apart, each at 0.5)
// under Newmark and Moreau-Jean (the contact nodes' mass kept: its law on
// the end velocities): automatic contact gives the pairs written
// by hand their figures at every step (1e-10 of the largest), the total
// momentum stays zero, and the contact never does positive work on the
// bodies in a step (EnergyAccount's count of such steps, 1e-8 of the
// energies at stake); the rings part again, each with no more momentum than
// it came with.
GLISSADE_TEST(automatic_contact_dynamic_impact)
{
  for (const std::string scheme : {"newmark", "moreau-jean"})
    {
      std::vector<std::vector<double>> histories[2];
      unsigned int                     creating[2] = {0, 0};
      std::size_t                      made[2]     = {0, 0};
      double momentum = 0., speed = 0., speed_before = 0.;
      for (const int automatic : {0, 1})
        {
          const std::string prm =
            "subsection Scene\n set Bodies = left, right\n" +
            with_contact(automatic ? "automatic" : "hand", {"left", "right"}) +
            ring("left", -1.3, " set Initial velocity = 0.5, 0\n") +
            ring("right", 1.3, " set Initial velocity = -0.5, 0\n") +
            "subsection Time integration\n set Scheme = " + scheme +
            // (Moreau-Jean with the mass kept: Jean's law on the end
            // velocities, the start gaps of the detection)
            (scheme == "moreau-jean" ? "\n set Contact mass = kept" : "") +
            "\nend\n"
            "subsection Load program\n set Stage end times = 1.2\n"
            " set Stage increments = 120\nend\n" +
            tolerances;
          Simulation simulation(SceneReader::read_string(
            prm,
            scheme + " impact",
            own_directory(scheme + std::to_string(automatic))));
          simulation.on_increment = [&](unsigned int, double) {
            const Body &left  = simulation.body("left"),
                       &right = simulation.body("right");
            if (speed_before == 0.)
              speed_before = left.inertia()->momentum()[0];
            const std::array<double, 2> a = left.inertia()->momentum(),
                                        b = right.inertia()->momentum();
            momentum = std::max(momentum, std::hypot(a[0] + b[0], a[1] + b[1]));
            std::vector<double> row;
            for (const Body *b : {&left, &right})
              for (const double f : b->get_contact_forces())
                row.push_back(f);
            histories[automatic].push_back(row);
          };
          simulation.run();
          creating[automatic] = simulation.energies()->contact_creating_steps;
          made[automatic]     = simulation.contact().contact_pairs().size();
          if (automatic)
            speed = simulation.body("left").inertia()->momentum()[0];
        }
      double difference = 0., scale = 0.;
      for (std::size_t k = 0; k < histories[0].size(); ++k)
        for (std::size_t i = 0; i < histories[0][k].size(); ++i)
          {
            difference =
              std::max(difference,
                       std::abs(histories[0][k][i] - histories[1][k][i]));
            scale = std::max(scale, std::abs(histories[0][k][i]));
          }
      std::cout << "  " << scheme << ": " << made[1]
                << " pairs made; largest contact force difference "
                << difference << " of " << scale << "; largest |momentum| "
                << momentum << "; steps whose contact created energy "
                << creating[1] << " (written: " << creating[0]
                << "); the left ring's momentum before the impact "
                << speed_before << ", at the end " << speed << std::endl;
      check(histories[0].size() == histories[1].size(),
            scheme + ": not as many steps");
      check(scale > 0., scheme + ": the rings never touched");
      check(difference <= 1e-10 * scale,
            scheme + ": automatic contact differs from the pairs written");
      check(momentum <= 1e-10, scheme + ": the total momentum is not zero");
      check(creating[1] == 0, scheme + ": the contact created energy");
      // The rings' rigid motion cannot take more than the energy there was:
      // |p| after <= |p| before (the rest rings on in the rings).
      check(speed < 0. && -speed <= speed_before * (1. + 1e-10),
            scheme + ": the left ring did not rebound, or faster than it came");
    }
}
