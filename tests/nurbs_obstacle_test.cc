// Rigid obstacles bounded by NURBS curves (Obstacle/Type = nurbs curve,
// issue 52): a circle written as a NURBS curve is exactly the analytic
// hole and disk (the same answers to round-off, knot-to-segment and
// mortar, a moving and turning disk with friction), and a curve file that
// is wrong is refused with the file and what is wrong; a block pushed off
// the end of an open curve runs through. The tangents on a wavy NURBS floor
// are in contact_tangent_test.cc.

#include <glissade/body/body_measures.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "nurbs_scene.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;

namespace
{
  /**
   * The circle of radius r about c as a NURBS curve file (four rational
   * quadratic quarters, weights 1 and cos 45 degrees), counterclockwise
   * (a hole: the obstacle outside, on the curve's right) or clockwise (a
   * disk); its path.
   */
  std::string
  circle_file(const Point<2> &c, const double r, const bool clockwise)
  {
    const double       h = std::sqrt(0.5);
    std::ostringstream text;
    text.precision(17);
    text << "degree 2\nknots 0 0 0 1 1 2 2 3 3 4 4 4\ncontrol points 9\n";
    for (unsigned int k = 0; k <= 8; ++k)
      {
        const double angle = (clockwise ? -1. : 1.) * k * M_PI / 4.;
        const double reach = k % 2 == 0 ? r : r / h;
        text << c[0] + reach * std::cos(angle) << " "
             << c[1] + reach * std::sin(angle) << " " << (k % 2 == 0 ? 1. : h)
             << "\n";
      }
    std::filesystem::create_directories("output/nurbs_obstacle");
    const std::string path = "output/nurbs_obstacle/circle_" +
                             std::string(clockwise ? "cw" : "ccw") + ".nurbs";
    std::ofstream(path) << text.str();
    return std::filesystem::absolute(path).string();
  }

  /** The obstacle's entries: the analytic circle or its NURBS curve. */
  std::string
  obstacle(const std::string &kind,
           const Point<2>    &c,
           const double       r,
           const std::string &motion)
  {
    std::ostringstream text;
    text.precision(17);
    text << " subsection Obstacle\n  set Point = " << c[0] << ", " << c[1]
         << "\n"
         << motion;
    if (kind == "nurbs curve")
      text << "  set Type = nurbs curve\n  set Curve file = "
           << circle_file(c, r, false) << "\n";
    else if (kind == "nurbs curve disk")
      text << "  set Type = nurbs curve\n  set Curve file = "
           << circle_file(c, r, true) << "\n";
    else
      text << "  set Type = " << kind << "\n  set Radius = " << r << "\n";
    text << " end\n";
    return text.str();
  }

  std::string
  common_settings(const std::string &directory)
  {
    return "subsection Contact solver\n set Tolerance = 1e-13\nend\n"
           "subsection Output\n set Progress = false\n set Plots = false\n"
           " set VTU interval = 0\n set Directory = output/" +
           directory +
           "\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-11\n"
           " set Displacement tolerance = 1e-11\nend\n";
  }


  /** The pair's contact force on the slave, summed over its points. */
  Tensor<1, 2>
  contact_force(Simulation &simulation)
  {
    Tensor<1, 2> force;
    for (const auto &node : simulation.contact().contact_pairs()[0]->nodes())
      if (node.active)
        force += node.force();
    return force;
  }
} // namespace



