#include <deal.II/grid/tria.h>

#include <glissade/body/body_measures.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/folding_corner.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    // A corner is where the boundary turns by at least this much.
    constexpr double sharp_corner_degrees = 45.;
    // A cell is crushed where a corner Jacobian fell below this.
    constexpr double crushed_corner_jacobian = 0.5;

    // The vertices of a deal.II quadrilateral counter-clockwise (its own
    // numbering is lexicographic: 0 = (0,0), 1 = (1,0), 2 = (0,1), 3 =
    // (1,1)).
    constexpr std::array<unsigned int, 4> counter_clockwise = {{0, 1, 3, 2}};

    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /** The angle by which the boundary turns at vertex v, in degrees. */
    double
    boundary_turn_degrees(const Triangulation<2> &mesh, const unsigned int v)
    {
      std::vector<Tensor<1, 2>> normals;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              (cell->face(f)->vertex_index(0) == v ||
               cell->face(f)->vertex_index(1) == v))
            {
              const Tensor<1, 2> edge =
                cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
              Tensor<1, 2> normal({edge[1], -edge[0]});
              if (normal * (cell->face(f)->center() - cell->center()) < 0.)
                normal = -normal;
              normals.push_back(normal / normal.norm());
            }
      if (normals.size() != 2)
        return 0.;
      return std::acos(std::clamp(normals[0] * normals[1], -1., 1.)) * 180. /
             M_PI;
    }

    struct CrushedCell
    {
      double   jacobian = 1.;
      Point<2> center;
    };

    /** The cell at vertex v with the smallest corner Jacobian. */
    CrushedCell
    most_crushed_cell_at(const Triangulation<2>          &mesh,
                         const std::vector<Tensor<1, 2>> &displacement,
                         const unsigned int               v)
    {
      CrushedCell worst;
      for (const auto &cell : mesh.active_cell_iterators())
        {
          bool touches = false;
          for (const unsigned int i : cell->vertex_indices())
            touches = touches || cell->vertex_index(i) == v;
          if (!touches)
            continue;
          for (unsigned int k = 0; k < 4; ++k)
            {
              const unsigned int here = counter_clockwise[k],
                                 next = counter_clockwise[(k + 1) % 4],
                                 prev = counter_clockwise[(k + 3) % 4];
              const auto X = [&](const unsigned int i) -> Tensor<1, 2> {
                return cell->vertex(i);
              };
              const auto x = [&](const unsigned int i) -> Tensor<1, 2> {
                return X(i) + displacement[cell->vertex_index(i)];
              };
              const double reference =
                cross(X(next) - X(here), X(prev) - X(here));
              const double deformed =
                cross(x(next) - x(here), x(prev) - x(here));
              if (reference > 0. && deformed / reference < worst.jacobian)
                {
                  worst.jacobian = deformed / reference;
                  worst.center   = cell->center();
                }
            }
        }
      return worst;
    }
  } // namespace



  std::string
  describe_folding_corner(const ContactPair &pair)
  {
    const Body             &body               = pair.slave();
    const Triangulation<2> &mesh               = body.triangulation();
    double                  total_normal_force = 0.;
    for (const ContactNode &node : pair.nodes())
      if (node.active)
        total_normal_force += node.reaction[1];

    std::vector<Tensor<1, 2>> displacement;
    for (const ContactNode &node : pair.nodes())
      {
        if (!node.active || node.vertex == ContactNode::no_vertex ||
            node.status == BiPotentialSolver::NodeStatus::open ||
            !(node.reaction[1] > 0.))
          continue;
        const double turn = boundary_turn_degrees(mesh, node.vertex);
        if (turn < sharp_corner_degrees)
          continue;
        if (displacement.empty())
          displacement = vertex_displacements(body);
        const CrushedCell crushed =
          most_crushed_cell_at(mesh, displacement, node.vertex);
        if (crushed.jacobian >= crushed_corner_jacobian)
          continue;

        const bool stuck = node.status == BiPotentialSolver::NodeStatus::stick;
        const double ratio = std::abs(node.reaction[0]) / node.reaction[1];
        std::ostringstream text;
        text << std::setprecision(3) << "the corner of body '" << body.name()
             << "' at slave node (" << node.reference_position[0] << ", "
             << node.reference_position[1] << ") of pair '" << pair.name()
             << "' folds: the boundary turns by " << std::round(turn)
             << " degrees there, the node "
             << (stuck ? "sticks" : "is in contact")
             << " (|r_t| / r_n = " << ratio
             << ", mu = " << pair.settings().friction << ") and carries "
             << std::round(100. * node.reaction[1] /
                           std::max(total_normal_force, 1e-300))
             << " % of the pair's normal force, and the cell at ("
             << crushed.center[0] << ", " << crushed.center[1]
             << ") is crushed to a corner Jacobian of " << crushed.jacobian
             << " at the last converged state. A sharp corner that "
             << (stuck ? "sticks" : "presses")
             << " is a singular point of exact contact: the equilibrium "
                "with it ends at a load that shrinks with the cell size "
                "(a finer mesh there folds sooner), so more increments do "
                "not carry on. What does: a rounded corner (a fillet a few "
                "cells wide), a coarser mesh at the corner, or less "
                "friction; past the fold its faces would need self-contact, "
                "which glissade does not model (doc/studies/rubber_block.md)";
        return text.str();
      }
    return "";
  }
} // namespace glissade
