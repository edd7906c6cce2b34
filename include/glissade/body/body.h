#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/body_inertia.h>
#include <glissade/body/body_linear_system.h>
#include <glissade/body/boundary_conditions.h>
#include <glissade/body/cell_integration.h>
#include <glissade/body/distributed_loads.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/element_space.h>
#include <glissade/fe/evaluator_pool.h>
#include <glissade/material/body_materials.h>
#include <glissade/mesh/mesh_factory.h>
#include <glissade/mesh/nurbs_multipatch.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * One deformable solid in the total Lagrangian setting. The body sets
   * itself up from its description (mesh, element space, materials,
   * boundary data), keeps its state (the displacement, the contact forces
   * on it, the forces of its last assembly) and assembles; its parts do
   * the rest:
   * - CellIntegration: what the material of each cell adds to the tangent
   *   and the internal forces;
   * - DistributedLoads: tractions, follower pressure and weight;
   * - BodyLinearSystem: the constraints, tangent, factorisation and
   *   solves, the contact port and the springs of a body held by contact;
   * - BodyInertia (under a dynamic scheme): mass, velocity, acceleration;
   * - body_measures.h: vertex displacements, reactions, strain energy.
   *
   * A Newton iteration, seen from the body, is: set_time(t) for the
   * increment, then assemble() -> system().factorize() -> system().solve()
   * -> update() until the Simulation says it has converged.
   */
  class Body
  {
  public:
    /**
     * On several processes the body holds its mesh shared out over them
     * (distribute_mesh); on one process, the whole mesh.
     */
    Body(const BodyDescription &description, const std::string &source);

    // What the body is, as set up from its description.
    const std::string &
    name() const;
    /** What the scene says of the body. */
    const BodyDescription &
    description_of_body() const;
    /** The .prm file the body comes from, for messages. */
    const std::string &
    source_name() const;
    /**
     * The mesh this process holds: the whole mesh, or on a distributed mesh
     * its share, the cells around it and every cell that touches the
     * boundary (distribute_mesh).
     */
    const dealii::Triangulation<2> &
    triangulation() const;
    /** True where the mesh is shared out over the processes. */
    bool
    mesh_is_distributed() const;
    /** The number of cells of the whole mesh. */
    unsigned int
    n_cells() const;
    /** True for the cells whose integrals this process adds (all of them
     *  on one process). */
    bool
    is_own_cell(const dealii::Triangulation<2>::cell_iterator &cell) const;
    /**
     * On a distributed mesh, every vertex of the whole mesh, with its value
     * dofs, and the value dofs of every node (history points and the
     * largest displacement, which the mesh held here may lack); empty
     * otherwise.
     */
    struct WholeMeshNodes
    {
      std::vector<dealii::Point<2>>                               vertices;
      std::vector<std::array<dealii::types::global_dof_index, 2>> vertex_dofs;
      std::vector<std::array<dealii::types::global_dof_index, 2>> node_dofs;
    };
    const WholeMeshNodes &
    whole_mesh_nodes() const;
    /** The named boundaries of the mesh. */
    const BoundaryNames &
    boundary_names() const;
    /** The boundary id of a named boundary; `entry` names the .prm entry. */
    dealii::types::boundary_id
    boundary_id(const std::string &boundary, const std::string &entry) const;
    const ElementSpace &
    space() const;
    const dealii::DoFHandler<2> &
    dof_handler() const;
    unsigned int
    n_dofs() const;
    const BodyMaterials &
    materials() const;
    /** Small strain: a cell's kept stiffness K_e (CellIntegration), or
     *  null. */
    const dealii::FullMatrix<double> *
    kept_cell_stiffness(
      const dealii::DoFHandler<2>::active_cell_iterator &cell) const
    {
      return cell_integration->kept_stiffness(cell->active_cell_index());
    }
    /** Plane strain, plane stress or a body of revolution
     *  (Material/Hypothesis), which the integrations ask. */
    const Hypothesis &
    hypothesis() const;
    /** The out-of-plane thickness (Material/Thickness). */
    double
    thickness() const;
    /** A length that measures the body (diameter of the reference mesh). */
    double
    size() const;

    /**
     * Under a dynamic scheme, the body's inertia (mass, velocity,
     * acceleration), whose terms each assemble() adds; nullptr (the
     * default) for a quasi-static body.
     */
    void
    set_inertia(std::unique_ptr<BodyInertia> body_inertia);
    BodyInertia *
    inertia() const;

    /** Target time of the current increment (Dirichlet and Neumann data). */
    void
    set_time(const double time);

    /**
     * Assembles system()'s tangent and right-hand side F_ext - F_int (under
     * the Dirichlet data of the current time) and the unconstrained
     * residual. False if the state is not admissible (J <= 0 or a NaN), so
     * that the caller cuts the step: assembly_problem() says why. Without
     * the tangent (with_tangent false) the right-hand side and residual
     * alone, the tangent left as it was (BodyLinearSystem::clear()).
     */
    bool
    assemble(const bool with_tangent = true);
    /**
     * Whether a residual alone costs much less than a residual with its
     * tangent: small strain, where each cell's stiffness is kept and its
     * forces are K_e u_e, and the tangent's cost is that of putting the
     * cells' matrices together. (At large strain both come from the same
     * loop over the quadrature points.)
     */
    bool
    residual_alone_is_cheap() const;
    const std::string &
    assembly_problem() const;

    /** F_int - F_ext (with the inertia force, if any) on every dof. */
    const dealii::Vector<double> &
    unbalanced_forces() const;
    /** F_ext of the last assembly: loads, tractions, pressure, weight. */
    const dealii::Vector<double> &
    applied_loads() const;
    /** |F_ext - F_int| on the free dofs. */
    double
    residual_norm() const;
    /**
     * max(|F_int|, |F_ext|, |F_contact|) over all dofs, floored by
     * 1e-4 E t |u|_max: the force scale of the residual tolerance.
     */
    double
    force_scale() const;

    /** The linear system of the last assembly and its factorisation. */
    const BodyLinearSystem &
    system() const;
    BodyLinearSystem &
    system();

    /** H^T r of the last contact solve, which the residual includes. */
    void
    set_contact_forces(const dealii::Vector<double> &forces);
    const dealii::Vector<double> &
    get_contact_forces() const;

    // The displacement.
    const dealii::Vector<double> &
    displacement() const;
    /**
     * The displacement at the nodes of the space's finite element (its
     * support points): displacement() itself for a nodal space, the values
     * the control points give there for NURBS (ElementSpace::nodal_values).
     * What output, history points and measures read.
     */
    const dealii::Vector<double> &
    nodal_displacement() const;
    /** The number of unknowns (ElementSpace::n_unknowns). */
    unsigned int
    n_unknowns() const;
    /** The displacement at the start of the current step. */
    const dealii::Vector<double> &
    stored_displacement() const;
    void
    update(const dealii::Vector<double> &increment);
    /** Exchanges the displacement with u, without copying (a trial
     *  state: ContactProblem::activate_nodes_crossed_by). */
    void
    swap_displacement(dealii::Vector<double> &u);
    /** Saves and restores the displacement (for cut-backs). */
    void
    store_state();
    void
    restore_state();
    /**
     * Writes or reads (a Boost archive) what a checkpoint holds: the
     * displacement and the contact forces H^T r the next residual starts
     * from; the rest is rebuilt from the scene.
     */
    template <class Archive>
    void
    serialize_state(Archive &archive);

  private:
    /** The exact geometry a NURBS space integrates on, from the mesh type,
     *  with the checks of what such a body does not take yet. */
    NurbsMultipatch
    exact_patch(const std::string &where) const;
    /**
     * The constructor's checks of the element space against the mesh and
     * the hypothesis: a space that cannot take a body of revolution, or
     * follow a second-order file's curved edges.
     */
    void
    check_space_for_mesh(const dealii::Triangulation<2> &serial,
                         bool                            second_order,
                         const std::string              &where) const;

    /**
     * The mesh and its dofs, from the whole mesh `serial`: kept whole on
     * one process, shared out on several (the serial mesh's dofs let go
     * once the element constraints, the axis and the nodes are known).
     * Returns the radial dofs on the axis of a body of revolution.
     */
    std::vector<dealii::types::global_dof_index>
    place_mesh_and_dofs(std::unique_ptr<dealii::Triangulation<2>> serial);

    /** The cells this process integrates in a run on several processes. */
    const std::vector<dealii::DoFHandler<2>::active_cell_iterator> &
    own_cells();

    /** assemble()'s copier: a cell and its loads to system and forces. */
    void
    add_cell(const CellIntegration::CellContribution &data,
             CellEvaluator                           &boundary_evaluator,
             dealii::Vector<double>                  &internal_forces,
             dealii::Vector<double>                  &viscous_forces,
             bool                                    &admissible);

    const BodyDescription                     description;
    const std::string                         source;
    const Hypothesis                          body_hypothesis;
    std::unique_ptr<dealii::Triangulation<2>> mesh;
    unsigned int                              n_mesh_cells = 0;
    WholeMeshNodes                            nodes_of_whole_mesh;
    BoundaryNames                             named_boundaries;
    double                                    reference_size = 1.;
    std::unique_ptr<ElementSpace>             element_space;
    // (after the space: its evaluators point at its element)
    std::unique_ptr<EvaluatorPool>      evaluators;
    dealii::DoFHandler<2>               dofs;
    dealii::AffineConstraints<double>   element_constraints;
    std::unique_ptr<BodyMaterials>      materials_of_cells;
    std::unique_ptr<BoundaryConditions> boundary_conditions;
    std::unique_ptr<DistributedLoads>   loads;
    std::unique_ptr<CellIntegration>    cell_integration;
    std::unique_ptr<BodyLinearSystem>   linear_system;
    std::unique_ptr<BodyInertia>        inertia_terms;

    double                 time = 0.;
    std::string            problem;
    dealii::Vector<double> solution, stored_solution;
    /** nodal_displacement() of a space that is not nodal, and whether it
     *  is that of the current solution. */
    mutable dealii::Vector<double> nodal_view;
    mutable bool                   nodal_view_current = false;
    dealii::Vector<double> unconstrained_residual; // F_int - F_ext, all dofs
    std::vector<dealii::DoFHandler<2>::active_cell_iterator> own_cell_list;
    dealii::Vector<double> external_forces; // F_ext, all dofs
    dealii::Vector<double> contact_forces, stored_contact_forces; // H^T r
    double                 internal_force_norm = 0., external_force_norm = 0.;
  };



  inline const std::string &
  Body::name() const
  {
    return description.name;
  }



  inline const BodyDescription &
  Body::description_of_body() const
  {
    return description;
  }



  inline const std::string &
  Body::source_name() const
  {
    return source;
  }



  inline const dealii::Triangulation<2> &
  Body::triangulation() const
  {
    return *mesh;
  }



  inline bool
  Body::mesh_is_distributed() const
  {
    return !nodes_of_whole_mesh.vertices.empty();
  }



  inline unsigned int
  Body::n_cells() const
  {
    return n_mesh_cells;
  }



  inline const Body::WholeMeshNodes &
  Body::whole_mesh_nodes() const
  {
    return nodes_of_whole_mesh;
  }



  inline const BoundaryNames &
  Body::boundary_names() const
  {
    return named_boundaries;
  }



  inline const ElementSpace &
  Body::space() const
  {
    return *element_space;
  }



  inline const dealii::DoFHandler<2> &
  Body::dof_handler() const
  {
    return dofs;
  }



  inline unsigned int
  Body::n_dofs() const
  {
    return dofs.n_dofs();
  }



  inline const BodyMaterials &
  Body::materials() const
  {
    return *materials_of_cells;
  }



  inline const Hypothesis &
  Body::hypothesis() const
  {
    return body_hypothesis;
  }



  inline double
  Body::thickness() const
  {
    return description.material.thickness;
  }



  inline double
  Body::size() const
  {
    return reference_size;
  }



  inline void
  Body::set_inertia(std::unique_ptr<BodyInertia> body_inertia)
  {
    inertia_terms = std::move(body_inertia);
  }



  inline BodyInertia *
  Body::inertia() const
  {
    return inertia_terms.get();
  }



  inline const std::string &
  Body::assembly_problem() const
  {
    return problem;
  }



  inline const dealii::Vector<double> &
  Body::unbalanced_forces() const
  {
    return unconstrained_residual;
  }



  inline const dealii::Vector<double> &
  Body::applied_loads() const
  {
    return external_forces;
  }



  inline const BodyLinearSystem &
  Body::system() const
  {
    return *linear_system;
  }



  inline BodyLinearSystem &
  Body::system()
  {
    return *linear_system;
  }



  inline void
  Body::set_contact_forces(const dealii::Vector<double> &forces)
  {
    contact_forces = forces;
  }



  inline const dealii::Vector<double> &
  Body::get_contact_forces() const
  {
    return contact_forces;
  }



  inline const dealii::Vector<double> &
  Body::displacement() const
  {
    return solution;
  }



  inline const dealii::Vector<double> &
  Body::stored_displacement() const
  {
    return stored_solution;
  }



  inline void
  Body::swap_displacement(dealii::Vector<double> &u)
  {
    nodal_view_current = false;
    solution.swap(u);
  }



  template <class Archive>
  inline void
  Body::serialize_state(Archive &archive)
  {
    nodal_view_current = false;
    archive &solution &contact_forces;
  }
} // namespace glissade