// A quarter ring 1 < r < 1.5 pressed into a rigid hole of radius 1.499
// (Lame's problem with u_r(1.5) = -1e-3): the hole as the analytic circle
// and as the NURBS curve of the same circle give the same displacement and
// contact force to round-off, for a Q1 ring (node-to-segment) and a NURBS
// ring (knot-to-segment and mortar); and a block pressed on a disk that
// moves and turns, with friction 0.3, the same forces and displacements.
GLISSADE_TEST(nurbs_curve_obstacle_is_the_circle)
{
  const Point<2> centre(0., 0.);
  for (const auto &[space, discretisation] :
       std::vector<std::pair<std::string, std::string>>{
         {"q1", "node-to-segment"},
         {"nurbs", "node-to-segment"},
         {"nurbs", "mortar"}})
    {
      std::vector<double> analytic;
      for (const std::string kind : {"hole", "nurbs curve"})
        {
          const std::string scene =
            "subsection Scene\n set Bodies = ring\n"
            " set Contact pairs = fit\nend\n"
            "subsection Body ring\n subsection Mesh\n"
            "  set Type = half ring\n  set Inner radius = 1\n"
            "  set Outer radius = 1.5\n  set Start angle = 0\n"
            "  set End angle = 90\n  set Subdivisions = 12, 4\n end\n"
            " subsection Element\n  set Space = " +
            space +
            "\n end\n subsection Material\n  set Young modulus = 1000\n"
            "  set Poisson ratio = 0.3\n  set Kinematics = small strain\n"
            " end\n subsection Boundary conditions\n"
            "  set Fixed = start: y; end: x\n end\nend\n"
            "subsection Contact fit\n set Slave body = ring\n"
            " set Slave boundary = outer\n set Discretisation = " +
            discretisation + "\n set Alert distance = 0.05\n" +
            obstacle(kind, centre, 1.499, "") + "end\n" +
            common_settings("nurbs_obstacle_hole");
          Simulation simulation(SceneReader::read_string(scene, "hole"));
          simulation.run();
          const Tensor<1, 2> force = contact_force(simulation);
          const double       u =
            vertex_displacement(simulation.body("ring"), Point<2>(1., 0.))[0];
          const std::vector<double> figures = {u, force[0], force[1]};
          std::cout << "  " << space << ", " << discretisation << ", " << kind
                    << ": u_r(1) " << u << ", contact force (" << force[0]
                    << ", " << force[1] << ")";
          if (analytic.empty())
            analytic = figures;
          else
            {
              const double difference = largest_difference(figures, analytic);
              std::cout << "; off the analytic hole's by " << difference;
              check(difference < 1e-10,
                    space + ", " + discretisation +
                      ": the NURBS circle is the hole");
            }
          std::cout << std::endl;
          check(u < -1e-4, "the ring is pressed in");
        }
    }

  // A Q1 block pressed on a disk that slides and turns under it.
  std::vector<double> analytic;
  for (const std::string kind : {"disk", "nurbs curve disk"})
    {
      const std::string scene =
        "subsection Scene\n set Bodies = block\n"
        " set Contact pairs = floor\nend\n"
        "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
        "  set Corner 1 = 0, 0.5\n  set Corner 2 = 1, 1\n"
        "  set Subdivisions = 8, 4\n end\n subsection Material\n"
        "  set Young modulus = 1000\n end\n"
        " subsection Boundary conditions\n"
        "  set Prescribed displacement = top: xy: 0, -0.02*t\n end\nend\n"
        "subsection Contact floor\n set Slave body = block\n"
        " set Slave boundary = bottom\n set Friction coefficient = 0.3\n"
        " set Alert distance = 0.1\n" +
        obstacle(kind,
                 Point<2>(0.5, -1.5),
                 2.,
                 "  set Motion = 0.01*t, 0\n  set Rotation = 0.02*t\n") +
        "end\nsubsection Load program\n set Stage increments = 4\nend\n" +
        common_settings("nurbs_obstacle_disk");
      Simulation simulation(SceneReader::read_string(scene, "disk"));
      simulation.run();
      const Tensor<1, 2> force = contact_force(simulation);
      const Tensor<1, 2> u =
        vertex_displacement(simulation.body("block"), Point<2>(0., 0.5));
      const std::vector<double> figures = {force[0], force[1], u[0], u[1]};
      std::cout << "  block on a " << kind << ": contact force (" << force[0]
                << ", " << force[1] << "), corner displacement (" << u[0]
                << ", " << u[1] << ")";
      if (analytic.empty())
        analytic = figures;
      else
        {
          const double difference = largest_difference(figures, analytic);
          std::cout << "; off the analytic disk's by " << difference;
          check(difference < 1e-10, "the clockwise NURBS circle is the disk");
        }
      std::cout << std::endl;
      check(force[1] > 1. && std::abs(force[0]) > 0.01 * force[1],
            "the block presses on the disk and rubs it");
    }
}



