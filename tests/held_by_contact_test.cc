// Bodies held by contact (issue 17): a body whose supports leave rigid
// motions free is regularised by springs that the contact problem takes
// out again exactly (theory.md, section 4.6). Each test checks what such a
// body must satisfy against a reference that does not come from the code:
// Lame's closed form, force balance, path independence of a sticking
// contact, and a run that reaches its load.

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <cmath>

#include "case3_rings_reference.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{

  /** Sum of the normal reactions of a pair's slave nodes. */
  double
  total_normal_reaction(const Simulation &simulation)
  {
    double sum = 0.;
    for (const auto &node : const_cast<Simulation &>(simulation)
                              .contact()
                              .contact_pairs()[0]
                              ->nodes())
      sum += node.reaction[1];
    return sum;
  }
} // namespace

// Case 3's rings, stage 1, with the outer ring held as the peers hold it:
// one tangential support at (2, 0), its other motions (x and the rotation
// about that point) held by frictionless contact with the inner ring. The
// answer must be the four-support run's (the supports carry nothing, the
// field is axisymmetric), and both must be Lame's ring a = 0.5, b = 2
// clamped at r = a under p = 400 / (2 pi b), within the discretisation
// error.
namespace
{
  /** The check of held_by_contact_rings_one_support_lame on rings of the
   *  space and surface that `settings` set. */
  void
  one_support_against_four(const std::vector<std::string> &settings,
                           const std::string              &label)
  {
    const auto run = [&](const std::string &fixed) {
      std::vector<std::string> overrides = {
        "Load program/Stage end times=1",
        "Load program/Stage increments=10",
        "Output/Progress=false",
        "Output/Directory=held_rings",
      };
      overrides.insert(overrides.end(), settings.begin(), settings.end());
      if (!fixed.empty())
        overrides.push_back("Body outer/Boundary conditions/Fixed=" + fixed);
      auto simulation = std::make_unique<Simulation>(
        SceneReader::read_file(source_path("prm/case3_rings.prm"), overrides));
      for (unsigned int k = 1; k <= 10; ++k)
        simulation->advance_to(0.1 * k, "increment");
      return simulation;
    };
    const auto four = run("");
    const auto one  = run("point(2, 0): y");

    // Lame (case3_rings_reference.h).
    const LameRings lame(1e4);
    const double    b = 2., c = 1.25;
    const double    u_b_lame    = lame.u_outer,
                 interface_lame = lame.interface_pressure;
    const double u_four = mean_radial_displacement(four->body("outer"), b);
    const double u_one  = mean_radial_displacement(one->body("outer"), b);
    const double p_four = total_normal_reaction(*four) / (2. * M_PI * c);
    const double p_one  = total_normal_reaction(*one) / (2. * M_PI * c);
    const double four_error_u =
      std::abs(u_four - u_b_lame) / std::abs(u_b_lame);
    const double four_error_p =
      std::abs(p_four - interface_lame) / interface_lame;
    std::cout << "  " << label << ", four supports: u_r(2) " << u_four
              << ", interface pressure " << p_four << " (Lame " << u_b_lame
              << ", " << interface_lame << "; deviations " << four_error_u
              << ", " << four_error_p << ")" << std::endl;
    check_relative(u_one,
                   u_b_lame,
                   1.01 * four_error_u + 1e-9,
                   "u_r(2), one support, against Lame");
    check_relative(p_one,
                   interface_lame,
                   1.01 * four_error_p + 1e-9,
                   "interface pressure, one support, against Lame");
    check_relative(u_one, u_four, 1e-8, "u_r(2), one support against four");

    // The support carries nothing but round-off of the 400 applied.
    const Tensor<1, 2> reaction =
      support_reaction(one->body("outer"), "point(2, 0)");
    std::cout << "  reaction of the one support: " << reaction[1] << std::endl;
    check(std::abs(reaction[1]) <= 1e-10 * 400.,
          "the support's reaction is zero");
  }
} // namespace

GLISSADE_TEST(held_by_contact_rings_one_support_lame)
{
  one_support_against_four({"Contact interface/Surface=bspline"},
                           "Q1 rings, B-spline master");
}

// The same with both rings NURBS (mortar on the inner ring's exact
// boundary): the springs that hold a body of control points sit on
// control points of its contact boundary. (The 400 N as the uniform
// pressure Lame has, rather than 10 N on each of 40 nodes, which a NURBS
// boundary of 44 control points does not have.)
GLISSADE_TEST(held_by_contact_nurbs_rings_one_support_lame)
{
  one_support_against_four(
    {"Body inner/Element/Space=nurbs",
     "Body outer/Element/Space=nurbs",
     "Contact interface/Surface=nurbs",
     "Contact interface/Discretisation=mortar",
     "Body outer/Boundary conditions/Nodal loads=",
     "Body outer/Boundary conditions/Pressure=outer: 400/(4*pi)*min(t, 1)"},
    "NURBS rings, mortar");
}



