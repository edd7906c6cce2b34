// Mortar contact (Discretisation = mortar): the contact patch test on
// non-matching meshes, which one-pass node-to-segment fails (test
// contact_patch_two_blocks: up to 25 %), and Newton's rate in a sliding
// increment. The consistent linearisation is checked against finite
// differences with the node-to-segment ones (contact_tangent_test.cc,
// contact_tangent_mortar_*).

#include <glissade/body/body_measures.h>
#include <glissade/scene/scene_reader.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>

#include "contact_patch.h"
#include "hertz_line_contact.h"
#include "source_tree.h"
#include "test_tools.h"

using namespace glissade;
using namespace dealii;
using namespace glissade_tests;


// The contact patch test (Taylor and Papadopoulos 1991; for mortar,
// Farah, Popp and Wall 2015): on non-matching meshes, each side as slave,
// a uniform stress crosses the interface exactly: every slave node's
// traction is the applied one to 1e-8.
// Both contact steps (condensed, sparse) take the mortar constraints, on
// the faceted and (frictionless) on the B-spline master. (With friction
// the sides of both blocks are moved, and on the B-spline a supported slave
// corner's weighted gap reaches the master's free nodes through the
// spline's weights by a hair: its compliance is nearly zero, and the
// condensed problem with it sticking singular.)
GLISSADE_TEST(mortar_patch_test)
{
  for (const auto &[method, surface] :
       std::vector<std::pair<std::string, std::string>>{
         {"condensed", "faceted"},
         {"sparse", "faceted"},
         {"condensed", "bspline"},
         {"condensed", "hermite"}})
    for (const bool friction : {false, true})
      if (!friction || surface != "bspline")
        for (const auto &[upper_cells, lower_cells] :
             std::vector<std::pair<unsigned int, unsigned int>>{{5, 8},
                                                                {7, 13}})
          for (const bool upper_is_slave : {true, false})
            {
              const std::string label =
                method + ", " + surface + ", " +
                std::string(friction ? "friction, " : "frictionless, ") +
                std::to_string(upper_cells) + " cells on " +
                std::to_string(lower_cells) + ", slave " +
                (upper_is_slave ? "upper" : "lower");
              Simulation simulation(
                SceneReader::read_string(patch_scene(upper_cells,
                                                     lower_cells,
                                                     upper_is_slave,
                                                     friction,
                                                     method,
                                                     surface),
                                         "mortar patch"));
              for (unsigned int k = 1; k <= 2; ++k)
                simulation.advance_to(0.5 * k,
                                      "increment " + std::to_string(k));
              unsigned int       n_checked = 0;
              const double       error     = largest_traction_error(simulation,
                                                          upper_is_slave,
                                                          n_checked,
                                                          label);
              const unsigned int slave_cells =
                upper_is_slave ? upper_cells : lower_cells;
              // Every slave node in contact, but (with friction, where the
              // sides of both blocks are moved) a corner whose weighted gap
              // depends on supported dofs only: biorthogonality zeroes its
              // weight on the free master node, and no reaction can move it.
              check(n_checked + (friction ? 2 : 0) >= slave_cells + 1,
                    label + ": every slave node in contact");
              check(error <= 1e-8, label + ": the traction is not uniform");
              if (friction)
                for (const auto &node :
                     simulation.contact().contact_pairs()[0]->nodes())
                  check(!node.active ||
                          node.status == BiPotentialSolver::NodeStatus::stick,
                        label + ": every node sticks");
            }
}



