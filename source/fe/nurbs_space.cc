// The NURBS element space (include/glissade/fe/nurbs_space.h).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>

#include <glissade/base/input_error.h>
#include <glissade/fe/nurbs_space.h>
#include <glissade/mesh/process_mesh.h>

#include <cmath>
#include <set>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** Where on a cell's span a deal.II face lies: the parameter it fixes
     *  (0: u, 1: v) and at which end (0: low, 1: high). */
    std::array<unsigned int, 2>
    fixed_parameter_of_face(const unsigned int face)
    {
      return {{face / 2, face % 2}};
    }

    /**
     * The rational functions of one span at the points a reinit asks for:
     * physical gradients by the inverse Jacobian, JxW from the parametric
     * measure.
     */
    class NurbsEvaluator : public CellEvaluator
    {
    public:
      NurbsEvaluator(const NurbsSpace &space, const unsigned int n_points)
        : space(space)
        , rule(n_points)
      {}

      void
      reinit(const CellIterator &cell) override
      {
        const auto [u, v] = ranges(cell);
        resize(rule.size() * rule.size());
        for (unsigned int j = 0, q = 0; j < rule.size(); ++j)
          for (unsigned int i = 0; i < rule.size(); ++i, ++q)
            {
              const double s = rule.point(i)[0], t = rule.point(j)[0];
              evaluate_at(cell,
                          q,
                          u[0] + s * (u[1] - u[0]),
                          v[0] + t * (v[1] - v[0]));
              JxW_values[q] = determinant(jacobians[q]) * rule.weight(i) *
                              rule.weight(j) * (u[1] - u[0]) * (v[1] - v[0]);
            }
      }

      void
      reinit(const CellIterator &cell, const unsigned int face) override
      {
        resize(rule.size());
        for (unsigned int q = 0; q < rule.size(); ++q)
          face_point(cell, face, q, rule.point(q)[0], rule.weight(q));
      }

      void
      reinit_at(const CellIterator &cell,
                const unsigned int  face,
                const double        fraction) override
      {
        resize(1);
        face_point(cell, face, 0, fraction, 1.);
        JxW_values[0] = 1.;
      }

      unsigned int
      n_quadrature_points() const override
      {
        return JxW_values.size();
      }
      unsigned int
      dofs_per_cell() const override
      {
        return 2 * n_functions();
      }
      unsigned int
      displacement_component(const unsigned int i) const override
      {
        return i % 2;
      }
      double
      shape_value(const unsigned int i, const unsigned int q) const override
      {
        return values[q][i / 2];
      }
      Tensor<1, 2>
      shape_grad(const unsigned int i, const unsigned int q) const override
      {
        return gradients[q][i / 2];
      }
      double
      JxW(const unsigned int q) const override
      {
        return JxW_values[q];
      }
      Point<2>
      quadrature_point(const unsigned int q) const override
      {
        return points[q];
      }
      Tensor<1, 2>
      normal_vector(const unsigned int q) const override
      {
        return normals[q];
      }

    private:
      const NurbsSpace                      &space;
      const QGauss<1>                        rule;
      NurbsPatch::Evaluation                 evaluation;
      std::vector<std::vector<double>>       values;
      std::vector<std::vector<Tensor<1, 2>>> gradients;
      std::vector<Tensor<2, 2>>              jacobians;
      std::vector<double>                    JxW_values;
      std::vector<Point<2>>                  points;
      std::vector<Tensor<1, 2>>              normals;

      unsigned int
      n_functions() const
      {
        const unsigned int p = space.polynomial_degree();
        return (p + 1) * (p + 1);
      }

      std::array<std::array<double, 2>, 2>
      ranges(const CellIterator &cell) const
      {
        const unsigned int k     = cell->active_cell_index();
        const auto        &span  = space.span_of(k).span;
        const NurbsPatch  &patch = space.patch_of(k);
        return {{patch.xi.span_range(span[0]), patch.eta.span_range(span[1])}};
      }

      void
      resize(const unsigned int n)
      {
        values.resize(n);
        gradients.resize(n);
        jacobians.resize(n);
        JxW_values.resize(n);
        points.resize(n);
        normals.assign(n, Tensor<1, 2>());
      }

      void
      evaluate_at(const CellIterator &cell,
                  const unsigned int  q,
                  const double        u,
                  const double        v)
      {
        const unsigned int k    = cell->active_cell_index();
        const auto        &span = space.span_of(k).span;
        space.patch_of(k).evaluate(span[0], span[1], u, v, evaluation);
        points[q]                    = evaluation.point;
        jacobians[q]                 = evaluation.jacobian;
        const Tensor<2, 2> inverse_t = transpose(invert(evaluation.jacobian));
        values[q]                    = evaluation.values;
        gradients[q].resize(evaluation.values.size());
        for (unsigned int k = 0; k < evaluation.values.size(); ++k)
          gradients[q][k] = inverse_t * evaluation.parametric_gradients[k];
      }

      /** Point q of face f at `fraction` along it, with weight w. */
      void
      face_point(const CellIterator &cell,
                 const unsigned int  face,
                 const unsigned int  q,
                 const double        fraction,
                 const double        w)
      {
        const auto range             = ranges(cell);
        const auto [fixed, at_end]   = fixed_parameter_of_face(face);
        const unsigned int    moving = 1 - fixed;
        std::array<double, 2> parameter;
        parameter[fixed] = range[fixed][at_end];
        parameter[moving] =
          range[moving][0] + fraction * (range[moving][1] - range[moving][0]);
        evaluate_at(cell, q, parameter[0], parameter[1]);
        Tensor<1, 2> along;
        for (unsigned int d = 0; d < 2; ++d)
          along[d] = jacobians[q][d][moving];
        JxW_values[q] =
          along.norm() * w * (range[moving][1] - range[moving][0]);
        // The outward normal: the fixed parameter's gradient, pointing out.
        Tensor<1, 2> reference;
        reference[fixed]     = at_end ? 1. : -1.;
        const Tensor<1, 2> n = transpose(invert(jacobians[q])) * reference;
        normals[q]           = n / n.norm();
      }
    };
  } // namespace



  NurbsSpace::NurbsSpace(const unsigned int degree)
    : degree(degree)
    , numbering(FE_Q<2>(degree), 2)
  {}



  ElementSpace::Capabilities
  NurbsSpace::capabilities() const
  {
    Capabilities c;
    c.dofs_are_nodal_values = false;
    c.needs_exact_patch     = true;
    return c;
  }



  void
  NurbsSpace::use_patches(const NurbsMultipatch &exact_geometry)
  {
    for (const auto &patch : exact_geometry.patches)
      AssertThrow(patch.xi.degree() == degree && patch.eta.degree() == degree,
                  ExcMessage("a patch is not of the space's degree"));
    geometry  = exact_geometry;
    has_patch = true;
  }



  void
  NurbsSpace::place_vertices(Triangulation<2> &mesh) const
  {
    AssertThrow(mesh.n_active_cells() == geometry.n_cells(),
                ExcMessage("the mesh's cells are not the patches' elements"));
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const auto [i, span]    = geometry.cell_span(cell->active_cell_index());
        const NurbsPatch &patch = geometry.patches[i];
        const auto        u     = patch.xi.span_range(span[0]);
        const auto        v     = patch.eta.span_range(span[1]);
        for (const unsigned int vertex : cell->vertex_indices())
          cell->vertex(vertex) =
            patch.point(span[0], span[1], u[vertex % 2], v[vertex / 2]);
      }
  }



  void
  NurbsSpace::setup(const DoFHandler<2>       &dof_handler,
                    AffineConstraints<double> &element_constraints)
  {
    AssertThrow(has_patch, ExcMessage("a NURBS body needs its patch first"));
    AssertThrow(dof_handler.get_triangulation().n_active_cells() ==
                  geometry.n_cells(),
                ExcMessage("the mesh's cells are not the patches' elements"));

    // The control points numbered into the dofs of each component, in
    // order; the dofs left over are constrained to zero. (On the whole
    // mesh: a share of it, attach(), numbers its dofs alike.)
    std::array<std::set<types::global_dof_index>, 2> component_dofs;
    std::vector<types::global_dof_index> local(numbering.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          component_dofs[numbering.system_to_component_index(i).first].insert(
            local[i]);
      }
    const unsigned int n_controls = geometry.n_controls();
    AssertThrow(component_dofs[0].size() >= n_controls,
                ExcMessage("fewer numbering dofs than control points"));
    control_dofs.assign(n_controls, {{0, 0}});
    for (unsigned int c = 0; c < 2; ++c)
      {
        auto dof = component_dofs[c].begin();
        for (unsigned int A = 0; A < n_controls; ++A, ++dof)
          control_dofs[A][c] = *dof;
        for (; dof != component_dofs[c].end(); ++dof)
          element_constraints.add_line(*dof);
      }
    element_constraints.close();
    place_cells(dof_handler);
  }



  void
  NurbsSpace::attach(const DoFHandler<2> &distributed)
  {
    place_cells(distributed);
    std::lock_guard<std::mutex> lock(trace_mutex);
    traces.clear();
  }



  void
  NurbsSpace::place_cells(const DoFHandler<2> &dof_handler)
  {
    // A cell is the patches' element of its number in the whole mesh
    // (NurbsMultipatch::cell_span), which the mesh types that have an
    // exact patch guarantee; checked at every corner.
    const auto &mesh = dof_handler.get_triangulation();
    double      size = 0.;
    for (const auto &v : mesh.get_vertices())
      size = std::max(size, v.norm());
    spans.resize(mesh.n_active_cells());
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const unsigned int k    = cell->active_cell_index();
        spans[k]                = geometry.cell_span(serial_cell_index(cell));
        const NurbsPatch &patch = patch_of(k);
        const auto       &span  = spans[k].span;
        const auto        u     = patch.xi.span_range(span[0]);
        const auto        v     = patch.eta.span_range(span[1]);
        for (const unsigned int vertex : cell->vertex_indices())
          {
            const Point<2> X =
              patch.point(span[0], span[1], u[vertex % 2], v[vertex / 2]);
            AssertThrow((X - cell->vertex(vertex)).norm() <=
                          1e-9 * std::max(size, 1.),
                        ExcMessage("cell " + std::to_string(k) +
                                   " is not the patch's element there"));
          }
      }

    // The output's nodes: FE_Q(p)'s support points mapped to each span's
    // parameters (a node on an edge gets the same point from both of its
    // cells, checked: across a join of patches too), placed on the patch.
    const auto &unit_points = numbering.get_unit_support_points();
    std::vector<types::global_dof_index> local(numbering.n_dofs_per_cell());
    support_parameters.assign(mesh.n_active_cells(), {});
    support_positions.reinit(dof_handler.n_dofs());
    std::vector<bool> placed(dof_handler.n_dofs(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int k     = cell->active_cell_index();
        const NurbsPatch  &patch = patch_of(k);
        const auto        &span  = spans[k].span;
        const auto         u     = patch.xi.span_range(span[0]);
        const auto         v     = patch.eta.span_range(span[1]);
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < unit_points.size(); ++i)
          {
            const std::array<double, 2> s = {
              {u[0] + unit_points[i][0] * (u[1] - u[0]),
               v[0] + unit_points[i][1] * (v[1] - v[0])}};
            support_parameters[k].push_back(s);
            const double x =
              patch.point(span[0],
                          span[1],
                          s[0],
                          s[1])[numbering.system_to_component_index(i).first];
            AssertThrow(!placed[local[i]] ||
                          std::abs(support_positions[local[i]] - x) <=
                            1e-9 * std::max(size, 1.),
                        ExcMessage("an output node of cell " +
                                   std::to_string(k) +
                                   " is not its neighbour's"));
            support_positions[local[i]] = x;
            placed[local[i]]            = true;
          }
      }
    output_mapping =
      std::make_unique<MappingFEField<2, 2, Vector<double>>>(dof_handler,
                                                             support_positions);
  }



  std::unique_ptr<CellEvaluator>
  NurbsSpace::create_evaluator(const unsigned int points_per_direction) const
  {
    return std::make_unique<NurbsEvaluator>(
      *this, points_per_direction > 0 ? points_per_direction : degree + 1);
  }



  void
  NurbsSpace::cell_dof_indices(
    const DoFHandler<2>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>      &indices) const
  {
    const unsigned int cell_index = cell->active_cell_index();
    const auto        &span       = spans[cell_index].span;
    const NurbsPatch  &patch      = patch_of(cell_index);
    const unsigned int a0         = patch.xi.first_function(span[0]);
    const unsigned int b0         = patch.eta.first_function(span[1]);
    indices.resize(2 * (degree + 1) * (degree + 1));
    for (unsigned int j = 0, k = 0; j <= degree; ++j)
      for (unsigned int i = 0; i <= degree; ++i, ++k)
        {
          const unsigned int A = patch.unique_control(a0 + i, b0 + j);
          indices[2 * k]       = control_dofs[A][0];
          indices[2 * k + 1]   = control_dofs[A][1];
        }
  }



  const NurbsSpace::Trace &
  NurbsSpace::trace(const DoFHandler<2>     &dof_handler,
                    const types::boundary_id boundary) const
  {
    std::lock_guard<std::mutex> lock(trace_mutex);
    const auto                  found = traces.find(boundary);
    if (found != traces.end())
      return found->second;
    // On a side of the patch only the side's row of control points has
    // nonzero functions (open knot vectors): on face f of a cell, the row
    // i = 0 or p (faces 0, 1) or j = 0 or p (faces 2, 3).
    Trace                                t;
    std::map<unsigned int, unsigned int> position;
    NurbsEvaluator                       evaluator(*this, 2 * degree + 2);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == boundary)
          {
            const auto       &span     = spans[cell->active_cell_index()].span;
            const NurbsPatch &patch    = patch_of(cell->active_cell_index());
            const auto [fixed, at_end] = fixed_parameter_of_face(f);
            std::vector<unsigned int> local;
            for (unsigned int j = 0; j <= degree; ++j)
              for (unsigned int i = 0; i <= degree; ++i)
                if ((fixed == 0 ? i : j) == (at_end ? degree : 0))
                  local.push_back(i + (degree + 1) * j);
            std::vector<unsigned int> face_controls;
            for (const unsigned int k : local)
              {
                const unsigned int A = patch.unique_control(
                  patch.xi.first_function(span[0]) + k % (degree + 1),
                  patch.eta.first_function(span[1]) + k / (degree + 1));
                face_controls.push_back(A);
                if (position.emplace(A, t.controls.size()).second)
                  t.controls.push_back(A);
              }
            evaluator.reinit(cell, f);
            for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
              {
                Trace::Point point{evaluator.quadrature_point(q),
                                   evaluator.JxW(q),
                                   {}};
                for (unsigned int m = 0; m < local.size(); ++m)
                  point.values.emplace_back(position[face_controls[m]],
                                            evaluator.shape_value(2 * local[m],
                                                                  q));
                t.points.push_back(std::move(point));
              }
          }
    const unsigned int n = t.controls.size();
    FullMatrix<double> mass(n, n);
    for (const auto &point : t.points)
      for (const auto &[a, value_a] : point.values)
        for (const auto &[b, value_b] : point.values)
          mass(a, b) += value_a * value_b * point.weight;
    if (n > 0)
      mass.gauss_jordan();
    t.inverse_mass          = mass;
    return traces[boundary] = std::move(t);
  }



  void
  NurbsSpace::boundary_relations(const DoFHandler<2>       &dof_handler,
                                 const types::boundary_id   boundary,
                                 const Function<2>         &g,
                                 const std::array<bool, 2> &components,
                                 const bool,
                                 std::vector<DofRelation> &relations) const
  {
    const Trace       &t = trace(dof_handler, boundary);
    const unsigned int n = t.controls.size();
    for (unsigned int c = 0; c < 2; ++c)
      if (components[c])
        {
          Vector<double> moments(n), coefficients(n);
          for (const auto &point : t.points)
            {
              const double value = g.value(point.X, c) * point.weight;
              for (const auto &[a, value_a] : point.values)
                moments[a] += value * value_a;
            }
          t.inverse_mass.vmult(coefficients, moments);
          for (unsigned int a = 0; a < n; ++a)
            relations.push_back(
              {control_dofs[t.controls[a]][c], {}, coefficients[a]});
        }
  }



  void
  NurbsSpace::nodal_values(const DoFHandler<2>  &dof_handler,
                           const Vector<double> &coefficients,
                           Vector<double>       &nodal) const
  {
    nodal.reinit(dof_handler.n_dofs());
    std::vector<types::global_dof_index> local(numbering.n_dofs_per_cell());
    NurbsPatch::Evaluation               e;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int k = cell->active_cell_index();
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const unsigned int c = numbering.system_to_component_index(i).first;
            const auto        &s = support_parameters[k][i];
            patch_of(k).evaluate(
              spans[k].span[0], spans[k].span[1], s[0], s[1], e);
            double value = 0.;
            for (unsigned int m = 0; m < e.controls.size(); ++m)
              value +=
                e.values[m] * coefficients(control_dofs[e.controls[m]][c]);
            nodal(local[i]) = value;
          }
      }
  }



  std::vector<ElementSpace::InterpolationPoint>
  NurbsSpace::interpolation_points() const
  {
    std::vector<InterpolationPoint> points;
    const auto                      positions = geometry.control_points();
    for (unsigned int A = 0; A < positions.size(); ++A)
      for (unsigned int c = 0; c < 2; ++c)
        points.push_back({control_dofs[A][c], c, positions[A]});
    return points;
  }



  unsigned int
  NurbsSpace::n_unknowns(const DoFHandler<2> &) const
  {
    return 2 * geometry.n_controls();
  }
} // namespace glissade
