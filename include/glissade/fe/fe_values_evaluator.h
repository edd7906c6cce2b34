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
    FEValuesEvaluator(const Mapping<2>         &mapping,
                      const FiniteElement<2>   &fe,
                      const Quadrature<2>      &cell_quadrature,
                      const Quadrature<1>      &face_quadrature);

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
    Tensor<1, 2>
    shape_grad(const unsigned int i, const unsigned int q) const override;
    double
    JxW(const unsigned int q) const override;
    Point<2>
    quadrature_point(const unsigned int q) const override;
    Tensor<1, 2>
    normal_vector(const unsigned int q) const override;

  private:
    const FEValuesBase<2> &
    current() const;

    const Mapping<2>                &mapping;
    const FiniteElement<2>          &fe;
    FEValues<2>                      cell_values;
    FEFaceValues<2>                  face_values;
    std::unique_ptr<FEFaceValues<2>> point_values;
    enum class Where
    {
      cell,
      face,
      point
    } where = Where::cell;
    std::vector<unsigned int> component;
  };
} // namespace glissade
