#include <glissade/fe/fe_values_evaluator.h>

namespace glissade
{
  FEValuesEvaluator::FEValuesEvaluator(const Mapping<2>       &mapping,
                                       const FiniteElement<2> &fe,
                                       const Quadrature<2>    &cell_quadrature,
                                       const Quadrature<1>    &face_quadrature)
    : cell_values(mapping,
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
    on_face = false;
  }



  void
  FEValuesEvaluator::reinit(const CellIterator &cell, const unsigned int face)
  {
    face_values.reinit(cell, face);
    on_face = true;
  }



  const FEValuesBase<2> &
  FEValuesEvaluator::current() const
  {
    return on_face ? static_cast<const FEValuesBase<2> &>(face_values) :
                     static_cast<const FEValuesBase<2> &>(cell_values);
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
    return current().JxW(q);
  }



  Point<2>
  FEValuesEvaluator::quadrature_point(const unsigned int q) const
  {
    return current().quadrature_point(q);
  }



  Tensor<1, 2>
  FEValuesEvaluator::normal_vector(const unsigned int q) const
  {
    return face_values.normal_vector(q);
  }
} // namespace glissade
