#pragma once

#include <glissade/contact/curves/master_curve.h>
#include <glissade/contact/discretisation/contact_linearization.h>
#include <glissade/contact/surfaces/master_chain.h>
#include <glissade/contact/surfaces/master_surface.h>

#include <memory>
#include <string>

namespace glissade
{
  class Body;

  /**
   * The common part of the deformable master surfaces: a chain of master
   * nodes (MasterChain) seen through a MasterCurve built from their current
   * positions. The point of a slave node is the curve's closest point; its
   * dof weights are the curve's node weights (with their derivatives along
   * the curve) on the nodes' value dofs.
   *
   * A derived class creates the curve (set `curve` in its constructor) and
   * may add what its curve needs beyond the node positions (the Hermite
   * edge's tangents: rebuild(), add_kinematics(), dofs()), hand the
   * reaction to other dofs than the kinematic ones (set_forces()), or let a
   * node keep its segment beyond the segment's ends (extension()).
   */
  class CurveSurface : public MasterSurface
  {
  public:
    /** Curve `curve` of the boundary (MasterChain::build_all). */
    CurveSurface(const Body        &master,
                 const std::string &boundary,
                 const std::string &entry,
                 unsigned int       curve = 0);

    void
    update(double step_start_time, double time) override;

    SurfacePoint
    project(const dealii::Point<2> &x, const SegmentHint &keep) const override;

    /**
     * The closest point facing x (MasterCurve::project_among), with the
     * node's own segments and their neighbours left out.
     */
    SurfacePoint
    project_facing(const dealii::Point<2> &x,
                   const SegmentHint      &keep,
                   const FacingView       &view) const override;

    std::vector<dealii::types::global_dof_index>
    dofs() const override;

    std::vector<unsigned int>
    vertices() const override
    {
      return chain.vertices;
    }

    bool
    is_rigid() const override
    {
      return false;
    }

    const MasterCurve &
    master_curve() const
    {
      return *curve;
    }

    const MasterChain &
    master_chain() const
    {
      return chain;
    }

    /**
     * The dof weights of the curve point at (segment, s), s in [0, 1],
     * with their derivatives in s: the node weights on the value dofs and
     * what the curve adds (the Hermite edge's derivative dofs). A point's
     * change is sum_w w.value du(w.dof) in component w.component.
     */
    std::vector<SurfaceWeight>
    kinematics_at(unsigned int segment, double s) const;

    /**
     * Where a force at (segment, s) goes, with the weights' derivatives,
     * given the point's kinematics_at(segment, s).
     */
    std::vector<SurfaceWeight>
    forces_at(unsigned int                      segment,
              double                            s,
              const std::vector<SurfaceWeight> &kinematics) const;

    /**
     * What the curve's node k (MasterCurve::nodes(), a segment's end) moves
     * with: the chain node's value dofs, or, on a curve that does not
     * interpolate data at its nodes (NURBS), the data points' dofs with
     * their weights there. Mortar cuts the slave faces at these nodes.
     */
    virtual SlaveShares
    node_shares(const unsigned int k) const
    {
      return {{chain.value_dofs[k], 1.}};
    }

    /**
     * True when the reaction goes to the two nodes of the straight
     * segment under the curve point (the paper's segment transfer) rather
     * than by the kinematic weights.
     */
    virtual bool
    transfers_by_segment() const
    {
      return false;
    }

  protected:
    /** Rebuilds the curve from the current node positions. */
    virtual void
    rebuild(const std::vector<MasterCurve::Point> &positions);

    /**
     * The x and y dofs of the curve's data point `index` (the indices of
     * MasterCurve::weights_and_derivatives()): the chain's node `index` by
     * default; the control point `index` of a NURBS boundary.
     */
    virtual std::array<dealii::types::global_dof_index, 2>
    curve_data_dofs(const unsigned int index) const
    {
      return chain.value_dofs[index];
    }

    /** Entries of c(s) beyond the node weights (none by default). */
    virtual void
    add_kinematics(unsigned int                segment,
                   double                      s,
                   std::vector<SurfaceWeight> &kinematics) const;

    /** The dofs that receive the reaction (by default the kinematic ones). */
    virtual void
    set_forces(SurfacePoint &point) const;

    /**
     * How far past its ends (in units of s) a node may keep its segment
     * within an increment: 0 for smooth curves, where the neighbouring
     * segment continues the curve.
     */
    virtual double
    extension() const
    {
      return 0.;
    }

    /**
     * The point of x at the curve node where `segment` starts, taken as a
     * corner: the node itself, which does not slide, with the mean of the
     * two adjacent segments' normals (as MasterCurve::project() reports a
     * convex corner). The first node of an open curve has one segment, whose
     * normal it keeps.
     */
    SurfacePoint
    corner_point(const dealii::Point<2> &x, unsigned int segment) const;

    /**
     * The point of x on the segment a `keep` hint names, if the node may
     * keep it (MasterSurface::project); false if there is none or it may
     * not.
     */
    bool
    project_on_kept_segment(const dealii::Point<2> &x,
                            const SegmentHint      &keep,
                            SurfacePoint           &point) const;

    /** The surface point of the curve's projection p of x (none if p is
     *  not valid; at a convex corner, the curve's bisecting normal). */
    SurfacePoint
    surface_point_of(const dealii::Point<2>        &x,
                     const MasterCurve::Projection &p) const;

    const Body                  &master;
    const MasterChain            chain;
    std::unique_ptr<MasterCurve> curve;

  private:
    /**
     * For a point past an open end of the curve (s > 1 on the last
     * segment, s < 0 on the first), the end's s; -1 otherwise.
     */
    double
    end_of_extension(unsigned int segment, double s) const;

    /**
     * The curve and its first two derivatives, continued along the end's
     * tangent line past an open end (where a node kept on its segment for
     * the increment may go).
     */
    void
    evaluate(unsigned int        segment,
             double              s,
             MasterCurve::Point &c,
             MasterCurve::Point &dc,
             MasterCurve::Point &ddc) const;

    /** The point at (segment, s) for the slave position x. */
    SurfacePoint
    point_at(const dealii::Point<2> &x, unsigned int segment, double s) const;

    /**
     * Orthogonal projection on one segment by Newton from s; false if s
     * leaves [-margin, 1 + margin].
     */
    bool
    project_on_segment(const dealii::Point<2> &x,
                       unsigned int            segment,
                       double                 &s,
                       double                  margin) const;

    /** The turn of the bisecting normal at a corner node. */
    void
    set_vertex_rotation(SurfacePoint &point) const;
  };
} // namespace glissade
