#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * One curve of the master boundary of a contact pair as an ordered
   * chain of mesh vertices, with the master body on the right of the direction
   * of travel (so that n = e3 x t points out of it, theory.md section 4.1).
   * Node i of the chain is node i of the master curve; segment i joins node i
   * to node i + 1 (node N - 1 to node 0 if the chain is closed) and lies on the
   * face `faces[i]`.
   */
  struct MasterChain
  {
    struct Face
    {
      dealii::DoFHandler<2>::active_cell_iterator cell;
      unsigned int                                face;
    };

    bool                          closed = false;
    std::vector<unsigned int>     vertices;
    std::vector<dealii::Point<2>> reference_points;
    /** The x and y value dofs of each node. */
    std::vector<std::array<dealii::types::global_dof_index, 2>> value_dofs;
    std::vector<Face>                                           faces;

    /**
     * The curves of the boundary `boundary` of `body`, each one chain of
     * faces: one for a connected boundary, one per closed or open curve
     * otherwise (a body with holes: its outer boundary and each hole's
     * wall). Open curves come first, in the mesh's order of their first
     * ends, then the closed ones. Throws an InputError naming `entry` if
     * the boundary branches (three faces at a vertex) or a curve has fewer
     * nodes than a curve needs.
     */
    static std::vector<MasterChain>
    build_all(const Body        &body,
              const std::string &boundary,
              const std::string &entry);

    /** Curve number `curve` of build_all(). */
    static MasterChain
    build(const Body        &body,
          const std::string &boundary,
          const std::string &entry,
          unsigned int       curve = 0);
  };
} // namespace glissade
