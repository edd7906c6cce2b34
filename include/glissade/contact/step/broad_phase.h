#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * The broad phase of automatic contact (Scene/Contact bodies): which
   * couples of listed bodies are within reach of each other at the current
   * state, from the bounding boxes of their contact boundaries in an
   * R-tree (Boost.Geometry's, through deal.II's pack_rtree), so that the
   * search grows like n log n in the number of bodies instead of visiting
   * their n (n - 1) / 2 couples. Only the couples it names have pairs
   * that project nodes (the narrow phase, ContactPair).
   *
   * A couple is within reach when the boxes of the two boundaries'
   * vertices, each grown by its longest face and half the alert distance,
   * overlap: a smoothed master (B-spline, Hermite) leaves its vertices'
   * box by less than a face, so no slave node within the alert distance
   * of the master surface is missed.
   */
  class BroadPhase
  {
  public:
    /** A listed body and the boundary ids of its listed boundary. */
    struct Side
    {
      const Body                          *body;
      std::set<dealii::types::boundary_id> boundary_ids;
    };

    BroadPhase(const std::vector<Side> &sides, const double alert_distance);

    /** The couples (i, j), i < j, indices into the sides, within reach at
     *  the bodies' current displacements; sorted. */
    std::vector<std::array<unsigned int, 2>>
    couples_within_reach() const;

    /** The box of a side at the current state, grown as described above. */
    dealii::BoundingBox<2>
    reach_box(const unsigned int side) const;

    unsigned int
    n_sides() const
    {
      return boundaries.size();
    }

  private:
    /** A side's boundary: its vertices' value dofs and positions, and its
     *  faces as indices into them. */
    struct Boundary
    {
      const Body                                                 *body;
      std::vector<std::array<dealii::types::global_dof_index, 2>> dofs;
      std::vector<dealii::Point<2>>                               reference;
      std::vector<std::array<unsigned int, 2>>                    faces;
    };
    std::vector<Boundary> boundaries;
    double                alert_distance;
  };
} // namespace glissade
