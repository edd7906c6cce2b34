#pragma once

#include <glissade/contact/surfaces/curve_surface.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * A master boundary made of several curves, each its own surface of the
   * pair's kind (faceted, B-spline, Hermite): a body with holes, whose
   * boundary is its outer curve and each hole's wall, or a boundary named
   * on separate stretches. A slave node's counterpart is the closest of
   * the curves' points; the curves' segments are numbered one after the
   * other (curve 0's first, then curve 1's, ...), and so are their nodes
   * in vertices().
   *
   * Self-contact: a node of curve c sees its own curve as a one-curve
   * surface does (CurveSurface::project_facing) and the curves after c,
   * not those before: two curves facing each other are held once, by the
   * earlier one's nodes, as two stretches of one curve are.
   */
  class CompositeSurface : public MasterSurface
  {
  public:
    explicit CompositeSurface(
      std::vector<std::unique_ptr<CurveSurface>> &&curves);

    void
    update(double step_start_time, double time) override;

    SurfacePoint
    project(const dealii::Point<2> &x, const SegmentHint &keep) const override;

    SurfacePoint
    project_facing(const dealii::Point<2> &x,
                   const SegmentHint      &keep,
                   const FacingView       &view) const override;

    std::vector<unsigned int>
    vertices() const override;

    std::vector<dealii::types::global_dof_index>
    dofs() const override;

    bool
    is_rigid() const override
    {
      return false;
    }

    unsigned int
    n_curves() const
    {
      return curves.size();
    }

  private:
    /** The curve that the pair-wide segment `segment` lies on. */
    unsigned int
    curve_of_segment(int segment) const;

    /** The curve that the pair-wide node `node` lies on. */
    unsigned int
    curve_of_node(int node) const;

    /** `point` of curve c, with its segment numbered pair-wide. */
    SurfacePoint
    numbered(SurfacePoint point, unsigned int c) const;

    /** The valid point of `candidates` closest to x (none if none). */
    static SurfacePoint
    closest(const dealii::Point<2>          &x,
            const std::vector<SurfacePoint> &candidates);

    std::vector<std::unique_ptr<CurveSurface>> curves;
    /** Where each curve's segments and nodes start, pair-wide. */
    std::vector<int> first_segment, first_node;
  };
} // namespace glissade
