#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * @name Measures of a body's state
   *
   * What histories, studies and tests read off a body: displacements at
   * vertices, the largest one, the reaction of a support, the stored
   * energy. Each is computed from the body's public state (displacement,
   * forces, mesh and element space) and changes nothing.
   */
  /** @{ */

  /** The displacement at the mesh vertex at `point` (an input error if
   *  there is none). */
  dealii::Tensor<1, 2>
  vertex_displacement(const Body &body, const dealii::Point<2> &point);

  /**
   * The x and y value dofs of the mesh vertex at `point` (an input error
   * if there is none): found once, read at every increment (history).
   */
  std::array<dealii::types::global_dof_index, 2>
  vertex_value_dofs(const Body &body, const dealii::Point<2> &point);

  /**
   * The displacement of every vertex of the mesh, indexed like
   * triangulation().get_vertices() (zero for unused vertices).
   */
  std::vector<dealii::Tensor<1, 2>>
  vertex_displacements(const Body &body);

  /** The largest nodal displacement norm over the body. */
  double
  max_displacement(const Body &body);

  /**
   * The sum of F_int - F_ext - F_contact over the dofs of a named boundary
   * or at a vertex "point(x, y)": on supported dofs, the force the support
   * exerts on the body.
   */
  dealii::Tensor<1, 2>
  support_reaction(const Body &body, const std::string &boundary);

  /** The stored energy of the current state, int W dV. */
  double
  strain_energy(const Body &body);

  /** @} */
} // namespace glissade
