#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/manifold.h>

#include <glissade/fe/gauss_rule.h>
#include <glissade/fe/hermite_space.h>

#include <cmath>
#include <map>
#include <set>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using Vector2 = HermiteQuadrilateral::Vector;

    Vector2
    to_array(const Tensor<1, 2> &t)
    {
      return {{t[0], t[1]}};
    }

    /**
     * Shape functions of the Hermite space at quadrature points, computed by
     * HermiteQuadrilateral for the cell's stored geometry.
     */
    class HermiteEvaluator : public CellEvaluator
    {
    public:
      HermiteEvaluator(const HermiteSpace &space, const unsigned int n_points)
        : space(space)
        , cell_rule(tensor_gauss_rule(n_points))
        , line_rule(gauss_legendre_rule(n_points))
      {}

      void
      reinit(const CellIterator &cell) override
      {
        const HermiteQuadrilateral &element =
          space.element(cell->active_cell_index());
        values.resize(cell_rule.size());
        weights.resize(cell_rule.size());
        for (unsigned int q = 0; q < cell_rule.size(); ++q)
          {
            values[q]  = element.evaluate(cell_rule[q].xi, cell_rule[q].eta);
            weights[q] = values[q].jacobian_determinant * cell_rule[q].weight;
          }
      }

      void
      reinit(const CellIterator &cell, const unsigned int face) override
      {
        evaluate_on_edge(cell,
                         HermiteQuadrilateral::edge_from_dealii_face(face).edge,
                         line_rule.points,
                         line_rule.weights);
      }

      /** Values, weights |dX/ds| w and outward normals at points s_q. */
      void
      evaluate_on_edge(const CellIterator        &cell,
                       const unsigned int         edge,
                       const std::vector<double> &points,
                       const std::vector<double> &point_weights)
      {
        const HermiteQuadrilateral &element =
          space.element(cell->active_cell_index());
        const Vector2 direction =
          HermiteQuadrilateral::edge_reference_direction(edge);
        const unsigned int n = points.size();
        values.resize(n);
        weights.resize(n);
        normals.resize(n);
        for (unsigned int q = 0; q < n; ++q)
          {
            const Vector2 ref =
              HermiteQuadrilateral::edge_reference_point(edge, points[q]);
            values[q]       = element.evaluate(ref[0], ref[1]);
            const auto  &J  = values[q].jacobian;
            const double tx = J[0][0] * direction[0] + J[0][1] * direction[1];
            const double ty = J[1][0] * direction[0] + J[1][1] * direction[1];
            const double length = std::hypot(tx, ty);
            weights[q]          = length * point_weights[q];
            // Edges run counterclockwise: the outward normal is the tangent
            // turned clockwise.
            normals[q] = Tensor<1, 2>({ty / length, -tx / length});
          }
      }

      void
      reinit_at(const CellIterator &cell,
                const unsigned int  face,
                const double        fraction) override
      {
        const auto edge_of_face =
          HermiteQuadrilateral::edge_from_dealii_face(face);
        const double s =
          edge_of_face.reversed ? 1. - 2. * fraction : 2. * fraction - 1.;
        evaluate_on_edge(cell, edge_of_face.edge, {s}, {1.});
        weights[0] = 1.;
      }

      unsigned int
      n_quadrature_points() const override
      {
        return values.size();
      }

      unsigned int
      dofs_per_cell() const override
      {
        return space.finite_element().n_dofs_per_cell();
      }

      unsigned int
      displacement_component(const unsigned int i) const override
      {
        return space.local_dof(i).first;
      }

      double
      shape_value(const unsigned int i, const unsigned int q) const override
      {
        return values[q].shape_values[space.local_dof(i).second];
      }

      Tensor<1, 2>
      shape_grad(const unsigned int i, const unsigned int q) const override
      {
        const auto &g = values[q].shape_gradients[space.local_dof(i).second];
        return Tensor<1, 2>({g[0], g[1]});
      }

      double
      JxW(const unsigned int q) const override
      {
        return weights[q];
      }

      Point<2>
      quadrature_point(const unsigned int q) const override
      {
        return Point<2>(values[q].point[0], values[q].point[1]);
      }

      Tensor<1, 2>
      normal_vector(const unsigned int q) const override
      {
        return normals[q];
      }

    private:
      const HermiteSpace                            &space;
      const std::vector<QuadraturePoint2D>           cell_rule;
      const GaussLegendreRule                        line_rule;
      std::vector<HermiteQuadrilateral::PointValues> values;
      std::vector<double>                            weights;
      std::vector<Tensor<1, 2>>                      normals;
    };
  } // namespace



  HermiteSpace::HermiteSpace()
    : numbering(FE_Q<2>(1), 6)
    , output_mapping(1)
  {
    for (unsigned int i = 0; i < numbering.n_dofs_per_cell(); ++i)
      {
        const auto [component, vertex] = numbering.system_to_component_index(i);
        const unsigned int node =
          HermiteQuadrilateral::node_from_dealii_vertex(vertex);
        local_dofs.emplace_back(component / 3, 3 * node + component % 3);
      }
  }



  void
  HermiteSpace::setup(const DoFHandler<2> &dof_handler,
                      AffineConstraints<double> &)
  {
    // The geometry of each cell: its vertices and, at each, the derivatives
    // dX/dxi and dX/deta of the manifold's chart (half the tangent of the
    // geodesic to the neighbour along xi or eta; deal.II's unit cell is
    // [0,1]^2 and ours [-1,1]^2).
    elements.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Manifold<2> &manifold = cell->get_manifold();
        std::array<HermiteQuadrilateral::NodeGeometry, 4> nodes;
        for (unsigned int v = 0; v < 4; ++v)
          {
            const unsigned int v_xi  = v ^ 1; // neighbour along xi
            const unsigned int v_eta = v ^ 2; // neighbour along eta
            const double       s_xi  = (v & 1) ? -0.5 : 0.5;
            const double       s_eta = (v & 2) ? -0.5 : 0.5;
            auto              &node =
              nodes[HermiteQuadrilateral::node_from_dealii_vertex(v)];
            node.point = to_array(cell->vertex(v));
            node.tangent_xi =
              to_array(s_xi * manifold.get_tangent_vector(cell->vertex(v),
                                                          cell->vertex(v_xi)));
            node.tangent_eta = to_array(
              s_eta * manifold.get_tangent_vector(cell->vertex(v),
                                                  cell->vertex(v_eta)));
          }
        elements.emplace_back(nodes);
      }
  }



  void
  HermiteSpace::attach(const DoFHandler<2> &distributed)
  {
    AffineConstraints<double> none;
    setup(distributed, none);
  }



  std::unique_ptr<CellEvaluator>
  HermiteSpace::create_evaluator(const unsigned int points_per_direction) const
  {
    return std::make_unique<HermiteEvaluator>(
      *this, points_per_direction > 0 ? points_per_direction : 3);
  }



  void
  HermiteSpace::boundary_relations(const DoFHandler<2>       &dof_handler,
                                   const types::boundary_id   boundary,
                                   const Function<2>         &g,
                                   const std::array<bool, 2> &components,
                                   const bool                 all_derivatives,
                                   std::vector<DofRelation>  &relations) const
  {
    // Per boundary vertex: its dofs, position, and the unit tangents of the
    // constrained faces that meet there (two different ones at a corner).
    struct VertexData
    {
      std::array<types::global_dof_index, 6> dofs;
      Point<2>                               X;
      std::vector<Tensor<1, 2>>              tangents;
      double                                 size;
    };
    std::map<unsigned int, VertexData>   vertices;
    std::vector<types::global_dof_index> local(numbering.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == boundary)
          {
            cell->get_dof_indices(local);
            const auto        &element = elements[cell->active_cell_index()];
            const unsigned int edge =
              HermiteQuadrilateral::edge_from_dealii_face(f).edge;
            const auto direction =
              HermiteQuadrilateral::edge_reference_direction(edge);
            for (const unsigned int node :
                 HermiteQuadrilateral::edge_nodes(edge))
              {
                const unsigned int v =
                  HermiteQuadrilateral::dealii_vertex_from_node(node);
                auto &data = vertices[cell->vertex_index(v)];
                for (unsigned int k = 0; k < 6; ++k)
                  data.dofs[k] =
                    local[numbering.component_to_system_index(k, v)];
                data.X    = cell->vertex(v);
                data.size = cell->diameter();
                const auto ref =
                  HermiteQuadrilateral::node_reference_point(node);
                const auto   J = element.jacobian(ref[0], ref[1]);
                Tensor<1, 2> t(
                  {J[0][0] * direction[0] + J[0][1] * direction[1],
                   J[1][0] * direction[0] + J[1][1] * direction[1]});
                t /= t.norm();
                bool known = false;
                for (const auto &other : data.tangents)
                  known = known ||
                          std::abs(other[0] * t[1] - other[1] * t[0]) < 1e-10;
                if (!known)
                  data.tangents.push_back(t);
              }
          }

    for (const auto &[index, data] : vertices)
      for (unsigned int c = 0; c < 2; ++c)
        {
          if (!components[c])
            continue;
          // grad g by a fourth-order central difference: exact for the
          // polynomial data of patch tests up to round-off.
          const double h = 1e-3 * data.size;
          Tensor<1, 2> grad;
          for (unsigned int d = 0; d < 2; ++d)
            {
              Tensor<1, 2> e;
              e[d]          = h;
              const auto at = [&](const double k) {
                return g.value(Point<2>(data.X + k * e), c);
              };
              grad[d] = (-at(2) + 8 * at(1) - 8 * at(-1) + at(-2)) / (12 * h);
            }
          const auto value_dof = data.dofs[3 * c];
          const auto dx_dof    = data.dofs[3 * c + 1];
          const auto dy_dof    = data.dofs[3 * c + 2];
          relations.push_back({value_dof, {}, g.value(data.X, c)});
          if (all_derivatives || data.tangents.size() >= 2)
            {
              // Two independent tangents (a corner) fix the whole gradient.
              relations.push_back({dx_dof, {}, grad[0]});
              relations.push_back({dy_dof, {}, grad[1]});
            }
          else if (data.tangents.size() == 1)
            {
              // t_x du/dx + t_y du/dy = t . grad g, solved for the dof with
              // the larger coefficient.
              const Tensor<1, 2> &t      = data.tangents[0];
              const double        target = t * grad;
              if (std::abs(t[0]) >= std::abs(t[1]))
                relations.push_back(
                  {dx_dof, {{dy_dof, t[1] / t[0]}}, target / t[0]});
              else
                relations.push_back(
                  {dy_dof, {{dx_dof, t[0] / t[1]}}, target / t[1]});
            }
        }
  }



  void
  HermiteSpace::symmetry_relations(const DoFHandler<2>      &dof_handler,
                                   const types::boundary_id  boundary,
                                   const unsigned int        normal,
                                   std::vector<DofRelation> &relations) const
  {
    // Node dofs 3 c, 3 c + 1, 3 c + 2: u_c, d u_c / dx, d u_c / dy; the
    // tangential component's derivative along the normal is 3 t + 1 + n.
    const unsigned int                   tangential = 1 - normal;
    const unsigned int                   k = 3 * tangential + 1 + normal;
    std::vector<types::global_dof_index> local(numbering.n_dofs_per_cell());
    std::set<types::global_dof_index>    held;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == boundary)
          {
            cell->get_dof_indices(local);
            for (const unsigned int v : {0u, 1u})
              held.insert(local[numbering.component_to_system_index(
                k, GeometryInfo<2>::face_to_cell_vertices(f, v))]);
          }
    for (const auto dof : held)
      relations.push_back({dof, {}, 0.});
  }
} // namespace glissade
