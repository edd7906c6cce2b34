#include <glissade/contact/curves/bspline_curve.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/contact/surfaces/surface_registry.h>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The cubic uniform B-spline that interpolates the master nodes (paper
     * section 3.1), closed if the master boundary is. The reaction goes to
     * the spline's own weights (`Force transfer = spline`: consistent, W
     * symmetric) or, as in the paper, to the two nodes of the straight
     * segment under the spline point (`segment`).
     */
    class BSplineSurface : public CurveSurface
    {
    public:
      BSplineSurface(const SurfaceContext &context)
        : CurveSurface(*context.master,
                       context.description.master_boundary,
                       context.description.entry + "/Master boundary",
                       context.curve)
        , segment_transfer(context.description.force_transfer ==
                           ContactDescription::ForceTransfer::segment)
      {
        curve = std::make_unique<BSplineCurve>(
          chain.closed ? BSplineCurve::EndCondition::periodic :
                         BSplineCurve::EndCondition::double_vertex);
      }

      bool
      transfers_by_segment() const override
      {
        return segment_transfer;
      }

    protected:
      void
      set_forces(SurfacePoint &point) const override
      {
        if (!segment_transfer)
          {
            point.forces = point.kinematics;
            return;
          }
        // The hat weights of the underlying segment: 1 - s and s, whose
        // derivatives along the curve are -1 and 1.
        point.forces.clear();
        const auto ends = curve->segment_nodes(point.segment);
        for (unsigned int e = 0; e < 2; ++e)
          for (unsigned int comp = 0; comp < 2; ++comp)
            point.forces.push_back({chain.value_dofs[ends[e]][comp],
                                    comp,
                                    e == 0 ? 1. - point.s : point.s,
                                    e == 0 ? -1. : 1.});
      }

    private:
      const bool segment_transfer;
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_bspline_surface(const SurfaceContext &context)
  {
    return std::make_unique<BSplineSurface>(context);
  }
} // namespace glissade