// A block pushed off a rigid table's edge (an open NURBS curve's end),
// frictionless, its top pressed down by 0.01 and dragged by its whole width:
// the nodes at the edge, whose equilibrium is at the end, slid off and came
// back behind the table at every Newton iteration, and both discretisations
// stopped at t = 0.625 (six cut-backs). Each now runs to t = 1, and:
// - while the block is wholly on the table (t in [0.1, 0.5]) the table's
//   force does not change (a frictionless rigid translation),
// - at every increment's end every node before the edge (x <= 1.5) is in
//   contact, and past it at most the one node that held contact at the
//   edge within the increment (kept to the increment's end, as at a
//   deformable master's end), no farther past than the increment's drag,
// - the table's force falls as the nodes leave it,
// - the table's force is the top's reaction (both components),
// - the summary says how far the table's edge went into the block's
//   faces (which neither discretisation sees), as deep as the block's
//   boundary sags under the edge.
GLISSADE_TEST(nurbs_curve_obstacle_block_pushed_off_its_end)
{
  std::filesystem::create_directories("output/nurbs_obstacle_edge");
  const std::string table = "output/nurbs_obstacle_edge/table.nurbs";
  std::ofstream(table)
    << "degree 1\nknots 0 0 1 1\ncontrol points 2\n-1 0 1\n1.5 0 1\n";
  const double edge = 1.5;
  for (const std::string discretisation : {"node-to-segment", "mortar"})
    {
      const std::string scene =
        "subsection Scene\n set Bodies = block\n"
        " set Contact pairs = table\nend\n"
        "subsection Body block\n subsection Mesh\n  set Type = rectangle\n"
        "  set Corner 1 = 0, 0\n  set Corner 2 = 1, 0.5\n"
        "  set Subdivisions = 20, 10\n end\n"
        " subsection Material\n  set Young modulus = 1000\n"
        "  set Poisson ratio = 0.3\n end\n"
        " subsection Boundary conditions\n"
        "  set Prescribed displacement = top: x: t; top: y: "
        "-0.01*min(1, 10*t)\n end\nend\n"
        "subsection Contact table\n set Slave body = block\n"
        " set Slave boundary = bottom\n set Alert distance = 0.05\n"
        " set Discretisation = " +
        discretisation +
        "\n subsection Obstacle\n  set Type = nurbs curve\n"
        "  set Curve file = " +
        std::filesystem::absolute(table).string() +
        "\n end\nend\n"
        "subsection Load program\n set Stage end times = 1\n"
        " set Stage increments = 40\nend\n"
        "subsection Output\n set Directory = output/nurbs_obstacle_edge/" +
        discretisation +
        "\n set Progress = false\n set VTU interval = 0\nend\n";
      Simulation         simulation(SceneReader::read_string(scene, "edge"));
      const ContactPair &pair     = *simulation.contact().contact_pairs()[0];
      const Body        &block    = simulation.body("block");
      double             on_table = 0., last = 0., off_by = 0., rise = 0.;
      double             imbalance     = 0.;
      double             farthest_held = 0., sag = 0.;
      unsigned int       missing = 0, most_held = 0, with_held = 0;
      unsigned int       increments = 0;
      simulation.on_increment       = [&](unsigned int, double t) {
        ++increments;
        const Tensor<1, 2> force   = pair.total_force();
        const Tensor<1, 2> support = support_reaction(block, "top");
        imbalance =
          std::max(imbalance, (force + support).norm() / force.norm());
        unsigned int held_here = 0;
        for (const ContactNode &node : pair.nodes())
          {
            const double x = node.reference_position[0] +
                             node.displacement(block.displacement())[0];
            if (x <= edge + 1e-9)
              missing += !node.active;
            else if (node.active)
              {
                ++held_here;
                farthest_held = std::max(farthest_held, x - edge);
              }
          }
        most_held = std::max(most_held, held_here);
        // The slave's boundary below the table's edge, read off its nodes
        // along x: how far the edge went into the sagging face.
        std::vector<std::pair<double, double>> bottom;
        for (const ContactNode &node : pair.nodes())
          bottom.emplace_back(node.reference_position[0] +
                                node.displacement(block.displacement())[0],
                              node.reference_position[1] +
                                node.displacement(block.displacement())[1]);
        std::sort(bottom.begin(), bottom.end());
        for (unsigned int k = 0; k + 1 < bottom.size(); ++k)
          if (bottom[k].first <= edge && edge < bottom[k + 1].first)
            sag = std::max(sag,
                           -(bottom[k].second +
                             (bottom[k + 1].second - bottom[k].second) *
                               (edge - bottom[k].first) /
                               (bottom[k + 1].first - bottom[k].first)));
        with_held += held_here > 0;
        const double carried = std::abs(force[1]);
        if (t >= 0.1 - 1e-12 && t <= 0.5 + 1e-12)
          {
            if (on_table == 0.)
              on_table = carried;
            off_by = std::max(off_by, std::abs(carried - on_table) / on_table);
          }
        if (t > 0.5 + 1e-12)
          rise = std::max(rise, (carried - last) / on_table);
        last = carried;
      };
      simulation.run();
      std::cout << "  " << discretisation << ": " << increments
                << " increments to t = 1; the table's force on the table "
                << on_table << " (changed by " << off_by << "), at t = 1 "
                << last << " (largest rise " << rise
                << "); nodes before the edge out of contact: " << missing
                << "; increments that end with a node past the edge held: "
                << with_held << " (at most " << most_held << " at once, "
                << farthest_held
                << " past the edge); the force against the "
                   "top's reaction "
                << imbalance << std::endl;
      check(increments == 40, discretisation + ": not every increment ran");
      check(off_by <= 1e-9,
            discretisation + ": the force changed while the block slid on "
                             "the table");
      check(rise <= 1e-9 && last < 0.7 * on_table,
            discretisation + ": the force does not fall as the block leaves "
                             "the table");
      check(missing == 0,
            discretisation + ": a node before the edge is out of contact");
      // A node that held contact at the edge keeps it to the increment's
      // end (the obstacle's end continued along its tangent), as at a
      // deformable master's end: one node at most, no farther past the
      // edge than the increment's drag (1 / 40) and the block's own
      // lateral strain.
      check(most_held <= 1 && farthest_held <= 1. / 40. + 0.002,
            discretisation + ": nodes past the edge kept in contact");
      check(imbalance <= 1e-8,
            discretisation + ": the table's force is not the top's reaction");
      // Neither discretisation holds the table's edge off the block's
      // faces: it goes into the face that sags over it, and the run says
      // how far (the normal depth; the sag read along y here differs by
      // the face's slope squared).
      const double deepest = pair.deepest_corner_inside();
      std::cout << "  the edge went " << deepest
                << " into the block's faces (the sag under it " << sag << ")"
                << std::endl;
      check(sag > 0. && std::abs(deepest - sag) <= 0.02 * sag,
            discretisation + ": the edge's depth in the faces is not the "
                             "sag under it");
      check(simulation.summary().find("open ends went at most") !=
              std::string::npos,
            discretisation + ": the summary does not say how far the edge "
                             "went in");
    }
}



