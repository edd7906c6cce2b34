#pragma once

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/lac/vector.h>

#include <glissade/fe/element_space.h>

#include <memory>

namespace glissade
{
  /**
   * The serendipity quadrilaterals Q8 (degree 2) and Q12 (degree 3), which
   * deal.II does not ship, built on its tensor-product FE_Q.
   *
   * The serendipity space is the tensor-product space Q_p minus the monomials
   * whose degree exceeds p in one variable while being at least 2 in the
   * other: x^2 y^2 for Q8; x^2 y^2, x^3 y^2, x^2 y^3, x^3 y^3 for Q12. That is
   * exactly as many conditions as Q_p has interior nodes (1 and 4), so a
   * serendipity function is an FE_Q(p) function whose interior nodal values
   * are fixed, cell by cell, by its boundary ones. We number dofs with
   * FE_Q(p), impose those cell-local relations as constraints, and get every
   * deal.II facility (FEValues, interpolation, output) for free. For Q8 the
   * relation is the classical u_centre = -1/4 sum(corners) + 1/2
   * sum(mid-sides).
   *
   * The geometry is isoparametric in the same space: a MappingFEField whose
   * Euler vector holds the exact positions (from the mesh's manifold) of the
   * boundary nodes and the serendipity-constrained interior ones.
   */
  class SerendipitySpace : public ElementSpace
  {
  public:
    explicit SerendipitySpace(const unsigned int degree);

    std::string
    name() const override;

    /** Axisymmetric, and its geometry of degree 2 or 3 follows curved
     *  edges. */
    Capabilities
    capabilities() const override
    {
      Capabilities c;
      c.follows_curved_edges = true;
      return c;
    }

    const dealii::FiniteElement<2> &
    finite_element() const override
    {
      return fe;
    }

    void
    setup(const dealii::DoFHandler<2>       &dof_handler,
          dealii::AffineConstraints<double> &element_constraints) override;

    /** The geometry field on the distributed mesh's dofs (the same
     *  numbers, the same node positions). */
    void
    attach(const dealii::DoFHandler<2> &distributed) override;

    const dealii::Mapping<2> &
    mapping() const override;

    std::unique_ptr<CellEvaluator>
    create_evaluator(const unsigned int points_per_direction) const override;

  private:
    const unsigned int                                        degree;
    dealii::FESystem<2>                                       fe;
    std::vector<std::vector<std::pair<unsigned int, double>>> relations;
    dealii::Vector<double>                                    euler_vector;
    std::unique_ptr<dealii::MappingFEField<2, 2, dealii::Vector<double>>>
      geometry;
  };
} // namespace glissade
