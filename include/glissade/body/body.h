#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/body_inertia.h>
#include <glissade/body/body_linear_system.h>
#include <glissade/body/boundary_conditions.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/element_space.h>
#include <glissade/material/body_materials.h>
#include <glissade/mesh/mesh_factory.h>

#include <memory>
#include <string>

namespace glissade
{
  /**
   * One deformable solid in the total Lagrangian setting: its mesh, element
   * space, material, boundary data, and its own linear system
   * (BodyLinearSystem: the tangent, its factorisation, the contact port and
   * the springs of a body held by contact).
   *
   * A Newton iteration, seen from the body, is: set_time(t) for the
   * increment, then assemble() -> system().factorize() -> system().solve()
   * -> update() until the Simulation says it has converged.
   */
  class Body
  {
  public:
    Body(const BodyDescription &description, const std::string &source);

    const std::string &
    name() const
    {
      return description.name;
    }

    /** What the scene says of the body. */
    const BodyDescription &
    description_of_body() const
    {
      return description;
    }

    /** The .prm file the body comes from, for messages. */
    const std::string &
    source_name() const
    {
      return source;
    }

    /**
     * Under a dynamic scheme, the body's inertia (mass, velocity,
     * acceleration), whose Newmark terms each assemble() then adds;
     * nullptr (the default) for a quasi-static body.
     */
    void
    set_inertia(std::unique_ptr<BodyInertia> body_inertia)
    {
      inertia_terms = std::move(body_inertia);
    }
    BodyInertia *
    inertia() const
    {
      return inertia_terms.get();
    }

    /** F_int - F_ext (with the inertia force, if any) on every dof. */
    const dealii::Vector<double> &
    unbalanced_forces() const
    {
      return unconstrained_residual;
    }

    /** F_ext of the last assembly: loads, tractions, pressure, weight. */
    const dealii::Vector<double> &
    applied_loads() const
    {
      return external_forces;
    }

    const BodyMaterials &
    materials() const
    {
      return *materials_of_cells;
    }

    /** Target time of the current increment (Dirichlet and Neumann data). */
    void
    set_time(const double time);

    /**
     * Assembles the tangent and the right-hand side F_ext - F_int (with the
     * Dirichlet constraints of the current time), plus the unconstrained
     * residual used for reactions. Returns false if the material state is
     * not admissible (J <= 0 or a NaN), so the caller can cut the step.
     */
    bool
    assemble();

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
    system() const
    {
      return *linear_system;
    }
    BodyLinearSystem &
    system()
    {
      return *linear_system;
    }

    /**
     * Contact forces acting on the body (from the last contact solve); the
     * equilibrium residual includes them.
     */
    void
    set_contact_forces(const dealii::Vector<double> &forces)
    {
      contact_forces = forces;
    }
    const dealii::Vector<double> &
    get_contact_forces() const
    {
      return contact_forces;
    }

    /** The named boundaries of the mesh. */
    const BoundaryNames &
    boundary_names() const
    {
      return named_boundaries;
    }

    /** The boundary id of a named boundary; `entry` names the .prm entry. */
    dealii::types::boundary_id
    boundary_id(const std::string &boundary, const std::string &entry) const;

    /** The displacement at the start of the current step. */
    const dealii::Vector<double> &
    stored_displacement() const
    {
      return stored_solution;
    }

    void
    update(const dealii::Vector<double> &increment);

    /**
     * Exchanges the displacement with u, without copying (a trial state;
     * see ContactProblem::activate_nodes_crossed_by).
     */
    void
    swap_displacement(dealii::Vector<double> &u)
    {
      solution.swap(u);
    }

    /** Saves and restores the displacement (for cut-backs). */
    void
    store_state();
    void
    restore_state();

