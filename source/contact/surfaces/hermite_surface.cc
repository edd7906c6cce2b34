#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/contact/curves/hermite_curve.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/fe/hermite_space.h>

#include <algorithm>
#include <cmath>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The C1 edges of a master body of Hermite elements (paper section
     * 3.2): on each edge the cubic Hermite curve of its two end nodes'
     * positions and tangents dx/ds = (I + grad u) dX/ds, so that the
     * derivative dofs enter the surface point (eq. 29-30).
     */
    class HermiteSurface : public CurveSurface
    {
    public:
      HermiteSurface(const SurfaceContext &context);

      std::vector<types::global_dof_index>
      dofs() const override
      {
        auto result = CurveSurface::dofs();
        for (const auto &d : derivative_dofs)
          result.insert(result.end(), d.begin(), d.end());
        return result;
      }

    protected:
      void
      rebuild(const std::vector<MasterCurve::Point> &positions) override
      {
        // Deformed tangents d = (I + grad u) T at both ends of each segment.
        const Vector<double> &u = master.displacement();
        std::vector<std::array<MasterCurve::Point, 2>> tangents;
        for (unsigned int i = 0; i < reference_tangents.size(); ++i)
          {
            std::array<MasterCurve::Point, 2> pair;
            for (unsigned int e = 0; e < 2; ++e)
              {
                const unsigned int  node = (i + e) % positions.size();
                const Tensor<1, 2> &T    = reference_tangents[i][e];
                const auto         &d    = derivative_dofs[node];
                for (unsigned int c = 0; c < 2; ++c)
                  pair[e][c] =
                    T[c] + u(d[3 * c + 1]) * T[0] + u(d[3 * c + 2]) * T[1];
              }
            tangents.push_back(pair);
          }
        static_cast<HermiteCurve &>(*curve).update(positions, tangents);
      }

      void
      add_kinematics(const unsigned int          segment,
                     const double                s,
                     std::vector<SurfaceWeight> &kinematics) const override
      {
        // The tangent data d = (I + grad u) T enter c(s) with H10, H11.
        const auto ends = curve->segment_nodes(segment);
        const auto h    = static_cast<const HermiteCurve &>(*curve)
                         .tangent_weights_and_derivatives(segment, s);
        for (unsigned int e = 0; e < 2; ++e)
          {
            const Tensor<1, 2> &T = reference_tangents[segment][e];
            const auto         &d = derivative_dofs[ends[e]];
            for (unsigned int c = 0; c < 2; ++c)
              for (unsigned int k = 0; k < 2; ++k)
                kinematics.push_back(
                  {d[3 * c + 1 + k], c, h[e] * T[k], h[2 + e] * T[k]});
          }
      }

    private:
      /**
       * The Hermite edge is C1 only if the reference geometry is: the two
       * segments at a node must leave it along one tangent. Meshes read from
       * a file have straight-sided cells, so the reference tangents are the
       * chords and every node of a curved boundary is a kink: the Hermite
       * master would act as a faceted one (u_r 7 % off on a ring) without a
       * word. Refused when most nodes are kinks; a few (the corners of a
       * polygonal boundary) are genuine.
       */
      void
      check_reference_edge_is_smooth(const SurfaceContext &context) const;

      std::vector<std::array<types::global_dof_index, 6>> derivative_dofs;
      std::vector<std::array<Tensor<1, 2>, 2>>            reference_tangents;
    };



    HermiteSurface::HermiteSurface(const SurfaceContext &context)
      : CurveSurface(*context.master,
                     context.description.master_boundary,
                     context.description.entry + "/Master boundary",
                     context.curve)
    {
      const auto *hermite = dynamic_cast<const HermiteSpace *>(&master.space());
      if (hermite == nullptr)
        throw InputError(context.description.entry + "/Surface",
                         "a hermite surface needs a master body of "
                         "Hermite elements (body '" +
                           master.name() + "' uses " + master.space().name() +
                           ")");
      curve = std::make_unique<HermiteCurve>(chain.closed);

      // Per node its six dofs (x, dx/dX, dx/dY, y, dy/dX, dy/dY), and per
      // segment the reference tangents dX/ds at its two ends.
      const FiniteElement<2> &fe = master.space().finite_element();
      derivative_dofs.resize(chain.vertices.size());
      for (unsigned int i = 0; i < chain.faces.size(); ++i)
        {
          const auto        &face = chain.faces[i];
          const unsigned int a = i, b = (i + 1) % chain.vertices.size();
          const auto         edge =
            HermiteQuadrilateral::edge_from_dealii_face(face.face);
          const auto ends = HermiteQuadrilateral::edge_nodes(edge.edge);
          const auto dir =
            HermiteQuadrilateral::edge_reference_direction(edge.edge);
          const auto &element =
            hermite->element(face.cell->active_cell_index());
          std::array<Tensor<1, 2>, 2> tangent_at_end;
          for (unsigned int e = 0; e < 2; ++e)
            {
              const auto ref =
                HermiteQuadrilateral::node_reference_point(ends[e]);
              const auto J = element.jacobian(ref[0], ref[1]);
              // d/ds on [-1, 1] -> d/dsigma on [0, 1]: a factor 2.
              tangent_at_end[e] =
                2. * Tensor<1, 2>({J[0][0] * dir[0] + J[0][1] * dir[1],
                                   J[1][0] * dir[0] + J[1][1] * dir[1]});
              const unsigned int v =
                HermiteQuadrilateral::dealii_vertex_from_node(ends[e]);
              const unsigned int node =
                face.cell->vertex_index(v) == chain.vertices[a] ? a : b;
              for (unsigned int k = 0; k < 6; ++k)
                derivative_dofs[node]
                               [fe.system_to_component_index(v * 6 + k).first] =
                                 face.cell->vertex_dof_index(v, k);
            }
          const bool same_direction =
            face.cell->vertex_index(
              HermiteQuadrilateral::dealii_vertex_from_node(ends[0])) ==
            chain.vertices[a];
          reference_tangents.push_back(
            same_direction ? std::array<Tensor<1, 2>, 2>{{tangent_at_end[0],
                                                          tangent_at_end[1]}} :
                             std::array<Tensor<1, 2>, 2>{
                               {-tangent_at_end[1], -tangent_at_end[0]}});
        }
      check_reference_edge_is_smooth(context);
    }



    void
    HermiteSurface::check_reference_edge_is_smooth(
      const SurfaceContext &context) const
    {
      const unsigned int n_segments = reference_tangents.size();
      unsigned int       interior = 0, kinks = 0;
      double             largest = 0.;
      for (unsigned int i = 0; i < n_segments; ++i)
        {
          if (!chain.closed && i + 1 == n_segments)
            break;
          const Tensor<1, 2> &before = reference_tangents[i][1];
          const Tensor<1, 2> &after =
            reference_tangents[(i + 1) % n_segments][0];
          const double angle =
            std::atan2(std::abs(cross_product_2d(before) * after),
                       before * after);
          ++interior;
          largest = std::max(largest, angle);
          if (angle > 1e-6)
            ++kinks;
        }
      if (interior > 0 && 2 * kinks > interior)
        throw InputError(
          context.description.entry + "/Surface",
          "a hermite surface on body '" + master.name() +
            "': the reference geometry of its master boundary has a "
            "tangent that jumps at " +
            std::to_string(kinks) + " of its " + std::to_string(interior) +
            " nodes (by up to " + std::to_string(largest * 180. / numbers::PI) +
            " degrees), as in a mesh read from a file, whose cells have "
            "straight sides; such an edge is no smoother than a faceted "
            "one. Use Surface = bspline, or a generated mesh (ring, half "
            "ring) whose cells follow the curved boundary");
    }
  } // namespace



  std::unique_ptr<MasterSurface>
  make_hermite_surface(const SurfaceContext &context)
  {
    return std::make_unique<HermiteSurface>(context);
  }
} // namespace glissade
