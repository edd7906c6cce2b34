#include <deal.II/fe/component_mask.h>
#include <deal.II/numerics/vector_tools.h>

#include <glissade/fe/element_space.h>

namespace glissade
{
  using namespace dealii;

  void
  ElementSpace::setup(const DoFHandler<2> &, AffineConstraints<double> &)
  {}



  void
  ElementSpace::attach(const DoFHandler<2> &)
  {}



  void
  ElementSpace::use_patches(const NurbsMultipatch &)
  {
    AssertThrow(false,
                ExcMessage("the " + name() + " space takes no NURBS patch"));
  }



  void
  ElementSpace::place_vertices(Triangulation<2> &) const
  {}



  void
  ElementSpace::cell_dof_indices(
    const DoFHandler<2>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>      &indices) const
  {
    indices.resize(cell->get_fe().n_dofs_per_cell());
    cell->get_dof_indices(indices);
  }



  void
  ElementSpace::nodal_values(const DoFHandler<2> &,
                             const Vector<double> &coefficients,
                             Vector<double>       &nodal) const
  {
    nodal = coefficients;
  }



  unsigned int
  ElementSpace::n_unknowns(const DoFHandler<2> &dof_handler) const
  {
    return dof_handler.n_dofs();
  }



  const ElementSpace::BoundarySupport &
  ElementSpace::boundary_support(const DoFHandler<2>     &dof_handler,
                                 const types::boundary_id boundary,
                                 const unsigned int       component) const
  {
    // (bodies assemble on several threads; each has its own space, but a
    // lock costs nothing beside the search it guards)
    std::lock_guard<std::mutex> lock(boundary_support_mutex);
    const auto                  key =
      std::make_tuple(&dof_handler, dof_handler.n_dofs(), boundary, component);
    const auto found = boundary_support_cache.find(key);
    if (found != boundary_support_cache.end())
      return found->second;

    // The points are those interpolate_boundary_values evaluates a datum
    // at, to the bit: it interpolates each coordinate of the point itself.
    class Coordinate : public Function<2>
    {
    public:
      explicit Coordinate(const unsigned int d)
        : Function<2>(2)
        , d(d)
      {}
      double
      value(const Point<2> &X, const unsigned int) const override
      {
        return X[d];
      }

    private:
      const unsigned int d;
    };
    std::array<std::map<types::global_dof_index, double>, 2> coordinates;
    const ComponentMask mask(std::vector<bool>{component == 0, component == 1});
    for (unsigned int d = 0; d < 2; ++d)
      VectorTools::interpolate_boundary_values(
        mapping(), dof_handler, boundary, Coordinate(d), coordinates[d], mask);
    BoundarySupport support;
    for (const auto &[dof, x] : coordinates[0])
      support.emplace_back(dof, Point<2>(x, coordinates[1].at(dof)));
    return boundary_support_cache[key] = std::move(support);
  }



  void
  ElementSpace::symmetry_relations(const DoFHandler<2> &,
                                   const types::boundary_id,
                                   const unsigned int,
                                   std::vector<DofRelation> &) const
  {}



  void
  ElementSpace::boundary_relations(const DoFHandler<2>       &dof_handler,
                                   const types::boundary_id   boundary,
                                   const Function<2>         &g,
                                   const std::array<bool, 2> &components,
                                   const bool,
                                   std::vector<DofRelation> &relations) const
  {
    for (unsigned int c = 0; c < 2; ++c)
      if (components[c])
        for (const auto &[dof, X] : boundary_support(dof_handler, boundary, c))
          relations.push_back({dof, {}, g.value(X, c)});
  }
} // namespace glissade
