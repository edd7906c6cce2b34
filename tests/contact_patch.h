#pragma once

// The contact patch test's two blocks (Taylor and Papadopoulos 1991) and
// the traction their interface carries, for the tests of every
// discretisation and master (mortar_test.cc, nurbs_contact_test.cc).

#include <glissade/body/body_measures.h>
#include <glissade/solver/simulation.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "test_tools.h"

namespace glissade_tests
{
  /**
   * Two blocks, upper on lower, `upper_cells` and `lower_cells` along the
   * interface; the slave is the upper block or the lower one.
   *
   * frictionless: the upper block's top pushed down, the sides free: a
   * uniform uniaxial stress in both blocks (the same material expands
   * sideways the same), so the contact pressure is uniform.
   *
   * friction: every outer side of both blocks moved with the homogeneous
   * deformation x = F X, F = [1, gamma; 0, 1 - eps]: the same uniform
   * stress in both blocks solves the problem when the interface sticks,
   * with a shear traction below mu times the pressure.
   */
  inline std::string
  patch_scene(const unsigned int upper_cells,
              const unsigned int lower_cells,
              const bool         upper_is_slave,
              const bool         friction,
              const std::string &method         = "condensed",
              const std::string &surface        = "faceted",
              const std::string &slave_space    = "q1",
              const std::string &master_space   = "",
              const std::string &discretisation = "mortar")
  {
    const std::string motion = "xy: 0.004*y*t, -0.02*y*t";
    const std::string upper_conditions =
      friction ? "  set Prescribed displacement = top: " + motion +
                   "; left: " + motion + "; right: " + motion :
                 "  set Fixed = left: x\n"
                 "  set Prescribed displacement = top: y: -0.02*t";
    const std::string lower_conditions =
      friction ? "  set Prescribed displacement = bottom: " + motion +
                   "; left: " + motion + "; right: " + motion :
                 "  set Fixed = left: x; bottom: y";
    const std::string slave  = upper_is_slave ? "upper" : "lower";
    const std::string master = upper_is_slave ? "lower" : "upper";
    // A Hermite master surface is the edge of a body of Hermite elements
    // (a NURBS master's space is given with its degree).
    const std::string master_element = !master_space.empty() ? master_space :
                                       surface == "hermite"  ? "hermite" :
                                                               "q1";
    return "subsection Scene\n set Bodies = upper, lower\n"
           " set Contact pairs = interface\nend\n" +
           rectangle_body("upper",
                          "0, 0.5",
                          "1, 1",
                          std::to_string(upper_cells) + ", 3",
                          upper_is_slave ? slave_space : master_element,
                          upper_conditions) +
           rectangle_body("lower",
                          "0, 0",
                          "1, 0.5",
                          std::to_string(lower_cells) + ", 4",
                          upper_is_slave ? master_element : slave_space,
                          lower_conditions) +
           "subsection Contact interface\n set Slave body = " + slave +
           "\n set Slave boundary = " + (upper_is_slave ? "bottom" : "top") +
           "\n set Master body = " + master +
           "\n set Master boundary = " + (upper_is_slave ? "top" : "bottom") +
           "\n set Discretisation = " + discretisation +
           "\n set Surface = " + surface + "\n set Alert distance = 0.05\n" +
           (friction ? " set Friction coefficient = 0.5\n" : "") +
           "end\nsubsection Contact solver\n set Tolerance = 1e-13\n set Method = " +
           method +
           "\nend\n"
           "subsection Output\n set Progress = false\nend\n"
           "subsection Newton\n set Residual tolerance = 1e-11\n"
           " set Displacement tolerance = 1e-11\nend\n";
  }

  /**
   * The traction on the slave side of the interface: the upper block's top
   * support over the top's current width (its corners' displacements, the
   * nodal view of any space); on the upper block's bottom it is minus the
   * top's, on the lower block's top the top's.
   */
  inline dealii::Tensor<1, 2>
  applied_traction(glissade::Simulation &simulation, const bool upper_is_slave)
  {
    using namespace glissade;
    const Body                &upper   = simulation.body("upper");
    const dealii::Tensor<1, 2> support = support_reaction(upper, "top");
    const auto                &u       = upper.nodal_displacement();
    double                     left = 1e300, right = -1e300;
    for (const auto &cell : upper.dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[1] - 1.) < 1e-12)
          {
            const auto dofs =
              BoundaryConditions::cell_vertex_dofs(cell, v, upper.space());
            left  = std::min(left, cell->vertex(v)[0] + u(dofs[0]));
            right = std::max(right, cell->vertex(v)[0] + u(dofs[0]));
          }
    return (upper_is_slave ? -1. : 1.) * support / (right - left);
  }

  /**
   * The traction of each active slave node (its force over its current
   * tributary length: the mortar reaction is D_j lambda_j, D_j the
   * integral of the node's shape function) against applied_traction(): the
   * largest relative difference.
   */
  inline double
  largest_traction_error(glissade::Simulation &simulation,
                         const bool            upper_is_slave,
                         unsigned int         &n_checked,
                         const std::string    &label)
  {
    using namespace glissade;
    const dealii::Tensor<1, 2> applied =
      applied_traction(simulation, upper_is_slave);

    const auto &pair  = *simulation.contact().contact_pairs()[0];
    const Body &slave = pair.slave();
    const auto &us    = slave.displacement();
    std::vector<std::pair<double, const ContactNode *>> along;
    for (const auto &node : pair.nodes())
      along.emplace_back(node.reference_position[0], &node);
    std::sort(along.begin(), along.end());
    const auto x = [&](const ContactNode &node) {
      return node.reference_position[0] + node.displacement(us)[0];
    };
    double error = 0.;
    n_checked    = 0;
    for (unsigned int k = 0; k < along.size(); ++k)
      {
        const ContactNode &node = *along[k].second;
        if (!node.active)
          continue;
        const double tributary =
          0.5 * ((k + 1 < along.size() ? x(*along[k + 1].second) : x(node)) -
                 (k > 0 ? x(*along[k - 1].second) : x(node)));
        const dealii::Tensor<1, 2> traction =
          pair.reported_force(node) / tributary;
        error = std::max(error, (traction - applied).norm() / applied.norm());
        ++n_checked;
      }
    std::cout << "  " << label << ": applied traction (" << applied << "), "
              << n_checked << " active slave nodes, largest relative error "
              << error << std::endl;
    return error;
  }
} // namespace glissade_tests
