#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <map>

namespace glissade
{
  /**
   * At every vertex of the boundary faces that `on_boundary(id)` selects,
   * the sum of those faces' unit outward normals in the reference
   * configuration (not normalised: a cusp sums to zero). On a uniformly
   * divided circle it points along the exact radius. Used for normal and
   * tangential supports and to check that a rigid obstacle faces its slave.
   */
  std::map<unsigned int, dealii::Tensor<1, 2>>
  boundary_vertex_normals(
    const dealii::Triangulation<2>                        &triangulation,
    const std::function<bool(dealii::types::boundary_id)> &on_boundary);
} // namespace glissade
