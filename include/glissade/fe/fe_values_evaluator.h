#pragma once

#include <deal.II/fe/fe_values.h>

#include <glissade/fe/cell_evaluator.h>

#include <memory>
#include <vector>

namespace glissade
{
  /** A CellEvaluator on top of deal.II's FEValues and FEFaceValues. */
  class FEValuesEvaluator : public CellEvaluator
  {
  public:
    FEValuesEvaluator(const dealii::Mapping<2>       &mapping,
                      const dealii::FiniteElement<2> &fe,
                      const dealii::Quadrature<2>    &cell_quadrature,
                      const dealii::Quadrature<1>    &face_quadrature);

    void
    reinit(const CellIterator &cell) override;
    void
    reinit(const CellIterator &cell, const unsigned int face) override;
    void
    reinit_at(const CellIterator &cell,
              const unsigned int  face,
              const double        fraction) override;

    unsigned int
    n_quadrature_points() const override;
    unsigned int
    dofs_per_cell() const override;
    unsigned int
    displacement_component(const unsigned int i) const override;
    double
    shape_value(const unsigned int i, const unsigned int q) const override;
    dealii::Tensor<1, 2>
    shape_grad(const unsigned int i, const unsigned int q) const override;
    double
    JxW(const unsigned int q) const override;
    dealii::Point<2>
    quadrature_point(const unsigned int q) const override;
    dealii::Tensor<1, 2>
    normal_vector(const unsigned int q) const override;

  private:
    const dealii::FEValuesBase<2> &
    current() const;

    const dealii::Mapping<2>                &mapping;
    const dealii::FiniteElement<2>          &fe;
    dealii::FEValues<2>                      cell_values;
    dealii::FEFaceValues<2>                  face_values;
    std::unique_ptr<dealii::FEFaceValues<2>> point_values;
    enum class Where
    {
      cell,
      face,
      point
    } where = Where::cell;
    std::vector<unsigned int> component;
  };
} // namespace glissade
