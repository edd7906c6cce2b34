#include <glissade/fe/fe_values_evaluator.h>

namespace glissade
{
  using namespace dealii;

  FEValuesEvaluator::FEValuesEvaluator(const Mapping<2>       &mapping,
                                       const FiniteElement<2> &fe,
                                       const Quadrature<2>    &cell_quadrature,
                                       const Quadrature<1>    &face_quadrature)
    : mapping(mapping)
    , fe(fe)
    , cell_values(mapping,
                  fe,
                  cell_quadrature,
                  update_values | update_gradients | update_JxW_values |
                    update_quadrature_points)
    , face_values(mapping,
                  fe,
                  face_quadrature,
                  update_values | update_gradients | update_JxW_values |
                    update_quadrature_points | update_normal_vectors)
    , component(fe.n_dofs_per_cell())
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      component[i] = fe.system_to_component_index(i).first;
  }



  void
  FEValuesEvaluator::reinit(const CellIterator &cell)
  {
    cell_values.reinit(cell);
    where = Where::cell;
  }



  void
  FEValuesEvaluator::reinit(const CellIterator &cell, const unsigned int face)
  {
    face_values.reinit(cell, face);
    where = Where::face;
  }



  void
  FEValuesEvaluator::reinit_at(const CellIterator &cell,
                               const unsigned int  face,
                               const double        fraction)
  {
    point_values = std::make_unique<FEFaceValues<2>>(
      mapping,
      fe,
      Quadrature<1>(std::vector<Point<1>>{Point<1>(fraction)},
                    std::vector<double>{1.}),
      update_values | update_gradients | update_quadrature_points |
        update_normal_vectors | update_JxW_values);
    point_values->reinit(cell, face);
    where = Where::point;
  }



  const FEValuesBase<2> &
  FEValuesEvaluator::current() const
  {
    switch (where)
      {
        case Where::face:
          return face_values;
        case Where::point:
          return *point_values;
        default:
          return cell_values;
      }
  }



  unsigned int
  FEValuesEvaluator::n_quadrature_points() const
  {
    return current().n_quadrature_points;
  }



  unsigned int
  FEValuesEvaluator::dofs_per_cell() const
  {
    return component.size();
  }



  unsigned int
  FEValuesEvaluator::displacement_component(const unsigned int i) const
  {
    return component[i];
  }



  double
  FEValuesEvaluator::shape_value(const unsigned int i,
                                 const unsigned int q) const
  {
    return current().shape_value(i, q);
  }



  Tensor<1, 2>
  FEValuesEvaluator::shape_grad(const unsigned int i,
                                const unsigned int q) const
  {
    return current().shape_grad(i, q);
  }



  double
  FEValuesEvaluator::JxW(const unsigned int q) const
  {
    return where == Where::point ? 1. : current().JxW(q);
  }



  Point<2>
  FEValuesEvaluator::quadrature_point(const unsigned int q) const
  {
    return current().quadrature_point(q);
  }



  Tensor<1, 2>
  FEValuesEvaluator::normal_vector(const unsigned int q) const
  {
    return where == Where::point ? point_values->normal_vector(q) :
                                   face_values.normal_vector(q);
  }
} // namespace glissade
