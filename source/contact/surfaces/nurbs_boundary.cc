#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/body.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/fe/nurbs_space.h>

#include <cmath>
#include <map>

namespace glissade
{
  using namespace dealii;

  NurbsBoundary
  NurbsBoundary::build(const NurbsSpace &space, const MasterChain &chain)
  {
    NurbsBoundary                        boundary;
    std::map<unsigned int, unsigned int> local_of_control;
    std::vector<NurbsCurve::Segment>     segments;
    for (unsigned int i = 0; i < chain.faces.size(); ++i)
      {
        const auto &face = chain.faces[i];
        const auto  side =
          space.face_curve(face.cell->active_cell_index(), face.face);
        NurbsCurve::Segment segment;
        for (unsigned int m = 0; m < side.controls.size(); ++m)
          {
            const auto [at, added] =
              local_of_control.emplace(side.controls[m],
                                       boundary.control_points.size());
            if (added)
              {
                boundary.control_points.push_back(side.points[m]);
                boundary.control_dofs.push_back(
                  space.control_dofs_of(side.controls[m]));
              }
            segment.controls.push_back(at->second);
          }
        segment.weights = side.weights;
        segment.knots   = side.knots;
        // The chain runs from vertex i to vertex i + 1; the span from the
        // face's first vertex.
        segment.reversed =
          face.cell->vertex_index(
            GeometryInfo<2>::face_to_cell_vertices(face.face, 0)) !=
          chain.vertices[i];
        segments.push_back(std::move(segment));
      }
    boundary.curve = std::make_unique<NurbsCurve>(space.polynomial_degree(),
                                                  chain.closed,
                                                  std::move(segments));
    std::vector<MasterCurve::Point> reference;
    for (const Point<2> &X : boundary.control_points)
      reference.push_back({{X[0], X[1]}});
    boundary.curve->update(reference);
    return boundary;
  }



  void
  append_nurbs_slave_points(const Body                               &body,
                            const std::string                        &boundary,
                            const std::string                        &entry,
                            const SlavePointArea                      area_kind,
                            std::vector<ContactNode>                 &nodes,
                            std::vector<std::array<unsigned int, 2>> &faces)
  {
    const auto &space = dynamic_cast<const NurbsSpace &>(body.space());
    for (const MasterChain &chain :
         MasterChain::build_all(body, boundary, entry))
      {
        const NurbsBoundary curve_of_chain = NurbsBoundary::build(space, chain);
        const NurbsCurve   &curve          = *curve_of_chain.curve;
        const unsigned int  first          = nodes.size();
        // The collocation areas: sum_g R_A(x_g) w_g = int R_A dA, one
        // equation per control point, as many as the points (one Greville
        // point each; unisolvent: Schoenberg-Whitney).
        const auto         points = curve.greville_points();
        const unsigned int n      = points.size();
        AssertThrow(n == curve.n_controls(),
                    ExcMessage("a Greville point per control point"));
        FullMatrix<double> R(n, n);
        Vector<double>     integral(n), area(n);
        for (unsigned int g = 0; g < n; ++g)
          {
            const unsigned int                     segment = points[g].segment;
            const double                           s       = points[g].s;
            ContactNode                            node;
            MasterCurve::NodeWeightsAndDerivatives weights;
            curve.weights_and_derivatives(segment, s, weights);
            for (const auto &w : weights)
              {
                node.shares.push_back(
                  {curve_of_chain.control_dofs[w.node], w.value});
                R(w.node, g) += w.value;
              }
            const auto X            = curve.value(segment, s);
            const auto normal       = curve.unit_normal(segment, s);
            node.reference_position = Point<2>(X[0], X[1]);
            // (the chain has the body on its right: n = e3 x t points out)
            node.reference_outward_normal =
              Tensor<1, 2>({normal[0], normal[1]});
            nodes.push_back(std::move(node));
          }
        const QGauss<1> rule(curve.degree_of_curve() + 3);
        for (unsigned int i = 0; i < curve.n_segments(); ++i)
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              const double s  = rule.point(q)[0];
              const auto   X  = curve.value(i, s);
              const auto   dX = curve.derivative(i, s);
              const double dA =
                std::hypot(dX[0], dX[1]) * rule.weight(q) *
                body.hypothesis().out_of_plane_measure(Point<2>(X[0], X[1]));
              MasterCurve::NodeWeightsAndDerivatives weights;
              curve.weights_and_derivatives(i, s, weights);
              for (const auto &w : weights)
                integral(w.node) += w.value * dA;
            }
        if (area_kind == SlavePointArea::collocation)
          {
            R.gauss_jordan();
            R.vmult(area, integral);
          }
        else
          for (unsigned int g = 0; g < n; ++g)
            area(g) = integral(points[g].control);
        for (unsigned int g = 0; g < n; ++g)
          nodes[first + g].collocation_area = area(g);

        for (unsigned int k = first; k + 1 < nodes.size(); ++k)
          faces.push_back({{k, k + 1}});
        if (chain.closed && nodes.size() > first + 2)
          faces.push_back(
            {{static_cast<unsigned int>(nodes.size() - 1), first}});
      }
  }
} // namespace glissade
