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

    const FiniteElement<2> &
    finite_element() const override
    {
      return fe;
    }

    const Mapping<2> &
    mapping() const override
    {
      return geometry;
    }

    const Quadrature<2> &
    cell_quadrature() const override
    {
      return cell_rule;
    }

    const Quadrature<1> &
    face_quadrature() const override
    {
      return face_rule;
    }

  private:
    const unsigned int degree;
    FESystem<2>        fe;
    MappingQ<2>        geometry;
    QGauss<2>          cell_rule;
    QGauss<1>          face_rule;
  };
} // namespace glissade
