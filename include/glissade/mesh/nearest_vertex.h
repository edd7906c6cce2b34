#pragma once

#include <deal.II/base/point.h>

#include <vector>

namespace glissade
{
  /** A vertex of a list and its distance to a point. */
  struct NearestVertex
  {
    unsigned int index    = 0;
    double       distance = 0.;
  };

  /**
   * The vertex of `vertices` nearest to `point` (the first of equally near
   * ones), among those that `used` marks when it is given (a
   * Triangulation's vertex list keeps the places of removed vertices).
   * Where a support, a load or a history point names a point(x, y):
   * BoundaryConditions, distribute_mesh and the whole mesh's node table of
   * a body shared out over processes.
   */
  NearestVertex
  nearest_vertex(const std::vector<dealii::Point<2>> &vertices,
                 const dealii::Point<2>              &point,
                 const std::vector<bool>             *used = nullptr);
} // namespace glissade
