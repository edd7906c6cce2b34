#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <glissade/fe/cell_evaluator.h>

#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

namespace glissade
{
  class NurbsMultipatch;

  /**
   * One Dirichlet condition on one dof: u_dof + sum_k c_k u_{dof_k} = value.
   * Plain nodal values have no `others`; the Hermite element's tangential
   * derivative on a curved boundary couples its two gradient dofs.
   */
  struct DofRelation
  {
    dealii::types::global_dof_index                                 dof;
    std::vector<std::pair<dealii::types::global_dof_index, double>> others;
    double                                                          value;
  };

  /**
   * An element space: what a body needs to discretise its displacement.
   *
   * It gives the deal.II finite element used to number the dofs, the
   * geometry mapping (isoparametric: Q1 bodies have straight edges exactly
   * as the paper's Q4), evaluators of shape functions for assembly, and the
   * way Dirichlet data constrain its dofs. Bodies only talk to this
   * interface, so a new element type is one new class plus one line in
   * ElementSpaceRegistry (doc/adding_an_element_type.md).
   */
  class ElementSpace
  {
  public:
    virtual ~ElementSpace() = default;

    /** The name it is chosen by in the .prm ("q1", ...). */
    virtual std::string
    name() const = 0;

    /**
     * What a space can do, which the code asks instead of its name (a new
     * space says what it supports here, and the checks and their messages
     * follow).
     */
    struct Capabilities
    {
      /** Empty if the space takes an axisymmetric body; else why not. */
      std::string not_axisymmetric_because;
      /** Its geometry is of degree two or more: it follows the curved
       *  edges of a second-order mesh. */
      bool follows_curved_edges = false;
      /** Every dof is a vertex's displacement: a support along a
       *  boundary's normal or tangent is a relation between two of them. */
      bool vertex_dofs_only = false;
      /** Its dofs are displacements at nodes (every space but NURBS,
       *  whose dofs are control points'): what reads a vertex's dofs as
       *  its displacement (contact nodes, point supports and loads, the
       *  springs of a free body) may use them. */
      bool dofs_are_nodal_values = true;
      /** It needs the exact geometry of the body (use_patches), which only
       *  the mesh types that have one give. */
      bool needs_exact_patch = false;
    };

    virtual Capabilities
    capabilities() const = 0;

    /** The element whose dofs the DoFHandler distributes. */
    virtual const dealii::FiniteElement<2> &
    finite_element() const = 0;

    /**
     * The body's exact geometry (one patch or several joined), before
     * setup(), for a space whose capabilities say needs_exact_patch. The
     * default refuses it.
     */
    virtual void
    use_patches(const NurbsMultipatch &patches);

    /**
     * Puts the mesh's vertices where the space's geometry has them (a
     * distorted NURBS patch's knot points), before the dofs are
     * distributed. The default leaves them.
     */
    virtual void
    place_vertices(dealii::Triangulation<2> &mesh) const;

    /**
     * Called once the body's dofs are distributed, for what depends on the
     * mesh: a geometry field, constraints among the element's own dofs
     * (serendipity interiors). The default does nothing.
     */
    virtual void
    setup(const dealii::DoFHandler<2>       &dof_handler,
          dealii::AffineConstraints<double> &element_constraints);

    /**
     * The dofs of a cell's shape functions, in the evaluator's order. The
     * default is the cell's own dofs; a space whose functions reach beyond
     * their cell (NURBS) gives its own.
     */
    virtual void
    cell_dof_indices(
      const dealii::DoFHandler<2>::active_cell_iterator &cell,
      std::vector<dealii::types::global_dof_index>      &indices) const;

    /**
     * The displacement at the support points of finite_element(), from
     * the dofs' coefficients: what output and measures read. The default
     * (a nodal space) copies them.
     */
    virtual void
    nodal_values(const dealii::DoFHandler<2>  &dof_handler,
                 const dealii::Vector<double> &coefficients,
                 dealii::Vector<double>       &nodal) const;

