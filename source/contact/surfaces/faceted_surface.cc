#include <glissade/contact/curves/faceted_curve.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/contact/surfaces/surface_registry.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * How a faceted master resolves the normal a vertex lacks (its own
     * entry, Faceted vertex rule; contact.md, "The faceted master at a
     * vertex"): the segment kept over the increment, the closest point,
     * or the vertex's mean normal.
     */
    enum class VertexRule
    {
      kept_segment,
      closest_point,
      vertex_normal
    };

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
                       context.description.entry + "/Master boundary",
                       context.curve)
        , rule(
            context.description.surface_settings.has_value() ?
              std::any_cast<VertexRule>(context.description.surface_settings) :
              VertexRule::vertex_normal)
      {
        curve = std::make_unique<FacetedCurve>(chain.closed);
      }

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &keep) const override
      {
        if (rule != VertexRule::vertex_normal)
          return CurveSurface::project(x, keep);

        // A node that the contact law held at a vertex stays there while
        // it is within half a facet of it: the Newton step that pinned it
        // leaves it off the vertex by the step's second-order remainder,
        // which must not send it to a facet.
        if (keep.segment >= 0 && keep.at_vertex && keep.sticking)
          {
            SurfacePoint point = vertex_point(x, keep.segment);
            const double length =
              std::min(facet_length(keep.segment),
                       facet_length(keep.segment == 0 ?
                                      curve->n_segments() - 1 :
                                      keep.segment - 1));
            if (point.on_vertex && (x - point.point).norm() < 0.5 * length)
              return point;
          }
        // A node kept on a facet that has just passed one of its ends, by
        // less than half the facet, meets the vertex there: behind the
        // next facet (a valley of the slave's side) or in front of both
        // (a ridge), the vertex is where a node sliding along the facet
        // stops or turns, and without it the node would alternate between
        // the two facets from one iteration to the next. A node that has
        // left a vertex is projected afresh.
        if (keep.segment >= 0 && !keep.at_vertex)
          {
            const unsigned int segment = keep.segment;
            const auto         a       = curve->value(segment, 0.);
            const auto         b       = curve->value(segment, 1.);
            const double       ex = b[0] - a[0], ey = b[1] - a[1];
            const double       length2 = ex * ex + ey * ey;
            if (length2 > 0.)
              {
                const double s =
                  ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / length2;
                const unsigned int n = curve->n_segments();
                if (s < 0. && s >= -0.5 && (curve->is_closed() || segment > 0))
                  return vertex_point(x, segment);
                if (s > 1. && s <= 1.5 &&
                    (curve->is_closed() || segment + 1 < n))
                  return vertex_point(x, (segment + 1) % n);
              }
          }

        SurfacePoint point =
          CurveSurface::project(x, keep.at_vertex ? SegmentHint() : keep);
        if (!point.valid)
          return point;
        // The closest point is the vertex itself (a node behind both facets
        // of a corner, or in front of both at a ridge).
        if (point.on_vertex)
          return vertex_point(x, point.segment);
        // A node on a vertex, to 1e-9 of the segment: the closest point
        // reports it as the start of the segment leaving the vertex (or
        // the end of the one arriving), whose normal is tilted by half the
        // corner's angle. Meet the vertex with its mean normal and its
        // cone instead, the same whichever side the node came from.
        const double tolerance = 1e-9;
        if (std::abs(point.s) <= tolerance)
          return vertex_point(x, point.segment);
        if (std::abs(point.s - 1.) <= tolerance &&
            (curve->is_closed() ||
             point.segment + 1 < static_cast<int>(curve->n_segments())))
          return vertex_point(x, (point.segment + 1) % curve->n_segments());
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
      double
      facet_length(const unsigned int segment) const
      {
        const auto a = curve->value(segment, 0.);
        const auto b = curve->value(segment, 1.);
        return std::hypot(b[0] - a[0], b[1] - a[1]);
      }

      /**
       * The vertex where `segment` starts, with the mean normal of its two
       * facets and their cone: the tangent of half the angle between them,
       * tan(theta / 2) = sin(theta) / (1 + cos(theta)) for the facets'
       * unit tangents t_in, t_out at angle theta.
       */
      SurfacePoint
      vertex_point(const Point<2> &x, const unsigned int segment) const
      {
        SurfacePoint point = corner_point(x, segment);
        if (!point.on_vertex)
          return point;
        const unsigned int incoming =
          segment == 0 ? curve->n_segments() - 1 : segment - 1;
        const auto   t_in   = curve->unit_tangent(incoming, 1.);
        const auto   t_out  = curve->unit_tangent(segment, 0.);
        const double sine   = std::abs(t_in[0] * t_out[1] - t_in[1] * t_out[0]);
        const double cosine = t_in[0] * t_out[0] + t_in[1] * t_out[1];
        // Facets in line (to far below any mesh's corner angle) have no
        // corner: no cone either.
        if (sine > 1e-8)
          point.vertex_cone = sine / (1. + cosine);
        return point;
      }

      const VertexRule rule;
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_faceted_surface(const SurfaceContext &context)
  {
    return std::make_unique<FacetedSurface>(context);
  }



  // The faceted surface's own entry, in the pair's subsection.
  void
  declare_faceted_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Faceted vertex rule",
      "vertex normal",
      Patterns::Selection("kept segment|closest point|vertex normal"),
      "What a faceted master does at a vertex, where its normal jumps "
      "(doc/contact.md). vertex normal: a node on a vertex (to 1e-9 of "
      "the segment), in the corner's wedge, kept on a facet that it has "
      "just passed the end of, or held there by the last iteration meets "
      "the vertex with the mean normal of the two facets and their cone: "
      "it stays at the vertex while its reaction lies between the facets' "
      "normals (widened by friction's angle) and leaves it along a facet "
      "otherwise. Objective under a rigid turn, with or without friction. "
      "closest point: the closest point at every iteration, a node exactly "
      "on a vertex taking the segment leaving it. kept segment (the first "
      "rule, the default of older versions): a node keeps its segment over "
      "the increment, up to half its length past either end. These two "
      "pick one facet at a vertex, which no rigid turn leaves alone: they "
      "are kept so that scenes that ask for them give the answers they "
      "gave. Other surfaces ignore this entry.");
  }



  std::any
  parse_faceted_parameters(const ParameterHandler &prm,
                           const std::string &,
                           const std::string &)
  {
    const std::string rule = prm.get("Faceted vertex rule");
    return rule == "closest point" ? VertexRule::closest_point :
           rule == "vertex normal" ? VertexRule::vertex_normal :
                                     VertexRule::kept_segment;
  }
} // namespace glissade
