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

  /**
   * The slave points of a NURBS body's boundary `boundary` (one name or
   * several): on each of its curves the Greville points of the control
   * points (NurbsCurve::greville_points), as many as the curve's control
   * points, each with its shares (the control points' rational functions
   * there) and the exact outward normal; appended to `nodes`, with the
   * faces that join consecutive points along each curve, and each point's
   * collocation area (ContactNode::collocation_area, with the body's
   * out-of-plane measure). `entry` names the boundary in messages.
   */
  void
  append_nurbs_slave_points(const Body                               &body,
                            const std::string                        &boundary,
                            const std::string                        &entry,
                            std::vector<ContactNode>                 &nodes,
                            std::vector<std::array<unsigned int, 2>> &faces);
} // namespace glissade
