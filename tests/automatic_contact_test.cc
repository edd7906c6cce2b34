// Automatic contact among bodies (Scene/Contact bodies, issue 53): the
// pairs it makes are those a user would write, and the contact they carry
// obeys the balance laws and the symmetry of the scene.

#include <glissade/base/input_error.h>
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
    return own_output_directory("automatic_contact_", label);
  }

  /**
   * Two identical annuli (r in [0.1, 1], centres at x = -/+1.01), the left
   * one's inner edge held, the right one's pushed left by 0.06 t: their
   * outer edges press together over an arc. `contact` is what the scene
   * says of contact (the Scene entry and the sections).
   */
  std::string
  two_rings(const std::string &scene_contact, const std::string &sections)
  {
    std::string prm =
      "subsection Scene\n set Bodies = left, right\n" + scene_contact + "end\n";
    for (const auto &[name, x, support] :
         {std::tuple<std::string, std::string, std::string>{
            "left", "-1.01", "Fixed = inner: xy"},
          {"right", "1.01", "Prescribed displacement = inner: xy: -0.06*t, 0"}})
      prm += "subsection Body " + name +
             "\n subsection Mesh\n  set Type = ring\n  set Center = " + x +
             ", 0\n  set Inner radius = 0.1\n  set Outer radius = 1\n"
             "  set Subdivisions = 48, 6\n end\n"
             " subsection Material\n  set Young modulus = 1000\n"
             "  set Poisson ratio = 0.3\n end\n"
             " subsection Boundary conditions\n  set " +
             support + "\n end\nend\n";
    return prm + sections +
           "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-10\n"
           " set Displacement tolerance = 1e-10\nend\n"
           "subsection Output\n set Progress = false\nend\n";
  }

  const std::string settings = " set Surface = bspline\n"
                               " set Alert distance = 0.05\n";

  std::string
  hand_pair(const std::string &slave, const std::string &master)
  {
    return "subsection Contact " + slave + " on " + master +
           "\n set Slave body = " + slave + "\n set Slave boundary = outer\n" +
           " set Master body = " + master + "\n set Master boundary = outer\n" +
           settings + "end\n";
  }

  std::unique_ptr<Simulation>
  solved(const std::string &prm, const std::string &label)
  {
    auto simulation = std::make_unique<Simulation>(
      SceneReader::read_string(prm, label, own_directory(label)));
    for (unsigned int k = 1; k <= 4; ++k)
      simulation->advance_to(k / 4., "increment " + std::to_string(k));
    return simulation;
  }


  /** The largest difference of two bodies' contact force vectors. */
  double
  largest_difference(const Body &a, const Body &b)
  {
    Vector<double> d = a.get_contact_forces();
    d -= b.get_contact_forces();
    return d.linfty_norm();
  }
} // namespace

// The pairs found by automatic contact, in one pass and in two, carry the
// same forces as the same pairs written by hand; the forces on the two
// rings are equal and opposite and, the scene being symmetric about y = 0,
// have no y component; no slave node ends behind its master.
GLISSADE_TEST(automatic_contact_equals_pairs_written)
{
  for (const std::string passes : {"one", "two"})
    {
      const std::string by_hand =
        passes == "one" ?
          hand_pair("left", "right") :
          hand_pair("left", "right") + hand_pair("right", "left");
      const std::string names =
        passes == "one" ? "left on right" : "left on right, right on left";
      const auto written =
        solved(two_rings(" set Contact pairs = " + names + "\n", by_hand),
               "pairs written, " + passes + " pass");
      const auto found =
        solved(two_rings(" set Contact bodies = left: outer, right: outer\n",
                         "subsection Automatic contact\n set Passes = " +
                           passes + "\n" + settings + "end\n"),
               "automatic contact, " + passes + " pass");

      const auto &pairs = found->contact().contact_pairs();
      check(pairs.size() == (passes == "one" ? 1u : 2u),
            passes + ": " + std::to_string(pairs.size()) + " pairs made");
      const Tensor<1, 2> on_left =
        resultant(found->body("left"),
                  found->body("left").get_contact_forces());
      const Tensor<1, 2> on_right =
        resultant(found->body("right"),
                  found->body("right").get_contact_forces());
      const double scale = on_left.norm();
      const double difference =
        std::max(largest_difference(found->body("left"), written->body("left")),
                 largest_difference(found->body("right"),
                                    written->body("right")));
      std::cout << "  " << passes << " pass: force on the left ring ("
                << on_left << "), on the right (" << on_right
                << "); largest difference from the pairs written " << difference
                << std::endl;
      check(scale > 1., passes + ": the rings do not press on each other");
      check(difference <= 1e-10 * scale,
            passes + ": automatic contact differs from the pairs written");
      check((on_left + on_right).norm() <= 1e-10 * scale,
            passes + ": action != reaction");
      check(std::abs(on_left[1]) <= 1e-8 * scale,
            passes + ": a y force in a scene symmetric about y = 0");
      double deepest = 0.;
      for (const auto &pair : pairs)
        for (const auto &node : pair->nodes())
          if (node.projected)
            deepest = std::min(deepest, node.gap);
      std::cout << "  deepest gap " << deepest << std::endl;
      check(deepest >= -1e-8, passes + ": a slave node behind its master");
    }
}

