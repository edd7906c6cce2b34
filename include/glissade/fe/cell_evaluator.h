#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace glissade
{
  /**
   * What assembly sees of an element space on one cell or one boundary face:
   * physical shape values and gradients at quadrature points, the weights,
   * and which displacement component each local dof belongs to.
   *
   * Every shape function is "primitive": it moves one displacement
   * component, which is what the assembly's contractions rely on. For the
   * Lagrange and serendipity spaces this wraps deal.II's FEValues; the
   * Hermite space computes its own (derivative dofs, Hermite geometry).
   */
  class CellEvaluator
  {
  public:
    using CellIterator = typename dealii::DoFHandler<2>::active_cell_iterator;

    virtual ~CellEvaluator() = default;

    virtual void
    reinit(const CellIterator &cell) = 0;

    /** Switches to the quadrature of face f of the cell. */
    virtual void
    reinit(const CellIterator &cell, const unsigned int face) = 0;

    /**
     * Switches to one point of face f: the one at `fraction` (in [0, 1]) of
     * the way from the face's vertex 0 to its vertex 1 in the reference
     * configuration. For point loads and edge slopes; JxW is 1 there.
     */
    virtual void
    reinit_at(const CellIterator &cell,
              const unsigned int  face,
              const double        fraction) = 0;

    virtual unsigned int
    n_quadrature_points() const = 0;

    virtual unsigned int
    dofs_per_cell() const = 0;

    /** 0 (x) or 1 (y): the displacement component dof i moves. */
    virtual unsigned int
    displacement_component(const unsigned int i) const = 0;

    virtual double
    shape_value(const unsigned int i, const unsigned int q) const = 0;

    virtual dealii::Tensor<1, 2>
    shape_grad(const unsigned int i, const unsigned int q) const = 0;

    /** Reference-configuration measure times quadrature weight. */
    virtual double
    JxW(const unsigned int q) const = 0;

    virtual dealii::Point<2>
    quadrature_point(const unsigned int q) const = 0;

    /** Outward unit normal in the reference configuration (faces only). */
    virtual dealii::Tensor<1, 2>
    normal_vector(const unsigned int q) const = 0;

    /** The displacement at point q, from the cell's dof values. */
    dealii::Tensor<1, 2>
    value(const std::vector<double> &dof_values, const unsigned int q) const
    {
      dealii::Tensor<1, 2> u;
      for (unsigned int i = 0; i < dof_values.size(); ++i)
        u[displacement_component(i)] += dof_values[i] * shape_value(i, q);
      return u;
    }

    /** The displacement gradient at point q, from the cell's dof values. */
    dealii::Tensor<2, 2>
    gradient(const std::vector<double> &dof_values, const unsigned int q) const
    {
      dealii::Tensor<2, 2> H;
      for (unsigned int i = 0; i < dof_values.size(); ++i)
        H[displacement_component(i)] += dof_values[i] * shape_grad(i, q);
      return H;
    }
  };
} // namespace glissade
