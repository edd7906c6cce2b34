#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/base/user_function.h>
#include <glissade/body/boundary_conditions.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/mesh/boundary_normals.h>
#include <glissade/mesh/mesh_diameter.h>
#include <glissade/mesh/nearest_vertex.h>
#include <glissade/mesh/process_mesh.h>

#include <cmath>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** u(X) = R(angle(t)) (X - c) + c - X: a rigid rotation about c. */
    class RigidRotation : public Function<2>
    {
    public:
      RigidRotation(const Point<2>    &center,
                    const std::string &angle,
                    const std::string &entry)
        : Function<2>(2)
        , center(center)
        , angle(1)
        , angle_expression(angle)
        , entry(entry)
      {
        this->angle.initialize("x,y,t", {angle}, {{"pi", numbers::PI}}, true);
      }

      double
      value(const Point<2> &X, const unsigned int component) const override
      {
        angle.set_time(this->get_time());
        const double a = checked_user_value(
          angle.value(X), entry, angle_expression, this->get_time(), X);
        const Tensor<1, 2> d       = X - center;
        const double       rotated = component == 0 ?
                                       std::cos(a) * d[0] - std::sin(a) * d[1] :
                                       std::sin(a) * d[0] + std::cos(a) * d[1];
        return rotated - d[component];
      }

    private:
      const Point<2>            center;
      mutable FunctionParser<2> angle;
      const std::string         angle_expression;
      const std::string         entry;
    };

    std::shared_ptr<Function<2>>
    make_parser(const std::vector<std::string> &expressions,
                const std::string              &entry)
    {
      return std::make_shared<UserFunction>(expressions, entry);
    }
  } // namespace



  Location
  BoundaryConditions::resolve(const std::string      &location,
                              const BoundaryNames    &boundary_names,
                              const Triangulation<2> &triangulation,
                              const std::string      &body_name,
                              const std::string      &entry,
                              const bool              allow_face_point,
                              const double            known_diameter)
  {
    Location result;
    double   x, y;
    if (text::parse_point_location(location, x, y))
      {
        result.is_vertex     = true;
        result.point         = Point<2>(x, y);
        const auto &vertices = triangulation.get_vertices();
        const auto  used     = triangulation.get_used_vertices();
        const auto [best_v, best] =
          nearest_vertex(vertices, result.point, &used);
        // The diameter walks the boundary: callers that resolve many
        // points pass it.
        const double size =
          known_diameter > 0. ? known_diameter : mesh_diameter(triangulation);
        if (best > 1e-8 * size && allow_face_point)
          for (const auto &cell : triangulation.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() != cut_boundary_id)
                {
                  const Point<2>     a = cell->face(f)->vertex(0);
                  const Tensor<1, 2> d = cell->face(f)->vertex(1) - a;
                  const double       fraction =
                    (result.point - a) * d / d.norm_square();
                  const double distance =
                    (result.point - (a + fraction * d)).norm();
                  if (fraction >= 0. && fraction <= 1. &&
                      distance <= 1e-8 * size)
                    {
                      result.is_vertex  = false;
                      result.on_face    = true;
                      result.cell_index = cell->active_cell_index();
                      result.face       = f;
                      result.fraction   = fraction;
                      return result;
                    }
                }
        if (best > 1e-8 * size)
          {
            std::ostringstream message;
            message << "point(" << x << ", " << y
                    << ") is not a vertex of the mesh of body '" << body_name
                    << "'"
                    << (allow_face_point ? " nor on a straight boundary face" :
                                           "")
                    << " (the nearest vertex is at " << vertices[best_v] << ")";
            throw InputError(entry, message.str());
          }
        result.vertex = best_v;
        return result;
      }

    const auto named = boundary_names.find(text::trim(location));
    if (named == boundary_names.end())
      {
        std::string known;
        for (const auto &n : boundary_names)
          known += (known.empty() ? "" : ", ") + n.first;
        throw InputError(entry,
                         "the mesh of body '" + body_name +
                           "' has no boundary named '" + location +
                           "' (it has: " + (known.empty() ? "none" : known) +
                           "; or use point(x, y))");
      }
    const auto ids = triangulation.get_boundary_ids();
    if (std::find(ids.begin(), ids.end(), named->second) == ids.end())
      throw InputError(entry,
                       "boundary '" + location + "' of body '" + body_name +
                         "' has no faces in the mesh");
    result.boundary = named->second;
    return result;
  }



  void
  BoundaryConditions::locate_on_boundary_face(Location               &where,
                                              const Triangulation<2> &tria,
                                              const std::string      &body_name,
                                              const std::string      &entry)
  {
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (const unsigned int v : {0u, 1u})
            if (cell->face(f)->vertex_index(v) == where.vertex)
              {
                where.on_face    = true;
                where.cell_index = cell->active_cell_index();
                where.face       = f;
                where.fraction   = v;
                return;
              }
    std::ostringstream message;
    message << "point(" << where.point[0] << ", " << where.point[1]
            << ") is inside body '" << body_name
            << "', whose dofs are control points, not nodes: its point "
               "supports and loads act at points of its boundary";
    throw InputError(entry, message.str());
  }



  std::vector<BoundaryConditions::FunctionAtPoint>
  BoundaryConditions::functions_at_face_point(const DoFHandler<2> &dof_handler,
                                              const ElementSpace  &space,
                                              const Location      &where)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->active_cell_index() == where.cell_index)
        return functions_at_face_point(space, cell, where.face, where.fraction);
    return {};
  }



  std::vector<BoundaryConditions::FunctionAtPoint>
  BoundaryConditions::functions_at_face_point(
    const ElementSpace                                 &space,
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const unsigned int                                  face,
    const double                                        fraction)
  {
    std::vector<FunctionAtPoint> result;
    const auto                   evaluator = space.create_evaluator();
    evaluator->reinit_at(cell, face, fraction);
    std::vector<types::global_dof_index> local;
    space.cell_dof_indices(cell, local);
    for (unsigned int i = 0; i < local.size(); ++i)
      if (std::abs(evaluator->shape_value(i, 0)) > 1e-14)
        result.push_back({local[i],
                          evaluator->displacement_component(i),
                          evaluator->shape_value(i, 0)});
    return result;
  }



  const std::vector<BoundaryConditions::FunctionAtPoint> &
  BoundaryConditions::cached_functions_at(
    const ElementSpace                                 &space,
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const unsigned int                                  face,
    const double                                        fraction) const
  {
    const auto key = std::make_tuple(cell->active_cell_index(), face, fraction);
    const auto found = function_cache.find(key);
    if (found != function_cache.end())
      return found->second;
    return function_cache[key] =
             functions_at_face_point(space, cell, face, fraction);
  }



  const std::vector<BoundaryConditions::FunctionAtPoint> &
  BoundaryConditions::cached_functions_at(const DoFHandler<2> &dof_handler,
                                          const ElementSpace  &space,
                                          const Location      &where) const
  {
    const auto found = function_cache.find(
      std::make_tuple(where.cell_index, where.face, where.fraction));
    if (found != function_cache.end())
      return found->second;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->active_cell_index() == where.cell_index)
        return cached_functions_at(space, cell, where.face, where.fraction);
    static const std::vector<FunctionAtPoint> none;
    return none;
  }



  std::array<types::global_dof_index, 2>
  BoundaryConditions::cell_vertex_dofs(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const unsigned int                                  v,
    const ElementSpace                                 &space)
  {
    // System component k moves displacement component k / per_dim;
    // k % per_dim == 0 is the nodal value, the rest derivatives.
    const FiniteElement<2> &fe      = cell->get_fe();
    const unsigned int      per_dim = space.components_per_displacement();
    std::array<types::global_dof_index, 2> dofs;
    for (unsigned int k = 0; k < fe.n_dofs_per_vertex(); ++k)
      {
        const unsigned int local = v * fe.n_dofs_per_vertex() + k;
        const unsigned int component =
          fe.system_to_component_index(local).first;
        if (component % per_dim == 0)
          dofs[component / per_dim] = cell->vertex_dof_index(v, k);
      }
    return dofs;
  }



  std::array<types::global_dof_index, 2>
  BoundaryConditions::vertex_dofs(const DoFHandler<2> &dof_handler,
                                  const ElementSpace  &space,
                                  const unsigned int   vertex)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex_index(v) == vertex)
          return cell_vertex_dofs(cell, v, space);
    Assert(false, ExcInternalError());
    return {};
  }



  std::array<types::global_dof_index, 2>
  BoundaryConditions::cached_vertex_dofs(const DoFHandler<2> &dof_handler,
                                         const ElementSpace  &space,
                                         const unsigned int   vertex) const
  {
    const auto found = vertex_dof_cache.find(vertex);
    if (found != vertex_dof_cache.end())
      return found->second;
    return vertex_dof_cache[vertex] = vertex_dofs(dof_handler, space, vertex);
  }



  BoundaryConditions::BoundaryConditions(const BodyDescription  &body,
                                         const ElementSpace     &space,
                                         const BoundaryNames    &names,
                                         const Triangulation<2> &tria)
  {
    // A space whose dofs are not nodal values (NURBS: control points)
    // has no dof at a vertex: a point it is held or loaded at is a point
    // of a boundary face, where its functions give the displacement.
    const bool nodal = space.capabilities().dofs_are_nodal_values;
    vertex_has_dofs  = nodal;
    // The entries name their file already ("scene.prm: Body b/...").
    for (const auto &d : body.dirichlet)
      {
        DirichletItem item;
        item.where = resolve(d.location, names, tria, body.name, d.entry);
        if (!nodal && item.where.is_vertex)
          locate_on_boundary_face(item.where, tria, body.name, d.entry);
        item.components      = {{d.x_component, d.y_component}};
        item.all_derivatives = d.all_derivatives;
        if (d.symmetry)
          {
            item.symmetry_normal =
              symmetry_normal(item.where, tria, body.name, d.entry);
            item.components[item.symmetry_normal] = true;
          }
        if (d.direction != DirichletDescription::Direction::cartesian)
          {
            if (!space.capabilities().vertex_dofs_only)
              throw InputError(
                d.entry,
                "the normal (n) and tangential (t) supports are implemented "
                "for spaces whose dofs are the vertices' alone (" +
                  ElementSpaceRegistry::names_that(
                    [](const ElementSpace::Capabilities &c) {
                      return c.vertex_dofs_only;
                    }) +
                  "); body '" + body.name + "' uses " + space.name() +
                  " (use x, y or a rotated mesh)");
            item.directed_vertices = support_directions(
              item.where, d.direction, tria, body.name, d.entry);
          }
        switch (d.kind)
          {
            case DirichletDescription::Kind::fixed:
              item.displacement =
                std::make_shared<Functions::ZeroFunction<2>>(2);
              break;
            case DirichletDescription::Kind::displacement:
              {
                std::vector<std::string> both;
                unsigned int             next = 0;
                both.push_back(d.x_component ? d.expressions[next++] : "0");
                both.push_back(d.y_component ? d.expressions[next++] : "0");
                item.displacement = make_parser(both, d.entry);
                break;
              }
            case DirichletDescription::Kind::rotation:
              item.displacement =
                std::make_shared<RigidRotation>(d.rotation_center,
                                                d.angle_expression,
                                                d.entry);
              break;
          }
        dirichlet_items.push_back(item);
      }

    for (const auto &n : body.neumann)
      {
        Location where =
          resolve(n.location,
                  names,
                  tria,
                  body.name,
                  n.entry,
                  n.kind == NeumannDescription::Kind::point_load);
        if (!nodal && where.is_vertex)
          locate_on_boundary_face(where, tria, body.name, n.entry);
        if (n.kind == NeumannDescription::Kind::point_load)
          point_loads.push_back({where, make_parser(n.expressions, n.entry)});
        else if (n.kind == NeumannDescription::Kind::nodal_loads)
          nodal_loads.push_back({where, make_parser(n.expressions, n.entry)});
        else
          loads_on_boundaries.push_back(
            {where.boundary,
             n.kind == NeumannDescription::Kind::pressure,
             make_parser(n.expressions, n.entry)});
      }
  }



  std::vector<std::pair<unsigned int, Tensor<1, 2>>>
  BoundaryConditions::support_directions(
    const Location                       &where,
    const DirichletDescription::Direction direction,
    const Triangulation<2>               &tria,
    const std::string                    &body_name,
    const std::string                    &entry)
  {
    // The outward normal at a boundary vertex: the sum of the unit outward
    // normals of its faces on that boundary (on any boundary for a point).
    std::map<unsigned int, Tensor<1, 2>> normal =
      boundary_vertex_normals(tria, [&where](const types::boundary_id id) {
        return where.is_vertex || id == where.boundary;
      });
    if (where.is_vertex)
      {
        const auto at_vertex = normal.find(where.vertex);
        std::map<unsigned int, Tensor<1, 2>> only;
        if (at_vertex != normal.end())
          only.insert(*at_vertex);
        normal = only;
      }
    std::vector<std::pair<unsigned int, Tensor<1, 2>>> directions;
    for (const auto &[vertex, n] : normal)
      {
        if (!(n.norm() > 1e-12))
          throw InputError(entry,
                           "body '" + body_name +
                             "': the boundary normal at a node is undefined "
                             "(a cusp); give x or y there");
        const Tensor<1, 2> unit = n / n.norm();
        directions.emplace_back(vertex,
                                direction ==
                                    DirichletDescription::Direction::normal ?
                                  unit :
                                  Tensor<1, 2>({-unit[1], unit[0]}));
      }
    if (directions.empty())
      throw InputError(entry,
                       "body '" + body_name +
                         "': a normal or tangential support needs a point on "
                         "the boundary");
    return directions;
  }



  int
  BoundaryConditions::symmetry_normal(const Location         &where,
                                      const Triangulation<2> &tria,
                                      const std::string      &body_name,
                                      const std::string      &entry)
  {
    // Every face of the boundary along x (normal y), or every one along y
    // (normal x), all on one line.
    const std::string what = "body '" + body_name + "': a symmetry line ";
    if (where.is_vertex)
      throw InputError(entry, what + "is a boundary, not a point");
    int    normal = -1;
    double level = 0., size = 0.;
    bool   straight = true, found = false;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == where.boundary)
          {
            const Point<2> a = cell->face(f)->vertex(0),
                           b = cell->face(f)->vertex(1);
            size             = std::max(size, a.distance(b));
            const int along_x =
              std::abs(a[1] - b[1]) <= 1e-10 * a.distance(b) ? 1 : 0;
            const int along_y =
              std::abs(a[0] - b[0]) <= 1e-10 * a.distance(b) ? 1 : 0;
            const int here = along_x ? 1 : along_y ? 0 : -1;
            if (!found)
              {
                normal = here;
                level  = here >= 0 ? a[here] : 0.;
                found  = true;
              }
            straight = straight && here >= 0 && here == normal &&
                       std::abs(a[here] - level) <= 1e-10 * (1. + size) &&
                       std::abs(b[here] - level) <= 1e-10 * (1. + size);
          }
    if (!found)
      throw InputError(entry, what + "needs faces on its boundary");
    if (!straight)
      throw InputError(entry,
                       what +
                         "is a straight boundary along x or y; this one is "
                         "not (a roller on another line: n)");
    return normal;
  }



  void
  BoundaryConditions::make_constraints(
    const DoFHandler<2>             &dof_handler,
    const ElementSpace              &space,
    const double                     time,
    const Vector<double>            &current_displacement,
    const AffineConstraints<double> &element_constraints,
    AffineConstraints<double>       &constraints) const
  {
    // Collect all relations first: a dof on two items (a corner shared by
    // two fixed sides) must be constrained once, the later item winning.
    std::map<types::global_dof_index, DofRelation> relations;
    for (const auto &item : dirichlet_items)
      {
        if (!item.directed_vertices.empty())
          {
            // d . u = 0: u_a + (d_b / d_a) u_b = 0, pivoting on the larger
            // component of d, or on the other one if a support of another
            // direction already holds that dof (a corner between two
            // rollers).
            for (const auto &[vertex, d] : item.directed_vertices)
              {
                const auto dofs =
                  cached_vertex_dofs(dof_handler, space, vertex);
                unsigned int a = std::abs(d[0]) >= std::abs(d[1]) ? 0 : 1;
                if (relations.count(dofs[a]) && !relations.count(dofs[1 - a]) &&
                    std::abs(d[1 - a]) > 1e-12)
                  a = 1 - a;
                const unsigned int b = 1 - a;
                DofRelation        r{dofs[a], {}, 0.};
                if (std::abs(d[b]) > 1e-14 * std::abs(d[a]))
                  r.others.push_back({dofs[b], d[b] / d[a]});
                relations[r.dof] = r;
              }
            continue;
          }
        item.displacement->set_time(time);
        std::vector<DofRelation> these;
        if (item.where.is_vertex && !vertex_has_dofs)
          {
            // sum_i N_i(X) u_i = g per component, pivoting on the largest
            // function not yet constrained by another item.
            const auto &functions =
              cached_functions_at(dof_handler, space, item.where);
            for (unsigned int c = 0; c < 2; ++c)
              if (item.components[c])
                {
                  const FunctionAtPoint *pivot = nullptr;
                  for (const auto &f : functions)
                    if (f.component == c && !relations.count(f.dof) &&
                        (pivot == nullptr ||
                         std::abs(f.value) > std::abs(pivot->value)))
                      pivot = &f;
                  AssertThrow(pivot != nullptr,
                              ExcMessage("a point support finds every "
                                         "function there held already"));
                  DofRelation r{pivot->dof,
                                {},
                                item.displacement->value(item.where.point, c) /
                                  pivot->value};
                  for (const auto &f : functions)
                    if (f.component == c && f.dof != pivot->dof)
                      r.others.emplace_back(f.dof, f.value / pivot->value);
                  these.push_back(r);
                }
          }
        else if (item.where.is_vertex)
          {
            const auto dofs =
              cached_vertex_dofs(dof_handler, space, item.where.vertex);
            const Point<2> X =
              dof_handler.get_triangulation().get_vertices()[item.where.vertex];
            for (unsigned int c = 0; c < 2; ++c)
              if (item.components[c])
                these.push_back({dofs[c], {}, item.displacement->value(X, c)});
          }
        else
          {
            space.boundary_relations(dof_handler,
                                     item.where.boundary,
                                     *item.displacement,
                                     item.components,
                                     item.all_derivatives,
                                     these);
            if (item.symmetry_normal >= 0)
              space.symmetry_relations(dof_handler,
                                       item.where.boundary,
                                       item.symmetry_normal,
                                       these);
          }
        for (const auto &r : these)
          relations[r.dof] = r;
      }

    for (const types::global_dof_index dof : axis_dofs)
      relations[dof] = DofRelation{dof, {}, 0.};

    // Two items may couple the same pair of dofs the opposite way round (a
    // Hermite node where two fixed boundaries meet: each fixes its own
    // tangential derivative, a + c_a b = v_a and b + c_b a = v_b). That is
    // a cycle, which AffineConstraints cannot close: solve the 2 x 2 system
    // instead, or keep one equation if the two are the same one.
    for (auto &[a, ra] : relations)
      if (ra.others.size() == 1)
        {
          const auto b  = ra.others[0].first;
          const auto rb = relations.find(b);
          if (rb == relations.end() || rb->second.others.size() != 1 ||
              rb->second.others[0].first != a)
            continue;
          const double c_a = ra.others[0].second;
          const double c_b = rb->second.others[0].second;
          const double v_a = ra.value, v_b = rb->second.value;
          const double det = 1. - c_a * c_b;
          if (std::abs(det) > 1e-10)
            {
              ra.value         = (v_a - c_a * v_b) / det;
              rb->second.value = v_b - c_b * ra.value;
              rb->second.others.clear();
            }
          else
            relations.erase(rb);
          ra.others.clear();
        }

    constraints.clear();
    for (const auto &line : element_constraints.get_lines())
      {
        constraints.add_line(line.index);
        constraints.add_entries(line.index, line.entries);
      }
    for (const auto &[dof, r] : relations)
      {
        // u_dof + sum c_k u_k = value, as an increment from the current
        // state: du_dof = -sum c_k du_k + (value - current combination).
        double current = current_displacement[dof];
        constraints.add_line(dof);
        for (const auto &[other, c] : r.others)
          {
            constraints.add_entry(dof, other, -c);
            current += c * current_displacement[other];
          }
        constraints.set_inhomogeneity(dof, r.value - current);
      }
    constraints.close();
  }



  std::vector<std::vector<double>>
  BoundaryConditions::support_rows(
    const DoFHandler<2>              &dof_handler,
    const ElementSpace               &space,
    const std::array<RigidMotion, 3> &basis) const
  {
    // A rigid motion as a displacement field: the space interpolates it on
    // a support exactly (it is linear), derivative dofs included.
    class MotionField : public Function<2>
    {
    public:
      explicit MotionField(const RigidMotion &motion)
        : Function<2>(2)
        , motion(motion)
      {}
      double
      value(const Point<2> &X, const unsigned int c) const override
      {
        return motion.at(X)[c];
      }

    private:
      const RigidMotion motion;
    };

    std::vector<std::vector<double>> rows;
    const auto &vertices = dof_handler.get_triangulation().get_vertices();
    for (const auto &item : dirichlet_items)
      {
        if (!item.directed_vertices.empty())
          {
            for (const auto &[vertex, d] : item.directed_vertices)
              {
                std::vector<double> row;
                for (const auto &m : basis)
                  row.push_back(d * m.at(vertices[vertex]));
                rows.push_back(row);
              }
            continue;
          }
        if (item.where.is_vertex)
          {
            for (unsigned int c = 0; c < 2; ++c)
              if (item.components[c])
                {
                  std::vector<double> row;
                  for (const auto &m : basis)
                    row.push_back(m.at(vertices[item.where.vertex])[c]);
                  rows.push_back(row);
                }
            continue;
          }
        // The same relations, in the same order, for each motion.
        std::array<std::vector<DofRelation>, 3> relations;
        for (unsigned int j = 0; j < 3; ++j)
          space.boundary_relations(dof_handler,
                                   item.where.boundary,
                                   MotionField(basis[j]),
                                   item.components,
                                   item.all_derivatives,
                                   relations[j]);
        for (unsigned int i = 0; i < relations[0].size(); ++i)
          rows.push_back({relations[0][i].value,
                          relations[1][i].value,
                          relations[2][i].value});
      }
    return rows;
  }



  void
  BoundaryConditions::add_point_loads(const DoFHandler<2> &dof_handler,
                                      const ElementSpace  &space,
                                      const double         time,
                                      Vector<double>      &forces) const
  {
    for (const auto &load : nodal_loads)
      {
        load.force->set_time(time);
        std::set<unsigned int> done;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == load.where.boundary)
              for (const unsigned int v : {0u, 1u})
                {
                  const unsigned int vertex = cell->face(f)->vertex_index(v);
                  if (!done.insert(vertex).second)
                    continue;
                  const Point<2> X = cell->face(f)->vertex(v);
                  if (vertex_has_dofs)
                    {
                      const auto dofs = cell_vertex_dofs(
                        cell,
                        GeometryInfo<2>::face_to_cell_vertices(f, v),
                        space);
                      for (unsigned int c = 0; c < 2; ++c)
                        forces[dofs[c]] += load.force->value(X, c);
                    }
                  else
                    // (through the face ending there)
                    for (const auto &function :
                         cached_functions_at(space, cell, f, v))
                      forces[function.dof] +=
                        function.value *
                        load.force->value(X, function.component);
                }
      }
    for (const auto &load : point_loads)
      {
        load.force->set_time(time);
        const Tensor<1, 2> f({load.force->value(load.where.point, 0),
                              load.force->value(load.where.point, 1)});
        if (load.where.is_vertex && vertex_has_dofs)
          {
            const auto dofs =
              cached_vertex_dofs(dof_handler, space, load.where.vertex);
            for (unsigned int c = 0; c < 2; ++c)
              forces[dofs[c]] += f[c];
            continue;
          }
        // A point of a face: the element's shape functions there hand the
        // force to its dofs (eq. 29), derivative dofs included.
        for (const auto &function :
             cached_functions_at(dof_handler, space, load.where))
          forces[function.dof] += function.value * f[function.component];
      }
  }
} // namespace glissade