namespace
{
  /**
   * A cylinder R = 1 pressed on a deformable flat block, plane strain,
   * the quarter x >= 0 (prm/meshes: the cylinder's arc graded to 0.0025
   * at the contact, the block's top to 0.0021: non-matching), E = 200,
   * nu = 0.3 for both, the cylinder's top driven down by `drive`.
   */
  std::string
  hertz_scene(const std::string &discretisation,
              const double       drive,
              const bool         rigid_flat = false)
  {
    const std::string meshes =
      std::string(GLISSADE_SOURCE_DIR) + "/prm/meshes/";
    const auto body = [&](const std::string &name,
                          const std::string &file,
                          const std::string &conditions) {
      return "subsection Body " + name +
             "\n subsection Mesh\n  set Type = gmsh\n  set File = " + meshes +
             file +
             "\n end\n subsection Material\n  set Young modulus = 200\n"
             "  set Poisson ratio = 0.3\n end\n"
             " subsection Boundary conditions\n" +
             conditions + "\n end\nend\n";
    };
    if (rigid_flat)
      return "subsection Scene\n set Bodies = cylinder\n"
             " set Contact pairs = touch\nend\n" +
             body("cylinder",
                  "hertz_sphere_upper.msh",
                  "  set Fixed = axis: x\n  set Prescribed displacement = "
                  "top: y: -" +
                    std::to_string(drive) + "*t") +
             "subsection Contact touch\n set Slave body = cylinder\n"
             " set Slave boundary = arc\n set Master body = rigid\n"
             " set Discretisation = " +
             discretisation +
             "\n set Alert distance = 0.02\n subsection Obstacle\n"
             "  set Type = line\n  set Point = 0, 0\n  set Normal = 0, 1\n"
             " end\nend\n"
             "subsection Load program\n set Stage increments = 2\nend\n"
             "subsection Newton\n set Residual tolerance = 1e-10\n"
             " set Displacement tolerance = 1e-10\nend\n"
             "subsection Output\n set Progress = false\nend\n";
    return "subsection Scene\n set Bodies = cylinder, block\n"
           " set Contact pairs = touch\nend\n" +
           body("cylinder",
                "hertz_sphere_upper.msh",
                "  set Fixed = axis: x\n  set Prescribed displacement = top: "
                "y: -" +
                  std::to_string(drive) + "*t") +
           body("block",
                "hertz_flat_block.msh",
                "  set Fixed = axis: x; bottom: y") +
           "subsection Contact touch\n set Slave body = cylinder\n"
           " set Slave boundary = arc\n set Master body = block\n"
           " set Master boundary = top\n set Discretisation = " +
           discretisation +
           "\n set Alert distance = 0.02\nend\n"
           "subsection Load program\n set Stage increments = 2\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-10\n"
           " set Displacement tolerance = 1e-10\nend\n"
           "subsection Output\n set Progress = false\nend\n";
  }

  /**
   * The slave nodes of the quarter model as Hertz's points: each node's
   * pressure its force over its tributary length (the axis node: twice
   * its force, the quarter model's half, over the mirrored tributary).
   */
  std::vector<HertzPoint>
  cylinder_points(const ContactPair &pair)
  {
    const auto &u = pair.slave().displacement();
    std::vector<std::pair<double, const ContactNode *>> along;
    for (const ContactNode &node : pair.nodes())
      along.emplace_back(node.reference_position[0] + node.displacement(u)[0],
                         &node);
    std::sort(along.begin(), along.end());
    std::vector<HertzPoint> points;
    for (unsigned int k = 0; k + 1 < along.size(); ++k)
      {
        const double left      = k > 0 ? along[k - 1].first : -along[1].first;
        const double tributary = 0.5 * (along[k + 1].first - left);
        const double force =
          along[k].second->active ? along[k].second->force()[1] : 0.;
        points.push_back(
          {along[k].first, force, (k == 0 ? 2. : 1.) * force / tributary});
      }
    return points;
  }
} // namespace

// Hertz, a cylinder on a deformable flat (plane strain, non-matching
// meshes), a / R about 0.05: with mortar, p0 and a within 1 % of Hertz's
// at the load the contact carries, and no node-to-node oscillation of the
// pressure above 2 % of p0 inside 0.9 a; the same with mortar on a rigid
// flat (the obstacle's closest points integrated against the dual
// functions). Node-to-segment on the faceted master is printed beside it.
GLISSADE_TEST(mortar_hertz_cylinder_on_flat)
{
  for (const std::string discretisation : {"mortar",
                                           "node-to-segment",
                                           "node-to-segment, rigid flat",
                                           "mortar, rigid flat"})
    {
      // On a rigid flat, E* = E / (1 - nu^2), and half the drive gives
      // about the same a.
      const bool   rigid  = discretisation.find("rigid") != std::string::npos;
      const double E_star = 200. / ((rigid ? 1. : 2.) * (1. - 0.3 * 0.3));
      Simulation   simulation(
        SceneReader::read_string(hertz_scene(rigid ? "mortar" : discretisation,
                                             rigid ? 0.0052 : 0.0045,
                                             rigid),
                                 "hertz"));
      simulation.run();
      const ContactPair &pair = *simulation.contact().contact_pairs()[0];
      HertzFigures       hertz;
      const HertzFigures measured =
        hertz_line_contact(cylinder_points(pair), E_star, hertz);
      const double reaction =
        support_reaction(simulation.body("cylinder"), "top")[1];
      std::cout << "  " << discretisation << ": "
                << describe(measured, hertz, -2. * reaction) << std::endl;
      check_relative(measured.load,
                     -2. * reaction,
                     1e-9,
                     discretisation + ": contact load against the support");
      // On the rigid flat, node-to-segment and mortar see the same exact
      // line and give the same figures to 1e-5 (p0 1.2 % above Hertz's, a
      // 0.95 % below: the quarter cylinder's finite size and large
      // strain, which a plane contact feels more than the axisymmetric
      // one); the 1 % holds for the deformable flat.
      const double tolerance = rigid ? 2e-2 : 1e-2;
      if (discretisation.rfind("mortar", 0) == 0)
        {
          check(hertz.half_width > 0.04 && hertz.half_width < 0.06,
                "a / R is not about 0.05");
          check_relative(measured.half_width, hertz.half_width, tolerance, "a");
          check_relative(measured.peak_pressure,
                         hertz.peak_pressure,
                         tolerance,
                         "p0");
          check(measured.oscillation <= 0.02,
                "the pressure oscillates by more than 2 % of p0");
        }
    }
}