// What Contact bodies refuses, each with a message naming the entry.
GLISSADE_TEST(automatic_contact_input_errors)
{
  const auto refusal = [](const std::string &scene_contact,
                          const std::string &sections) -> std::string {
    try
      {
        Simulation simulation(
          SceneReader::read_string(two_rings(scene_contact, sections),
                                   "scene.prm",
                                   own_directory("refused")));
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "accepted";
  };
  for (const auto &[listed, sections, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
         {"left: outer, left: inner", "", "body 'left' is listed twice"},
         {"left: outer, middle: outer", "", "there is no body 'middle'"},
         {"left: outer", "", "lists one body ('left')"},
         {"left, right: outer", "", "'left' is not 'body: boundary'"},
         {"left: outer inner, right: outer", "", "several joined by '+'"},
         {"left: outer, right: outer\n set Contact pairs = left on right",
          hand_pair("left", "right"),
          "makes the pair 'left on right', which Scene/Contact pairs names"},
         {"left: outr, right: outer", "", "no boundary named 'outr'"}})
    {
      const std::string message =
        refusal(" set Contact bodies = " + listed + "\n",
                sections + "subsection Automatic contact\n" + settings +
                  "end\n");
      std::cout << "  " << listed.substr(0, listed.find('\n')) << ": "
                << message << std::endl;
      check(message.find(expected) != std::string::npos &&
              (message.find("Contact bodies") != std::string::npos ||
               message.find("Automatic contact") != std::string::npos),
            "'" + listed + "': expected '" + expected + "'");
    }
}

// Scene/Contact bodies set from the command line (--set), as any entry:
// the first pass over the scene, which reads the bodies' and pairs' names
// alone, took every Scene/ override and refused this one as undeclared.
// The override replaces the file's list, and a wrong one is refused with
// the entry named, as in the file.
GLISSADE_TEST(automatic_contact_listed_from_the_command_line)
{
  const std::string      scene = source_path("prm/rings_in_a_row.prm");
  const SceneDescription listed =
    SceneReader::read_file(scene,
                           {"Scene/Contact bodies=left: outer, middle: outer"});
  std::string sides;
  for (const auto &side : listed.automatic_contact.sides)
    sides += (sides.empty() ? "" : ", ") + side.body + ": " + side.boundary;
  std::cout << "  overridden: " << sides << std::endl;
  check(sides == "left: outer, middle: outer",
        "the override did not replace the file's list");
  std::string refused = "accepted";
  try
    {
      SceneReader::read_file(scene,
                             {"Scene/Contact bodies=left: outer, left: inner"});
    }
  catch (const InputError &e)
    {
      refused = e.what();
    }
  std::cout << "  refused: " << refused << std::endl;
  check(refused.find("Contact bodies") != std::string::npos &&
          refused.find("listed twice") != std::string::npos,
        "a wrong override is not refused with its entry named");
}
