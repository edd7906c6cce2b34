#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <glissade/contact/curves/nurbs_curve.h>
#include <glissade/contact/discretisation/contact_node.h>
#include <glissade/contact/surfaces/master_chain.h>

#include <array>
#include <memory>
#include <vector>

namespace glissade
{
  class Body;
  class Hypothesis;
  class NurbsSpace;

  /**
   * One curve of a NURBS body's boundary (a MasterChain of its faces) as
   * contact sees it: the NurbsCurve over the chain's faces, each face one
   * span of its side of the patch, and the curve's control points, their
   * reference positions and dofs (the curve's data indices). The master
   * surface of a NURBS body (Surface = nurbs) and the slave points of one
   * (ContactPair) are both built on it.
   */
  struct NurbsBoundary
  {
    std::unique_ptr<NurbsCurve>                                 curve;
    std::vector<dealii::Point<2>>                               control_points;
    std::vector<std::array<dealii::types::global_dof_index, 2>> control_dofs;

    /** The chain's curve, updated to the reference configuration. */
    static NurbsBoundary
    build(const NurbsSpace &space, const MasterChain &chain);
  };

  /** What a NURBS slave point's area (ContactNode::collocation_area) is. */
  enum class SlavePointArea
  {
    /** The collocation weights: sum_g R_A(x_g) w_g = int R_A dA for every
     *  A (knot-to-segment, whose point forces go by R_A(x_g)). */
    collocation,
    /** int R_A dA of the point's control point A (mortar, whose point A
     *  carries lambda_A int R_A). */
    function_integral
  };

  /**
   * The slave points of a NURBS body's boundary `boundary` (one name or
   * several): on each of its curves the Greville points of the control
   * points (NurbsCurve::greville_points), as many as the curve's control
   * points, in the order of greville_points(), each with its shares (the
   * control points' rational functions there) and the exact outward
   * normal; appended to `nodes`, with the faces that join consecutive
   * points along each curve, and each point's area (`area`, with the
   * body's out-of-plane measure). `entry` names the boundary in messages.
   */
  void
  append_nurbs_slave_points(const Body                               &body,
                            const std::string                        &boundary,
                            const std::string                        &entry,
                            SlavePointArea                            area,
                            std::vector<ContactNode>                 &nodes,
                            std::vector<std::array<unsigned int, 2>> &faces);
} // namespace glissade
