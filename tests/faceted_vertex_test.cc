// The faceted master at a vertex (issue 22, doc/contact.md "The faceted
// master at a vertex"): what each Faceted vertex rule does where the
// normal of a faceted master jumps.

#include <glissade/contact/contact_pair.h>
#include <glissade/contact/step/contact_problem.h>
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
          const Point<2> x =
            node.reference_position + node.displacement(inner.displacement());
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
// and across it to the solver's tolerance (measured 1.8e-13 of the mean).
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

// The vertex's cone (Faceted vertex rule = vertex normal): a node on a
// vertex of a faceted master holds there while its reaction lies between
// the two facets' normals, widened by friction's angle, and leaves it
// along a facet otherwise. Case 3's rings with mu = 0.1, compressed and
// then turned through one element: every slave node starts on a master
// vertex (corner angle 2 pi / 40). Closed forms: at a vertex
// |r_t| <= tan(pi/40 + atan(mu)) r_n about the mean normal, at the bound
// when it leaves; on a facet |r_t| <= mu r_n about the facet's normal,
// = mu r_n while it slips. The nodes must use more than friction alone
// at the vertices before they slip (the cone is in play), and the turn
// must run without a cut-back (it stopped after six before the cone).
GLISSADE_TEST(faceted_vertex_cone_holds_then_releases)
{
  const double mu = 0.1;
  Simulation   simulation(SceneReader::read_file(
    source_path("prm/case3_rings.prm"),
    {"Contact interface/Faceted vertex rule=vertex normal",
       "Contact interface/Friction coefficient=0.1",
       "Load program/Stage end times=1, 1.05",
       "Load program/Stage increments=10, 50",
       "Output/Progress=false",
       "Output/VTU interval=0",
       "Output/History=",
       "Output/Directory=faceted_vertex_test/cone"}));
  const auto  &pair       = *simulation.contact().contact_pairs().at(0);
  const double cone_bound = std::tan(M_PI / 40. + std::atan(mu));
  double       largest_vertex_ratio = 0., worst_excess = 0.;
  unsigned int vertex_nodes_beyond_friction = 0, slipping_on_facets_at_end = 0;
  double       worst_facet_slip_error = 0.;
  simulation.on_increment = [&](const unsigned int increment, double) {
    for (const auto &node : pair.nodes())
      {
        if (!node.active || node.reaction[1] <= 0.)
          continue;
        const double ratio = std::abs(node.reaction[0]) / node.reaction[1];
        const double cone  = node.linearization.vertex_cone;
        if (cone > 0.)
          {
            largest_vertex_ratio = std::max(largest_vertex_ratio, ratio);
            worst_excess         = std::max(worst_excess, ratio - cone_bound);
            vertex_nodes_beyond_friction += ratio > 1.01 * mu;
          }
        else
          {
            worst_excess = std::max(worst_excess, ratio - mu);
            if (increment == 60 &&
                node.status == BiPotentialSolver::NodeStatus::slip)
              {
                ++slipping_on_facets_at_end;
                worst_facet_slip_error =
                  std::max(worst_facet_slip_error, std::abs(ratio - mu));
              }
          }
      }
  };
  simulation.run();
  const auto &statistics = simulation.statistics();
  std::cout << "  cone bound tan(pi/40 + atan 0.1) = " << cone_bound
            << "; largest |r_t|/r_n at a vertex " << largest_vertex_ratio
            << " (" << vertex_nodes_beyond_friction
            << " node-increments beyond mu); worst excess over the bound "
            << worst_excess << "; " << slipping_on_facets_at_end
            << " nodes slipping on facets at the end, | |r_t|/r_n - mu | <= "
            << worst_facet_slip_error << "; " << statistics.cut_backs
            << " cut-backs, " << statistics.newton_iterations
            << " Newton iterations" << std::endl;
  check(worst_excess <= 1e-10, "a reaction left its cone");
  check(vertex_nodes_beyond_friction > 0,
        "no vertex carried more than friction alone: the cone was not used");
  check(slipping_on_facets_at_end == 40 && worst_facet_slip_error <= 1e-10,
        "the nodes do not all slide on facets at mu at the end of the turn");
  check(statistics.cut_backs == 0, "the turn needed cut-backs");
}