namespace
{
  /**
   * Three blocks of the same width and material stacked: `base` on a
   * roller, `puck` held by nothing but the two frictional contacts, and
   * `press` pushed down; a sideways load on the puck.
   */
  std::string
  squeezed_puck(const unsigned int increments)
  {
    const auto block = [](const std::string &name,
                          const std::string &y0,
                          const std::string &y1,
                          const std::string &supports) {
      return "subsection Body " + name +
             "\n subsection Mesh\n  set Type = rectangle\n  set Corner 1 = 0, " +
             y0 + "\n  set Corner 2 = 2, " + y1 +
             "\n  set Subdivisions = 8, 2\n end\n"
             " subsection Material\n  set Young modulus = 1000\n end\n"
             " subsection Boundary conditions\n" +
             supports + " end\nend\n";
    };
    const auto pair = [](const std::string &name,
                         const std::string &master,
                         const std::string &slave_side,
                         const std::string &master_side) {
      return "subsection Contact " + name +
             "\n set Slave body = puck\n"
             " set Slave boundary = " +
             slave_side + "\n set Master body = " + master +
             "\n set Master boundary = " + master_side +
             "\n set Alert distance = 0.1\n set Friction coefficient = 0.5\n"
             " set Tolerance = 1e-13\nend\n";
    };
    return "subsection Scene\n set Bodies = base, puck, press\n"
           " set Contact pairs = lower, upper\nend\n" +
           block("base",
                 "0",
                 "0.5",
                 "  set Fixed = bottom: y; point(1, 0): x\n") +
           block("puck",
                 "0.5",
                 "1",
                 "  set Point loads = point(2, 0.75): 0.3*t, 0\n") +
           block("press",
                 "1",
                 "1.5",
                 "  set Fixed = point(1, 1.5): x\n"
                 "  set Prescribed displacement = top: y: -0.02*t\n") +
           pair("lower", "base", "bottom", "top") +
           pair("upper", "press", "top", "bottom") +
           "subsection Load program\n set Stage end times = 1\n"
           " set Stage increments = " +
           std::to_string(increments) +
           "\nend\nsubsection Newton\n set Residual tolerance = 1e-12\n"
           " set Displacement tolerance = 1e-11\nend\n"
           "subsection Output\n set Progress = false\n"
           " set Directory = held_puck\nend\n";
  }
} // namespace

// A block with no Dirichlet data between two supported blocks, held by
// Coulomb friction against a sideways load: its equilibrium (the two
// contact forces and the load) to round-off, every node sticking, and its
// position the same whatever the number of increments (a sticking contact
// has no history).
GLISSADE_TEST(held_by_contact_puck_squeezed_with_friction)
{
  std::array<Tensor<1, 2>, 2> position;
  for (const unsigned int increments : {2u, 8u})
    {
      Simulation simulation(
        SceneReader::read_string(squeezed_puck(increments), "puck"));
      for (unsigned int k = 1; k <= increments; ++k)
        simulation.advance_to(double(k) / increments, "increment");
      const auto        &pairs = simulation.contact().contact_pairs();
      const Tensor<1, 2> lower = pairs[0]->total_force();
      const Tensor<1, 2> upper = pairs[1]->total_force();
      const Tensor<1, 2> load({0.3, 0.});
      const Tensor<1, 2> balance = lower + upper + load;
      unsigned int       stuck = 0, closed = 0;
      for (const auto &pair : pairs)
        for (const auto &node : pair->nodes())
          if (node.active && node.reaction[1] > 0.)
            {
              ++closed;
              stuck += node.status == BiPotentialSolver::NodeStatus::stick;
            }
      position[increments == 8u] =
        vertex_displacement(simulation.body("puck"), Point<2>(1., 0.75));
      std::cout << "  " << increments << " increments: lower (" << lower
                << "), upper (" << upper << "), |balance| " << balance.norm()
                << "; " << stuck << " of " << closed
                << " closed nodes stick; puck centre moved ("
                << position[increments == 8u] << ")" << std::endl;
      check(lower[1] > 1., "the press squeezes the puck");
      check(balance.norm() <= 1e-10 * lower.norm(),
            "the puck is in equilibrium to round-off");
      check(closed == 18 && stuck == closed, "every node closed and sticking");
    }
  const double moved = (position[0] - position[1]).norm();
  std::cout << "  position difference 2 vs 8 increments: " << moved
            << std::endl;
  check(std::abs(position[1][0]) > 1e-5, "the load moves the puck sideways");
  check(moved <= 1e-8 * position[1].norm(),
        "the puck's position does not depend on the increments");
}



