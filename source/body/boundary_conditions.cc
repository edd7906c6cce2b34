#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/body/boundary_conditions.h>

#include <cmath>
#include <sstream>

namespace glissade
{
  namespace
  {
    /** u(X) = R(angle(t)) (X - c) + c - X: a rigid rotation about c. */
    class RigidRotation : public Function<2>
    {
    public:
      RigidRotation(const Point<2> &center, const std::string &angle)
        : Function<2>(2)
        , center(center)
        , angle(1)
      {
        angle_expression = angle;
        this->angle.initialize("x,y,t", {angle}, {{"pi", numbers::PI}}, true);
      }

      double
      value(const Point<2> &X, const unsigned int component) const override
      {
        angle.set_time(this->get_time());
        const double       a = angle.value(X);
        const Tensor<1, 2> d = X - center;
        const double rotated = component == 0 ?
                                 std::cos(a) * d[0] - std::sin(a) * d[1] :
                                 std::sin(a) * d[0] + std::cos(a) * d[1];
        return rotated - d[component];
      }

    private:
      const Point<2>            center;
      mutable FunctionParser<2> angle;
      std::string               angle_expression;
    };

    std::shared_ptr<FunctionParser<2>>
    make_parser(const std::vector<std::string> &expressions)
    {
      auto f = std::make_shared<FunctionParser<2>>(expressions.size());
      f->initialize("x,y,t", expressions, {{"pi", numbers::PI}}, true);
      return f;
    }
  } // namespace



  Location
  BoundaryConditions::resolve(const std::string      &location,
                              const BoundaryNames    &boundary_names,
                              const Triangulation<2> &triangulation,
                              const std::string      &body_name,
                              const std::string      &entry)
  {
    Location result;
    double   x, y;
    if (text::parse_point_location(location, x, y))
      {
        result.is_vertex = true;
        result.point     = Point<2>(x, y);
        const auto  &vertices = triangulation.get_vertices();
        const auto   used     = triangulation.get_used_vertices();
        double       best     = std::numeric_limits<double>::max();
        unsigned int best_v   = 0;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (used[v] && vertices[v].distance(result.point) < best)
            {
              best   = vertices[v].distance(result.point);
              best_v = v;
            }
        const double size = GridTools::diameter(triangulation);
        if (best > 1e-8 * size)
          {
            std::ostringstream message;
            message << "point(" << x << ", " << y
                    << ") is not a vertex of the mesh of body '" << body_name
                    << "' (the nearest vertex is at " << vertices[best_v]
                    << ")";
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



  std::array<types::global_dof_index, 2>
  BoundaryConditions::vertex_dofs(const DoFHandler<2> &dof_handler,
                                  const unsigned int   vertex)
  {
    const FiniteElement<2> &fe = dof_handler.get_fe();
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex_index(v) == vertex)
          {
            // The first dof of each component at a vertex is its nodal
            // value (elements with derivative dofs list those after it).
            std::array<types::global_dof_index, 2> dofs;
            std::array<bool, 2>                    found = {{false, false}};
            for (unsigned int k = 0; k < fe.n_dofs_per_vertex(); ++k)
              {
                const unsigned int local = v * fe.n_dofs_per_vertex() + k;
                const unsigned int c = fe.system_to_component_index(local).first;
                if (!found[c])
                  {
                    dofs[c]  = cell->vertex_dof_index(v, k);
                    found[c] = true;
                  }
              }
            return dofs;
          }
    Assert(false, ExcInternalError());
    return {};
  }



  BoundaryConditions::BoundaryConditions(const BodyDescription  &body,
                                         const BoundaryNames    &names,
                                         const Triangulation<2> &tria,
                                         const std::string      &source)
  {
    const std::string prefix = source + ": ";
    for (const auto &d : body.dirichlet)
      {
        DirichletItem item;
        item.where = resolve(d.location, names, tria, body.name,
                             prefix + d.entry);
        item.mask  = ComponentMask(std::vector<bool>{d.x_component, d.y_component});
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
                item.displacement = make_parser(both);
                break;
              }
            case DirichletDescription::Kind::rotation:
              item.displacement =
                std::make_shared<RigidRotation>(d.rotation_center,
                                                d.angle_expression);
              break;
          }
        dirichlet_items.push_back(item);
      }

    for (const auto &n : body.neumann)
      {
        const Location where =
          resolve(n.location, names, tria, body.name, prefix + n.entry);
        if (n.kind == NeumannDescription::Kind::point_load)
          point_loads.push_back({where, make_parser(n.expressions)});
        else
          loads_on_boundaries.push_back(
            {where.boundary,
             n.kind == NeumannDescription::Kind::pressure,
             make_parser(n.expressions)});
      }
  }



  void
  BoundaryConditions::make_constraints(
    const DoFHandler<2>       &dof_handler,
    const Mapping<2>          &mapping,
    const double               time,
    const Vector<double>      &current_displacement,
    AffineConstraints<double> &constraints) const
  {
    // Collect all targets first: a dof on two items (a corner shared by two
    // fixed sides) must be constrained once, the later item winning.
    std::map<types::global_dof_index, double> targets;
    for (const auto &item : dirichlet_items)
      {
        item.displacement->set_time(time);
        if (item.where.is_vertex)
          {
            const auto dofs = vertex_dofs(dof_handler, item.where.vertex);
            const Point<2> X =
              dof_handler.get_triangulation().get_vertices()[item.where.vertex];
            for (unsigned int c = 0; c < 2; ++c)
              if (item.mask[c])
                targets[dofs[c]] = item.displacement->value(X, c);
          }
        else
          {
            std::map<types::global_dof_index, double> values;
            VectorTools::interpolate_boundary_values(mapping,
                                                     dof_handler,
                                                     item.where.boundary,
                                                     *item.displacement,
                                                     values,
                                                     item.mask);
            for (const auto &v : values)
              targets[v.first] = v.second;
          }
      }

    constraints.clear();
    for (const auto &t : targets)
      {
        constraints.add_line(t.first);
        constraints.set_inhomogeneity(t.first,
                                      t.second -
                                        current_displacement[t.first]);
      }
    constraints.close();
  }



  void
  BoundaryConditions::add_point_loads(const DoFHandler<2> &dof_handler,
                                      const double         time,
                                      Vector<double>      &forces) const
  {
    for (const auto &load : point_loads)
      {
        load.force->set_time(time);
        const auto dofs = vertex_dofs(dof_handler, load.where.vertex);
        for (unsigned int c = 0; c < 2; ++c)
          forces[dofs[c]] += load.force->value(load.where.point, c);
      }
  }
} // namespace glissade
