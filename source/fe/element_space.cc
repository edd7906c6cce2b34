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
  ElementSpace::boundary_relations(const DoFHandler<2>       &dof_handler,
                                   const types::boundary_id   boundary,
                                   const Function<2>         &g,
                                   const std::array<bool, 2> &components,
                                   const bool,
                                   std::vector<DofRelation> &relations) const
  {
    std::map<types::global_dof_index, double> values;
    VectorTools::interpolate_boundary_values(
      mapping(),
      dof_handler,
      boundary,
      g,
      values,
      ComponentMask(std::vector<bool>{components[0], components[1]}));
    for (const auto &v : values)
      relations.push_back({v.first, {}, v.second});
  }
} // namespace glissade
