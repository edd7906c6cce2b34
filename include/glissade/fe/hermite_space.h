#pragma once

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <glissade/fe/element_space.h>
#include <glissade/fe/hermite_quadrilateral.h>

#include <vector>

namespace glissade
{
  /**
   * The paper's C1-edge Hermite quadrilateral (section 3.2): the 12-term
   * cubic of eq. 22 with, per node and displacement component, the value
   * and the two spatial derivatives (eq. 21): 6 dofs per node, 24 per cell.
   *
   * deal.II 9.4 has no such element, so the space is ours:
   * - numbering: FESystem(FE_Q(1), 6) distributes exactly 6 dofs per vertex
   *   and nothing else; its components are (u, du/dx, du/dy, v, dv/dx,
   *   dv/dy). Its shape functions are never used for the solution.
   * - shape functions and geometry: HermiteQuadrilateral, isoparametric with
   *   node tangents from the mesh's manifold (the exact parametric
   *   description: PolarManifold on rings, straight edges elsewhere), so the
   *   boundary of a ring is a C1 curve.
   * - quadrature: the paper's 3 x 3 Gauss rule (2 x 2 leaves zero-energy
   *   modes, measured in tests/hermite).
   *
   * Dirichlet data: a prescribed displacement g on a boundary fixes the
   * value dofs and the derivative along the boundary (t . grad u = t . grad
   * g), which is what makes u = g hold along the whole edge, since the trace
   * of the element on an edge depends only on those. The normal derivative
   * stays free: it carries the strain at the support, which elasticity does
   * not make zero. The paper's static test (fig 11) clamps every dof of the
   * lower nodes; "Fixed = bottom: all" does that.
   */
  class HermiteSpace : public ElementSpace
  {
  public:
    HermiteSpace();

    std::string
    name() const override
    {
      return "hermite";
    }

    /** Straight edges (the paper's bilinear geometry), derivative dofs,
     *  and no axisymmetric body. */
    Capabilities
    capabilities() const override
    {
      Capabilities c;
      c.not_axisymmetric_because =
        "its derivative dofs would need the axis condition on the "
        "derivatives of u_r too (du_r/dz = 0 on the axis), and the hoop "
        "strain u_r / r of a C1 field near the axis is not what the element "
        "was built for";
      return c;
    }

    const dealii::FiniteElement<2> &
    finite_element() const override
    {
      return numbering;
    }

    void
    setup(const dealii::DoFHandler<2>       &dof_handler,
          dealii::AffineConstraints<double> &element_constraints) override;

    /** The cells' geometry for the cells `distributed` holds, by their
     *  index there. */
    void
    attach(const dealii::DoFHandler<2> &distributed) override;


    /** Straight-sided Q1 geometry: for output only. */
    const dealii::Mapping<2> &
    mapping() const override
    {
      return output_mapping;
    }

    unsigned int
    components_per_displacement() const override
    {
      return 3;
    }

    std::unique_ptr<CellEvaluator>
    create_evaluator(const unsigned int points_per_direction) const override;

    void
    boundary_relations(const dealii::DoFHandler<2>     &dof_handler,
                       const dealii::types::boundary_id boundary,
                       const dealii::Function<2>       &g,
                       const std::array<bool, 2>       &components,
                       const bool                       all_derivatives,
                       std::vector<DofRelation> &relations) const override;

    /** d u_t / d n = 0 at each node of the symmetry line. */
    void
    symmetry_relations(const dealii::DoFHandler<2>     &dof_handler,
                       const dealii::types::boundary_id boundary,
                       const unsigned int               normal,
                       std::vector<DofRelation> &relations) const override;

    /** The element of a cell (its geometry), by active cell index. */
    const HermiteQuadrilateral &
    element(const unsigned int active_cell_index) const
    {
      return elements[active_cell_index];
    }

    /**
     * For local dof i of a cell: its displacement component and its index
     * in HermiteQuadrilateral's 12-entry order (3 node + kind).
     */
    std::pair<unsigned int, unsigned int>
    local_dof(const unsigned int i) const
    {
      return local_dofs[i];
    }

  private:
    dealii::FESystem<2>                                numbering;
    dealii::MappingQ<2>                                output_mapping;
    std::vector<HermiteQuadrilateral>                  elements;
    std::vector<std::pair<unsigned int, unsigned int>> local_dofs;
  };
} // namespace glissade
