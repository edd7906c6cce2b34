#pragma once

#include <deal.II/grid/tria.h>

namespace glissade
{
  /**
   * The largest distance between two vertices of the mesh: the same value
   * as dealii::GridTools::diameter, found in O(b log b) for b boundary
   * vertices. deal.II 9.4 runs a double loop over every vertex of the mesh
   * (checking a flag for each pair), which took 100 s of a 1M-dof run of
   * two rings; the farthest pair is two vertices of the boundary's convex
   * hull, and only those are compared here.
   */
  double
  mesh_diameter(const dealii::Triangulation<2> &mesh);
} // namespace glissade