namespace
{
  /**
   * Ironing (prm/ironing.prm: MOOSE's ironing test, after Yang, Laursen and
   * Meng 2005): a stiff die pressed 1 deep into a soft slab and slid along
   * it with mu = 0.5, with mortar (`scene`: ironing.prm or a variant of
   * it). The normal force
   * on the die over the steady slide (t in [2.5, 6.5]) must oscillate by
   * less than 1 % of its mean about its slow trend (a quadratic in t,
   * fitted by least squares): the die's points pass the slab's element
   * edges without the force jumping. The contact force must balance the
   * support's reaction at every increment.
   */
  void
  check_steady_ironing(const std::string &scene, const std::string &directory)
  {
    Simulation simulation(
      SceneReader::read_file(source_path(scene),
                             {"Output/Directory=" + directory,
                              "Output/VTU interval=0",
                              "Output/Contact table interval=0",
                              "Output/Progress=false"}));
    std::vector<double> time, normal, tangential;
    double              worst_balance = 0., largest_support = 0.;
    simulation.on_increment = [&](unsigned int, const double t) {
      const Tensor<1, 2> support =
        support_reaction(simulation.body("die"), "top");
      const Tensor<1, 2> contact =
        simulation.contact().contact_pairs()[0]->total_force();
      worst_balance   = std::max(worst_balance, (support + contact).norm());
      largest_support = std::max(largest_support, support.norm());
      if (t >= 2.5 - 1e-9)
        {
          time.push_back(t);
          normal.push_back(-support[1]);
          tangential.push_back(support[0]);
        }
    };
    simulation.run();
    worst_balance /= largest_support;

    // Least squares on 1, t, t^2 (normal equations, 3 x 3).
    const auto oscillation = [&](const std::vector<double> &f) {
      FullMatrix<double> A(3, 3);
      Vector<double>     b(3), c(3);
      for (unsigned int k = 0; k < time.size(); ++k)
        for (unsigned int i = 0; i < 3; ++i)
          {
            b(i) += std::pow(time[k], i) * f[k];
            for (unsigned int j = 0; j < 3; ++j)
              A(i, j) += std::pow(time[k], i + j);
          }
      A.gauss_jordan();
      A.vmult(c, b);
      double mean = 0., largest = 0.;
      for (unsigned int k = 0; k < time.size(); ++k)
        {
          mean += f[k] / time.size();
          largest = std::max(largest,
                             std::abs(f[k] - c(0) - c(1) * time[k] -
                                      c(2) * time[k] * time[k]));
        }
      return std::make_pair(mean, largest / mean);
    };
    const auto [normal_mean, normal_oscillation] = oscillation(normal);
    const auto [tangential_mean, tangential_oscillation] =
      oscillation(tangential);
    std::cout << "  steady slide, " << time.size()
              << " increments: normal force " << normal_mean
              << ", oscillation about its trend " << 100. * normal_oscillation
              << " %; tangential force " << tangential_mean << " ("
              << tangential_mean / normal_mean
              << " of the normal), oscillation "
              << 100. * tangential_oscillation
              << " %; contact force against the support's reaction: "
              << worst_balance << std::endl;
    check(time.size() >= 100, "the slide was not computed");
    check(worst_balance <= 1e-8, "the contact force does not balance the die");
    check(normal_oscillation <= 0.01,
          "the normal force oscillates by more than 1 % of its mean");
  }
} // namespace



// The die of Q4 elements (MOOSE's mesh) on the Q1 slab, over its faces.
GLISSADE_TEST(mortar_ironing_steady_force)
{
  check_steady_ironing("prm/ironing.prm", "mortar_ironing");
}



// Both bodies isogeometric (degree 2), prm/ironing_nurbs.prm: the die one
// NURBS patch with its arc exact, the slave side its arc with mortar on
// its own functions (Mortar multipliers = standard), the slab's exact top
// the master.
GLISSADE_TEST(mortar_ironing_nurbs_die_and_slab)
{
  check_steady_ironing("prm/ironing_nurbs.prm", "mortar_ironing_nurbs");
}