// A curve file that is wrong stops with its file and what is wrong.
GLISSADE_TEST(nurbs_curve_obstacle_input_errors)
{
  std::filesystem::create_directories("output/nurbs_obstacle_bad");
  const auto file = [](const std::string &text) {
    const std::string path = "output/nurbs_obstacle_bad/" +
                             std::to_string(std::hash<std::string>()(text)) +
                             ".nurbs";
    std::ofstream(path) << text;
    return path;
  };
  const auto scene = [](const std::string &curve_entry) {
    return "subsection Scene\n set Bodies = block\n"
           " set Contact pairs = floor\nend\n"
           "subsection Body block\n subsection Mesh\n"
           "  set Type = rectangle\n end\n subsection Boundary conditions\n"
           "  set Fixed = top: xy\n end\nend\n"
           "subsection Contact floor\n set Slave body = block\n"
           " set Slave boundary = bottom\n subsection Obstacle\n"
           "  set Type = nurbs curve\n" +
           curve_entry + " end\nend\n";
  };
  const std::string points = "control points 3\n0 0 1\n1 0 1\n2 0 1\n";
  for (const auto &[curve_entry, expected] :
       std::vector<std::pair<std::string, std::string>>{
         {"", "a 'nurbs curve' obstacle needs its curve file"},
         {"  set Curve file = /nonexistent/floor.nurbs\n",
          "cannot open the NURBS curve file"},
         {"  set Curve file = " +
            file("degree 2\nknots 0 0 1 1 1 1\n" + points) + "\n",
          "knots: the first and last knots must each be repeated degree + "
          "1 = 3 times"},
         {"  set Curve file = " +
            file("degree 2\nknots 0 0 0 1 1 1\ncontrol points 3\n0 0 1\n"
                 "1 0 0\n2 0 1\n") +
            "\n",
          "control point 2: the weight must be positive"},
         {"  set Curve file = " +
            file("degree 2\nknots 0 0 0 0.5 1 1 1\n" + points) + "\n",
          "control points: 3, where its 7 knots and degree 2 make 4"},
         {"  set Curve file = " +
            file("degree 2\nknots 0 0 0 1 1 2 2 2\ncontrol points 5\n"
                 "0 0 1\n1 0 1\n2 0 1\n2 1 1\n2 2 1\n") +
            "\n",
          "the curve has a corner at u = 1: its tangent turns by 90 degrees"},
         {"  set Curve file = " +
            file("degree 2\nknots 0 0 0 1 1 1\ncontrol points 3\n0 0 1\n"
                 "0 0 1\n0 0 1\n") +
            "\n",
          "the curve's tangent vanishes"},
         {"  set Curve file = " + file("degree 2\nknot 0 0 0 1 1 1\n") + "\n",
          "'knot' is not one of degree, knots, control points"}})
    {
      const std::string message = refusal(scene(curve_entry));
      std::cout << "  " << message << std::endl;
      check(message.find(expected) != std::string::npos,
            "expected a message with '" + expected + "'");
      check(message.find("Obstacle/Curve file") != std::string::npos,
            "the message names the entry");
    }
}
