#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <glissade/fe/element_space.h>

namespace glissade
{
  /**
   * Tensor-product Lagrange elements of degree p (deal.II's FE_Q): q1 is the
   * paper's Q4, q2 the 9-node and q3 the 16-node quadrilateral. The mapping
   * has the same degree (isoparametric) and the cell rule is (p+1)-point
   * Gauss, which integrates the stiffness of an affine cell exactly.
   */
  class LagrangeSpace : public ElementSpace
  {
  public:
    explicit LagrangeSpace(const unsigned int degree);

    std::string
    name() const override;

    /** Every degree is axisymmetric; degree 1 has straight edges and its
     *  dofs at the vertices alone. */
    Capabilities
    capabilities() const override
    {
      Capabilities c;
      c.follows_curved_edges = degree >= 2;
      c.vertex_dofs_only     = degree == 1;
      return c;
    }

    const dealii::FiniteElement<2> &
    finite_element() const override
    {
      return fe;
    }

    const dealii::Mapping<2> &
    mapping() const override
    {
      return geometry;
    }

    std::unique_ptr<CellEvaluator>
    create_evaluator(const unsigned int points_per_direction) const override;

  private:
    const unsigned int  degree;
    dealii::FESystem<2> fe;
    dealii::MappingQ<2> geometry;
  };
} // namespace glissade