// Case: a rubber block (20 x 10, E = 5, nu = 0.45) pressed by its top onto
// a rigid flat with Coulomb friction mu = 0.3 (the top driven down, its
// middle node held in x). Past about 10 % compression its tangent alone is
// not positive definite (LU replaces Cholesky); the problem with the
// frictional contact is well posed, and the run must reach 50 % on both
// meshes with no increment cut back.
GLISSADE_TEST(held_by_contact_rubber_block_to_half_height)
{
  for (const std::string subdivisions : {"20, 10", "40, 20"})
    {
      const std::string prm =
        "subsection Scene\n set Bodies = block\n set Contact pairs = base\nend\n"
        "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
        "  set Corner 1 = -10, 0\n  set Corner 2 = 10, 10\n"
        "  set Subdivisions = " +
        subdivisions +
        "\n end\n"
        " subsection Material\n  set Young modulus = 5\n"
        "  set Poisson ratio = 0.45\n end\n"
        " subsection Boundary conditions\n"
        "  set Prescribed displacement = top: y: -5*t\n"
        "  set Fixed = point(0, 10): x\n end\nend\n"
        "subsection Contact base\n set Slave body = block\n"
        " set Slave boundary = bottom\n set Master body = rigid\n"
        " set Alert distance = 0.5\n set Friction coefficient = 0.3\n"
        " subsection Obstacle\n  set Type = line\n  set Point = 0, 0\n"
        "  set Normal = 0, 1\n end\nend\n"
        "subsection Load program\n set Maximum cut-back depth = 0\nend\n"
        "subsection Output\n set Progress = false\n"
        " set Directory = held_rubber\nend\n";
      Simulation simulation(SceneReader::read_string(prm, "rubber"));
      for (unsigned int k = 1; k <= 40; ++k)
        simulation.advance_to(k / 40., "increment " + std::to_string(k));
      const RunStatistics s = simulation.statistics();
      const Tensor<1, 2>  contact =
        simulation.contact().contact_pairs()[0]->total_force();
      const double top = support_reaction(simulation.body("block"), "top")[1];
      std::cout << "  mesh " << subdivisions << ": 50 % compression in 40 "
                << "increments, " << s.newton_iterations
                << " Newton iterations, " << s.cut_backs << " cut-backs; "
                << s.n_lu << " of " << s.n_cholesky + s.n_lu
                << " factorisations by LU (tangent not positive definite); "
                << "contact force " << contact[1] << ", top reaction " << top
                << std::endl;
      check(s.cut_backs == 0, "no increment cut back");
      check(s.n_lu > 0, "the tangent alone was indefinite at some increments");
      check(std::abs(contact[1] + top) <= 1e-9 * std::abs(top),
            "the contact force balances the top's reaction");
    }
}



// A ring held in y by nothing but two rigid plates pressing it from above
// and below (frictionless, each touching at its apex first): the springs
// that regularise its free translation are taken out by one rank-one
// term, whose Woodbury system S = 1 - k e^T C e is zero but for round-off
// (the tangent is singular in y). It must be seen as singular and the
// closed directions augmented (section 4.5): the answer is then the one
// supports at (+-0.7, 0) give, where the symmetric answer has no
// reaction, to 1e-10. (Judged by LAPACK's rcond alone, which a 1 x 1 S
// always passes, the translation was left to round-off: uy(0.7, 0) =
// 2^-17 for 0 and the plates' force 3.6e-4 off.)
GLISSADE_TEST(held_by_contact_ring_between_two_plates)
{
  // (the pinched ring's scene, tests/input/processes_pinched_ring.prm,
  // over its first two increments: its self-contact pair is open until
  // t = 0.87)
  const auto run = [](const std::string &fixed) {
    auto simulation = std::make_unique<Simulation>(SceneReader::read_file(
      source_path("tests/input/processes_pinched_ring.prm"),
      {"Body ring/Boundary conditions/Fixed=" + fixed,
       "Output/Progress=false",
       "Output/Directory=held_ring_between_two_plates"}));
    std::vector<double> figures;
    for (const double t : {0.0125, 0.025})
      {
        simulation->advance_to(t, "increment");
        const Tensor<1, 2> u =
          vertex_displacement(simulation->body("ring"), Point<2>(0.7, 0.));
        figures.push_back(
          simulation->contact().contact_pairs()[0]->total_force()[1]);
        figures.push_back(u[0]);
        figures.push_back(u[1]);
      }
    return figures;
  };
  const auto by_contact = run("point(0, 1): x; point(0, -1): x");
  const auto supported =
    run("point(0, 1): x; point(0, -1): x; point(0.7, 0): y; "
        "point(-0.7, 0): y");
  for (unsigned int k = 0; k < 2; ++k)
    {
      std::cout << "  increment " << k + 1 << ": plate force "
                << by_contact[3 * k] << " (supported " << supported[3 * k]
                << "), u(0.7, 0) = (" << by_contact[3 * k + 1] << ", "
                << by_contact[3 * k + 2] << ")" << std::endl;
      check_relative(by_contact[3 * k],
                     supported[3 * k],
                     1e-10,
                     "the plate's force against the supported ring's");
      check_relative(by_contact[3 * k + 1],
                     supported[3 * k + 1],
                     1e-10,
                     "ux(0.7, 0) against the supported ring's");
      check(std::abs(by_contact[3 * k + 2]) <= 1e-12,
            "uy(0.7, 0) is not 0: the ring's translation is left free");
    }
}