    /**
     * Writes or reads (a Boost archive) the state a checkpoint must hold:
     * the displacement and the contact forces H^T r of the last iteration,
     * which the next residual starts from. Everything else is rebuilt from
     * the scene.
     */
    template <class Archive>
    void
    serialize_state(Archive &archive)
    {
      archive &solution &contact_forces;
    }

    /**
     * Why the last assemble() returned false, in words naming the body and
     * the cell (an inverted element, a stress beyond double precision);
     * empty if it returned true.
     */
    const std::string &
    assembly_problem() const
    {
      return problem;
    }

    /** Plane strain, plane stress or axisymmetric (Material/Hypothesis). */
    PlaneHypothesis
    hypothesis() const
    {
      return description.material.hypothesis;
    }

    /** The out-of-plane thickness (Material/Thickness). */
    double
    thickness() const
    {
      return description.material.thickness;
    }

    /** A length that measures the body (diameter of the reference mesh). */
    double
    size() const
    {
      return reference_size;
    }

    const dealii::DoFHandler<2> &
    dof_handler() const
    {
      return dofs;
    }
    const dealii::Triangulation<2> &
    triangulation() const
    {
      return mesh;
    }
    const ElementSpace &
    space() const
    {
      return *element_space;
    }
    const Material &
    material() const
    {
      return materials_of_cells->of_body();
    }
    const dealii::Vector<double> &
    displacement() const
    {
      return solution;
    }
    unsigned int
    n_dofs() const
    {
      return dofs.n_dofs();
    }

  private:
    /** The weight rho g of one cell (Boundary conditions/Gravity). */
    void
    assemble_weight(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      CellEvaluator                                              &evaluator,
      dealii::Vector<double> &cell_rhs) const;

    /**
     * An axisymmetric body: refuses a Hermite space and a mesh with a
     * vertex at x = r < 0, naming the cell.
     */
    void
    check_axisymmetric_mesh(const std::string &where) const;

    /** The radial dofs of the nodes on the axis x = 0. */
    std::vector<dealii::types::global_dof_index>
    dofs_on_axis() const;

    /** The rigid motions that the supports leave free. */
    std::vector<RigidMotion>
    free_motions_of_supports() const;

    void
    assemble_surface_loads(
      const typename dealii::DoFHandler<2>::active_cell_iterator &cell,
      const std::vector<dealii::types::global_dof_index>         &local_dofs,
      CellEvaluator                                              &evaluator,
      dealii::FullMatrix<double>                                 &cell_matrix,
      dealii::Vector<double> &cell_rhs) const;

    const BodyDescription          description;
    std::string                    problem;
    const std::string              source;
    dealii::Triangulation<2>       mesh;
    BoundaryNames                  named_boundaries;
    std::unique_ptr<ElementSpace>  element_space;
    dealii::DoFHandler<2>          dofs;
    std::unique_ptr<BodyMaterials> materials_of_cells;
    std::unique_ptr<BodyInertia>   inertia_terms;
    /** Small strain: each cell's stiffness K_e, integrated once (empty
     *  until then; at large strain unused). */
    std::vector<dealii::FullMatrix<double>> kept_linear_stiffness;
    /** Boundary conditions/Gravity: an acceleration of x, y, t, or none. */
    std::unique_ptr<dealii::Function<2>> gravity;
    std::unique_ptr<BoundaryConditions>  boundary_conditions;
    double                               reference_size = 1.;
    double                               time           = 0.;

    dealii::AffineConstraints<double> element_constraints; // the space's own
    std::unique_ptr<BodyLinearSystem> linear_system;

    dealii::Vector<double> solution;
    dealii::Vector<double> stored_solution;
    dealii::Vector<double> unconstrained_residual; // F_int - F_ext, all dofs
    dealii::Vector<double> external_forces;        // F_ext, all dofs
    dealii::Vector<double> contact_forces;         // H^T r, all dofs
    dealii::Vector<double> stored_contact_forces;
    double                 internal_force_norm = 0.;
    double                 external_force_norm = 0.;
  };
} // namespace glissade
