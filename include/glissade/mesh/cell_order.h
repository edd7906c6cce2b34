#pragma once

#include <deal.II/grid/tria.h>

namespace glissade
{
  /**
   * Puts the cells of a mesh in the order of a Hilbert curve through their
   * centres (vertices, boundary and material ids unchanged).
   *
   * On several processes each process integrates a range of the mesh's
   * cells and holds the cells around it (distribute_mesh): a range is a
   * compact piece of the body only if consecutive cells are neighbours,
   * and the dofs, numbered cell by cell, are then near each other too.
   * The meshes glissade generates are built so; a Gmsh file lists its
   * cells in the order its mesher made them, which on the Hertz sphere gave
   * process 0 of two 2,924 of the 3,107 cells to hold. Made on one process
   * too, so that every run numbers the dofs alike (the checkpoint, and the
   * comparisons between process counts, rely on it). The curve is
   * deal.II's (Utilities::inverse_Hilbert_space_filling_curve), on a grid
   * of 2^16 x 2^16 over the mesh's bounding square.
   */
  void
  order_cells_along_hilbert_curve(dealii::Triangulation<2> &mesh);
} // namespace glissade
