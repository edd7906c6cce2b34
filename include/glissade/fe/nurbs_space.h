#pragma once

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/lac/full_matrix.h>

#include <glissade/fe/element_space.h>
#include <glissade/mesh/nurbs_multipatch.h>

#include <map>
#include <mutex>
#include <vector>

namespace glissade
{
  /**
   * Isogeometric bodies (the paper's third strategy against faceted
   * contact, Hughes, Cottrell & Bazilevs 2005): the displacement in the
   * NURBS space of the body's exact geometry, X = sum R_A X_A and
   * u = sum R_A u_A over the patch's control points, of degree p with
   * continuity C^(p-1) between elements (C0 where the shape's pieces join:
   * the quarters of a ring).
   *
   * The elements are the patch's Bezier elements, one per cell of the
   * body's mesh: the mesh types that have an exact patch
   * (MeshFactory::MeshType::exact_patch) make their cells at the knot
   * spans, so that quadrature, WorkStream assembly, the boundary ids and
   * the VTU output stay deal.II's. The unknowns are not nodal values: they
   * are the control points' displacements, and a cell's dofs are those of
   * the (p + 1)^2 control points whose functions live on it, which reach
   * into the neighbouring cells (cell_dof_indices). deal.II 9.4 has no
   * such element; rather than a DoFHandler of its own, the space numbers
   * its control points into the dofs of FE_Q(p)^2 on the mesh (there are
   * always at least as many; the rest are constrained to zero by the
   * element constraints). That keeps one DoFHandler per body, and a vector
   * of the same dofs holds the nodal view (nodal_values): the displacement
   * at FE_Q(p)'s support points, which the VTU output, history points and
   * measures read as they read a Lagrange body's.
   *
   * Quadrature: (p + 1)^2 Gauss points per element (full integration of
   * the polynomial part). Dirichlet data: the L2 projection of g on the
   * boundary's trace (the functions of the boundary's row of control
   * points), which is exact when g is affine in x, y (a support, a rigid
   * motion, a uniform prescribed displacement) and optimal otherwise.
   */
  class NurbsSpace : public ElementSpace
  {
  public:
    explicit NurbsSpace(const unsigned int degree);

    std::string
    name() const override
    {
      return "nurbs";
    }

    Capabilities
    capabilities() const override;

    const dealii::FiniteElement<2> &
    finite_element() const override
    {
      return numbering;
    }

    void
    use_patches(const NurbsMultipatch &exact_geometry) override;

    /** Cell k's vertices at the corners of its span (cell_span). */
    void
    place_vertices(dealii::Triangulation<2> &mesh) const override;

    void
    setup(const dealii::DoFHandler<2>       &dof_handler,
          dealii::AffineConstraints<double> &element_constraints) override;

    /** The cells a share of the mesh holds placed on their elements, by
     *  their numbers in the whole mesh; the control points' dofs are the
     *  whole mesh's (setup). */
    void
    attach(const dealii::DoFHandler<2> &distributed) override;

    /** The patch's geometry at FE_Q(p)'s support points (a degree-p
     *  Lagrange field through points of the exact geometry): for output. */
    const dealii::Mapping<2> &
    mapping() const override
    {
      return *output_mapping;
    }

    std::unique_ptr<CellEvaluator>
    create_evaluator(const unsigned int points_per_direction) const override;

    void
    cell_dof_indices(
      const dealii::DoFHandler<2>::active_cell_iterator &cell,
      std::vector<dealii::types::global_dof_index> &indices) const override;

    void
    boundary_relations(const dealii::DoFHandler<2>     &dof_handler,
                       const dealii::types::boundary_id boundary,
                       const dealii::Function<2>       &g,
                       const std::array<bool, 2>       &components,
                       const bool                       all_derivatives,
                       std::vector<DofRelation> &relations) const override;

    void
    nodal_values(const dealii::DoFHandler<2>  &dof_handler,
                 const dealii::Vector<double> &coefficients,
                 dealii::Vector<double>       &nodal) const override;

    unsigned int
    n_unknowns(const dealii::DoFHandler<2> &dof_handler) const override;

    /** Each control point's dofs at the control point: exact for affine
     *  fields (the space is isoparametric), a quasi-interpolant of others. */
    std::vector<InterpolationPoint>
    interpolation_points() const override;

    /** The body's patches (after use_patches). */
    const NurbsMultipatch &
    patches() const
    {
      return geometry;
    }

    /** The polynomial degree, in both directions. */
    unsigned int
    polynomial_degree() const
    {
      return degree;
    }

    /** The patch and span of a cell, by active cell index. */
    const NurbsMultipatch::CellSpan &
    span_of(const unsigned int active_cell_index) const
    {
      return spans[active_cell_index];
    }

    /** The patch of a cell, by active cell index. */
    const NurbsPatch &
    patch_of(const unsigned int active_cell_index) const
    {
      return geometry.patches[spans[active_cell_index].patch];
    }

    /**
     * The boundary on face `face` of cell `active_cell_index`, a side of
     * its patch (NurbsPatch::side_span). The face's first vertex
     * (GeometryInfo::face_to_cell_vertices(face, 0)) is at the span's
     * start.
     */
    NurbsPatch::SideSpan
    face_curve(const unsigned int active_cell_index,
               const unsigned int face) const
    {
      const auto &cell = spans[active_cell_index];
      return geometry.patches[cell.patch].side_span(cell.span[0],
                                                    cell.span[1],
                                                    face);
    }

    /** The x and y dofs of a control point (a unique_control() number). */
    std::array<dealii::types::global_dof_index, 2>
    control_dofs_of(const unsigned int control) const
    {
      return control_dofs[control];
    }

  private:
    unsigned int           degree;
    dealii::FESystem<2>    numbering;
    dealii::Vector<double> support_positions;
    std::unique_ptr<dealii::MappingFEField<2, 2, dealii::Vector<double>>>
                                           output_mapping;
    NurbsMultipatch                        geometry;
    bool                                   has_patch = false;
    std::vector<NurbsMultipatch::CellSpan> spans;
    std::vector<std::array<dealii::types::global_dof_index, 2>> control_dofs;
    /** The parameters (u, v) of each support point of each cell: the
     *  span's parameters mapped from the unit cell's. */
    std::vector<std::vector<std::array<double, 2>>> support_parameters;

    /** A boundary's trace: its controls and the inverse of their mass. */
    struct Trace
    {
      std::vector<unsigned int>  controls;
      dealii::FullMatrix<double> inverse_mass;
      /** The faces (cell index, face) and their Gauss points' (point,
       *  ds-weight, the traced controls' values). */
      struct Point
      {
        dealii::Point<2> X;
        double           weight;
        /** (position in `controls`, value) of the face's p + 1 functions */
        std::vector<std::pair<unsigned int, double>> values;
      };
      std::vector<Point> points;
    };
    /** The patch and span of each cell of `dof_handler`'s mesh, and the
     *  output's nodes on them. */
    void
    place_cells(const dealii::DoFHandler<2> &dof_handler);

    const Trace &
    trace(const dealii::DoFHandler<2>     &dof_handler,
          const dealii::types::boundary_id boundary) const;
    mutable std::map<dealii::types::boundary_id, Trace> traces;
    mutable std::mutex                                  trace_mutex;
  };
} // namespace glissade
