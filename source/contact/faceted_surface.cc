#include <glissade/contact/curve_surface.h>
#include <glissade/contact/faceted_curve.h>
#include <glissade/contact/surface_registry.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using VertexRule = ContactDescription::VertexRule;

    /**
     * The element edges themselves (the paper's Q4): a piecewise linear
     * curve through the master nodes, whose normal jumps at every node.
     * What a node does at a vertex, where the normal is missing, is the
     * pair's Faceted vertex rule (doc/contact.md, "The faceted master at a
     * vertex").
     */
    class FacetedSurface : public CurveSurface
    {
    public:
      FacetedSurface(const SurfaceContext &context)
        : CurveSurface(*context.master,
                       context.description.master_boundary,
                       context.description.entry + "/Master boundary")
        , rule(context.description.vertex_rule)
      {
        curve = std::make_unique<FacetedCurve>(chain.closed);
      }

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &keep) const override
      {
        SurfacePoint point = CurveSurface::project(x, keep);
        if (rule != VertexRule::vertex_normal || !point.valid ||
            point.on_vertex)
          return point;
        // A node on a vertex, to 1e-9 of the segment: the closest point
        // reports it as the start of the segment leaving the vertex (or
        // the end of the one arriving, if the node was kept there), whose
        // normal is tilted by half the corner's angle. Meet the vertex with
        // its mean normal instead, the same whichever side the node came
        // from.
        const double tolerance = 1e-9;
        if (std::abs(point.s) <= tolerance)
          return corner_point(x, point.segment);
        if (std::abs(point.s - 1.) <= tolerance &&
            (curve->is_closed() ||
             point.segment + 1 < static_cast<int>(curve->n_segments())))
          return corner_point(x, (point.segment + 1) % curve->n_segments());
        return point;
      }

    protected:
      /**
       * kept segment: a faceted segment is kept along its extension, up to
       * half its length past either end. In the valley between two facets
       * (a concave master vertex) a node otherwise jumps from one facet to
       * the other at every iteration, which the fixed-point contact
       * iteration could not converge. The choice is made afresh at the next
       * increment. The other rules keep a segment only while the node
       * projects on it, and otherwise take the closest point, which in the
       * corner's wedge is the vertex with its mean normal.
       */
      double
      extension() const override
      {
        return rule == VertexRule::kept_segment ? 0.5 : 0.;
      }

    private:
      const VertexRule rule;
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_faceted_surface(const SurfaceContext &context)
  {
    return std::make_unique<FacetedSurface>(context);
  }
} // namespace glissade
