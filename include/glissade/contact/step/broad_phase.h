#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <glissade/contact/surfaces/master_chain.h>

#include <array>
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
    /** A listed body and the name of its listed boundary; `entry` names
     *  it in messages. */
    struct Side
    {
      const Body *body;
      std::string boundary;
      std::string entry;
    };

    /** Throws an InputError naming a side's entry if its boundary is not
     *  made of chains of faces (MasterChain::build_all). */
    BroadPhase(const std::vector<Side> &sides, const double alert_distance);

    /**
     * The couples (i, j), i < j, indices into the sides, within reach at
     * the bodies' current displacements; sorted. The boxes it compared are
     * kept (box()).
     */
    std::vector<std::array<unsigned int, 2>>
    couples_within_reach();

    /** A side's box, grown as described above, as the last
     *  couples_within_reach() found it. */
    const dealii::BoundingBox<2> &
    box(const unsigned int side) const
    {
      return boxes[side];
    }

    unsigned int
    n_sides() const
    {
      return chains.size();
    }

  private:
    /** A side's box at the current state. */
    dealii::BoundingBox<2>
    reach_box(const unsigned int side) const;

    std::vector<const Body *> bodies;
    /** Each side's curves (one for a connected boundary). */
    std::vector<std::vector<MasterChain>> chains;
    std::vector<dealii::BoundingBox<2>>   boxes;
    double                                alert_distance;
  };
} // namespace glissade