    /**
     * A space whose dofs are not nodal values: each dof, its displacement
     * component and the point whose field value it takes when a field (an
     * initial velocity, a rigid motion) is interpolated. Empty (the
     * default) for a nodal space, which is interpolated at its support
     * points.
     */
    struct InterpolationPoint
    {
      dealii::types::global_dof_index dof;
      unsigned int                    component;
      dealii::Point<2>                point;
    };
    virtual std::vector<InterpolationPoint>
    interpolation_points() const
    {
      return {};
    }

    /** The number of unknowns (the dofs less those set to zero for
     *  numbering only). */
    virtual unsigned int
    n_unknowns(const dealii::DoFHandler<2> &dof_handler) const;

    /**
     * A mesh shared out over the processes (Body): setup() has run on the
     * whole mesh's dofs, which `distributed` numbers alike, so that the
     * element constraints hold for every dof; what the space keeps of a
     * mesh (a geometry field, per-cell data) is then made again for the
     * cells `distributed` holds. The default does nothing.
     */
    virtual void
    attach(const dealii::DoFHandler<2> &distributed);

    /** The geometry, for output and boundary interpolation. */
    virtual const dealii::Mapping<2> &
    mapping() const = 0;

    /**
     * How many finite-element components describe one displacement
     * component: 1 for nodal spaces, 3 for Hermite (value, d/dx, d/dy).
     * System component k belongs to displacement component k / this.
     */
    virtual unsigned int
    components_per_displacement() const
    {
      return 1;
    }

    /**
     * Shape functions at quadrature points: the space's own rule if
     * points_per_direction is 0, else a Gauss rule with that many points
     * (error integration uses a richer one).
     */
    virtual std::unique_ptr<CellEvaluator>
    create_evaluator(const unsigned int points_per_direction = 0) const = 0;

    /**
     * The relations that prescribe the displacement g (a 2-component
     * function) on the faces with the given boundary id, for the components
     * in `components`. `all_derivatives` additionally fixes every derivative
     * dof there (the paper's fully clamped Hermite nodes; nodal spaces have
     * none). The default interpolates g at the support points.
     */
    virtual void
    boundary_relations(const dealii::DoFHandler<2>     &dof_handler,
                       const dealii::types::boundary_id boundary,
                       const dealii::Function<2>       &g,
                       const std::array<bool, 2>       &components,
                       const bool                       all_derivatives,
                       std::vector<DofRelation>        &relations) const;

    /**
     * What a symmetry line (a straight boundary, normal along component
     * `normal`) holds beyond the normal component that boundary_relations
     * holds: nothing where the dofs are values (the default), and on a
     * space whose dofs include derivatives the tangential component's
     * normal derivative, zero, so that the mirror image continues the
     * field with its slope (HermiteSpace).
     */
    virtual void
    symmetry_relations(const dealii::DoFHandler<2>     &dof_handler,
                       const dealii::types::boundary_id boundary,
                       const unsigned int               normal,
                       std::vector<DofRelation>        &relations) const;

  private:
    /**
     * The dofs of one component on one boundary and the points their
     * values are interpolated at, found once (a loop over every cell) and
     * kept: boundary_relations runs at every assembly.
     */
    using BoundarySupport =
      std::vector<std::pair<dealii::types::global_dof_index, dealii::Point<2>>>;
    const BoundarySupport &
    boundary_support(const dealii::DoFHandler<2>     &dof_handler,
                     const dealii::types::boundary_id boundary,
                     const unsigned int               component) const;

    mutable std::map<std::tuple<const dealii::DoFHandler<2> *,
                                dealii::types::global_dof_index,
                                dealii::types::boundary_id,
                                unsigned int>,
                     BoundarySupport>
                       boundary_support_cache;
    mutable std::mutex boundary_support_mutex;
  };
} // namespace glissade
