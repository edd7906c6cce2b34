#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/fe/nurbs_space.h>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The exact boundary of a master body of NURBS elements (Element/Space
     * = nurbs): the paper's third strategy, with no smoothing laid over the
     * body. Each segment of the chain is a boundary face's span of the
     * patch's side, its point the rational combination of the side's
     * control points, C^(p-1) inside a side and exact for a circle. The
     * reaction goes to the control points by the same functions
     * (consistent, W symmetric), as a traction on the body's boundary is
     * assembled.
     */
    class NurbsSurface : public CurveSurface
    {
    public:
      NurbsSurface(const SurfaceContext &context);

      void
      update(double, double) override;

      std::vector<types::global_dof_index>
      dofs() const override
      {
        std::vector<types::global_dof_index> result;
        for (const auto &d : control_dofs)
          result.insert(result.end(), d.begin(), d.end());
        return result;
      }

      SlaveShares
      node_shares(const unsigned int k) const override
      {
        // Node k starts segment k; an open curve's last node ends the last.
        const bool                             last = k == curve->n_segments();
        const double                           s    = last ? 1. : 0.;
        const auto                             segment = last ? k - 1 : k;
        MasterCurve::NodeWeightsAndDerivatives weights;
        curve->weights_and_derivatives(segment, s, weights);
        SlaveShares shares;
        for (const auto &w : weights)
          if (w.value != 0.)
            shares.push_back({control_dofs[w.node], w.value});
        return shares;
      }

    protected:
      std::array<types::global_dof_index, 2>
      curve_data_dofs(const unsigned int index) const override
      {
        return control_dofs[index];
      }

    private:
      /** The chain's control points: reference positions and dofs. */
      std::vector<Point<2>>                               control_points;
      std::vector<std::array<types::global_dof_index, 2>> control_dofs;
    };



    NurbsSurface::NurbsSurface(const SurfaceContext &context)
      : CurveSurface(*context.master,
                     context.description.master_boundary,
                     context.description.entry + "/Master boundary",
                     context.curve)
    {
      const auto *nurbs = dynamic_cast<const NurbsSpace *>(&master.space());
      if (nurbs == nullptr)
        throw InputError(context.description.entry + "/Surface",
                         "a nurbs surface is the exact boundary of a master "
                         "body of NURBS elements (Element/Space = nurbs); "
                         "body '" +
                           master.name() + "' uses " + master.space().name());
      NurbsBoundary boundary = NurbsBoundary::build(*nurbs, chain);
      control_points         = std::move(boundary.control_points);
      control_dofs           = std::move(boundary.control_dofs);
      curve                  = std::move(boundary.curve);
    }



    void
    NurbsSurface::update(double, double)
    {
      const Vector<double>           &u = master.displacement();
      std::vector<MasterCurve::Point> positions(control_points.size());
      for (unsigned int k = 0; k < positions.size(); ++k)
        for (unsigned int c = 0; c < 2; ++c)
          positions[k][c] = control_points[k][c] + u(control_dofs[k][c]);
      curve->update(positions);
    }
  } // namespace



  std::unique_ptr<MasterSurface>
  make_nurbs_surface(const SurfaceContext &context)
  {
    return std::make_unique<NurbsSurface>(context);
  }
} // namespace glissade
