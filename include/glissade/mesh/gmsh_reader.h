#pragma once

#include <deal.II/grid/tria.h>

#include <glissade/mesh/mesh_labels.h>

#include <string>

namespace glissade
{
  /**
   * Reads a Gmsh file (MSH 2.2 or 4.1, ASCII) of quadrilaterals into
   * `triangulation`, after checking every record (a damaged file is refused
   * with the line and what is wrong, never read half-way). Physical Curves
   * name boundaries, Physical Surfaces material regions. Second-order
   * quadrilaterals (9-node and 8-node) keep their curved edges as a
   * manifold, which a quadratic or higher element space follows.
   * `entry` names the .prm entry, for messages.
   */
  MeshLabels
  read_gmsh(const std::string        &file_name,
            dealii::Triangulation<2> &triangulation,
            const std::string        &entry);
} // namespace glissade
