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
   * The master boundary of a contact pair as one ordered chain of mesh
   * vertices, with the master body on the right of the direction of travel
   * (so that n = e3 x t points out of it, theory.md section 4.1). Node i of
   * the chain is node i of the master curve; segment i joins node i to node
   * i + 1 (node N - 1 to node 0 if the chain is closed) and lies on the face
   * `faces[i]`.
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
     * Walks the faces of the boundary `boundary` of `body`. Throws an
     * InputError naming `entry` if the boundary branches, is not connected,
     * or has fewer nodes than a curve needs.
     */
    static MasterChain
    build(const Body        &body,
          const std::string &boundary,
          const std::string &entry);
  };
} // namespace glissade
