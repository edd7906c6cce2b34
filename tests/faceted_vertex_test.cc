// The faceted master at a vertex (issue 22, doc/contact.md "The faceted
// master at a vertex"): what each Faceted vertex rule does where the
// normal of a faceted master jumps.

#include <glissade/contact/contact_pair.h>
#include <glissade/contact/contact_problem.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>

#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /**
   * Case 3's rings (40 x 4 each, every slave node on a master vertex),
   * both turned rigidly: the outer ring's outer edge is shrunk by 0.2 %
   * over the first stage and then turned with the inner ring's inner
   * edge through two elements (18 degrees, 20 increments: a node passes
   * the odd multiples of half an element, 4.5 and 13.5 degrees, exactly).
   * The exact solution is the compressed state turned rigidly, so every
   * slave node keeps its contact force's norm, and the force turns with
   * the rings. Returns the largest change of a force against its value at
   * the end of the compression, relative to the mean force, over the turn.
   */
  double
  rigid_turn_force_change(const std::string &rule)
  {
    const std::string angle = "(pi/10)*max(t - 1, 0)";
    const std::string c     = "(1 - 0.002*min(t, 1))";
    const std::string ux =
      c + "*(cos(" + angle + ")*x - sin(" + angle + ")*y) - x";
    const std::string uy =
      c + "*(sin(" + angle + ")*x + cos(" + angle + ")*y) - y";
    Simulation  simulation(SceneReader::read_file(
      source_path("prm/case3_rings.prm"),
      {"Body inner/Boundary conditions/Prescribed rotation=inner: 0, 0: " +
          angle,
        "Body outer/Boundary conditions/Fixed=",
        "Body outer/Boundary conditions/Nodal loads=",
        "Body outer/Boundary conditions/Prescribed displacement=outer: xy: " +
          ux + ", " + uy,
        "Contact interface/Faceted vertex rule=" + rule,
        "Load program/Stage increments=10, 20",
        "Output/Progress=false",
        "Output/VTU interval=0",
        "Output/History=",
        "Output/Directory=faceted_vertex_test/" + rule}));
    const auto &pair  = *simulation.contact().contact_pairs().at(0);
    const Body &inner = pair.slave();
    // Per slave node, its force's components on the radius and across it
    // at the node's current position: the same in the turning frame.
    std::vector<Tensor<1, 2>> compressed;
    double                    largest_change = 0.;
    simulation.on_increment = [&](const unsigned int increment, double) {
      std::vector<Tensor<1, 2>> forces;
      for (const auto &node : pair.nodes())
        {
          const Point<2> x = node.reference_position +
                             Tensor<1, 2>({inner.displacement()(node.dofs[0]),
                                           inner.displacement()(node.dofs[1])});
          const Tensor<1, 2> radial = x / x.norm();
          const Tensor<1, 2> across({-radial[1], radial[0]});
          const Tensor<1, 2> f = node.active ? node.force() : Tensor<1, 2>();
          forces.push_back(Tensor<1, 2>({f * radial, f * across}));
        }
      if (increment == 10)
        compressed = forces;
      if (increment <= 10)
        return;
      double mean = 0.;
      for (const auto &f : compressed)
        mean += f.norm() / compressed.size();
      for (unsigned int k = 0; k < forces.size(); ++k)
        largest_change =
          std::max(largest_change, (forces[k] - compressed[k]).norm() / mean);
    };
    simulation.run();
    std::cout << "  " << rule << ": largest change of a contact force over "
              << "the rigid turn " << 100. * largest_change << " % of the mean"
              << std::endl;
    return largest_change;
  }
} // namespace

// Objectivity: a rigid turn of the two rings must not change the contact
// forces seen from the turning rings (closed form: the compressed state
// turned). Every slave node sits on a master vertex throughout. The rule
// vertex normal meets it with the vertex's mean normal, the same at every
// angle and increment, so the forces keep their components on the radius
// and across it to the solver's tolerance (measured 1.5e-13 of the mean).
// The two other rules pick one of the two facets: the force, tilted by
// half the corner's angle, pushes the node a little past the vertex onto
// the other facet's side, so the next increment picks the other facet and
// the tilt flips from one increment to the next (measured: 16.2 % of the
// mean, 2 sin(pi/40) = 15.7 % of a force turned by twice pi/40). That is
// bounded by the facets' geometry, which is asserted too.
GLISSADE_TEST(faceted_vertex_rule_rigid_turn)
{
  check(rigid_turn_force_change("vertex normal") < 1e-8,
        "vertex normal: a rigid turn changed the contact forces");
  for (const std::string rule : {"kept segment", "closest point"})
    check(rigid_turn_force_change(rule) < 1.05 * 2. * std::sin(M_PI / 40.),
          rule + ": a rigid turn changed the forces beyond the facets' tilt");
}
