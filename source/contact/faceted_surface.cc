#include <glissade/contact/curve_surface.h>
#include <glissade/contact/faceted_curve.h>
#include <glissade/contact/surface_registry.h>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The element edges themselves (the paper's Q4): a piecewise linear
     * curve through the master nodes, whose normal jumps at every node.
     */
    class FacetedSurface : public CurveSurface
    {
    public:
      FacetedSurface(const SurfaceContext &context)
        : CurveSurface(*context.master, context.description.master_boundary,
                       context.description.entry + "/Master boundary")
      {
        curve = std::make_unique<FacetedCurve>(chain.closed);
      }

    protected:
      /**
       * A faceted segment is kept along its extension, up to half its
       * length past either end: in the valley between two facets (a
       * concave master vertex) a node otherwise jumps from one facet to
       * the other at every iteration and Newton cannot converge. The
       * choice is made afresh at the next increment.
       */
      double
      extension() const override
      {
        return 0.5;
      }
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_faceted_surface(const SurfaceContext &context)
  {
    return std::make_unique<FacetedSurface>(context);
  }
} // namespace glissade
