#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/energy_account.h>
#include <glissade/body/inertia_scheme.h>
#include <glissade/body/turning_frame.h>
#include <glissade/description/scene_description.h>
#include <glissade/lac/direct_solver.h>

#include <array>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * A body's inertia under a dynamic scheme (Time integration): its mass,
   * cell by cell, its velocity and acceleration, and the terms the scheme
   * adds to the body's residual and tangent at each Newton iteration of a
   * time step.
   *
   * The scheme's formulas are its own (InertiaScheme, one file per scheme
   * in source/time/): a step from (u_n, v_n, a_n) over dt is the equation
   * of its end state, whose velocity and acceleration are linear in its
   * displacement about predictors u~, v~, v(u) = v~ + c_v (u - u~) and
   * a(u) = c_a (u - u~); the equation of motion M (c_M (u - u~) + a_M
   * v(u)) + F_int(u) + F_v = F_ext + f_carried + F_c is the quasi-static
   * one with the inertia force on the left and the tangent K + (c_M + a_M
   * c_v) M: the contact step of the quasi-static scheme solves it
   * unchanged (doc/theory.md, "Dynamics"). Newmark's c_M = c_a = 1 / (beta
   * dt^2), c_v = gamma / (beta dt); Moreau-Jean's c_M = 1 / (theta dt)^2
   * with the start state's forces (1 - theta) / theta f_n carried.
   *
   * The mass is the reference configuration's (total Lagrangian: it never
   * changes): consistent, M_ij = int rho N_i N_j dV over each cell, or
   * lumped by the HRZ rule. With the contact mass redistributed (Khenous,
   * Laborde & Renard 2008), the value dofs of the nodes on a contact
   * boundary carry no mass: each such cell is lumped and the massless
   * dofs' share moved to the other dofs of their component in the cell, in
   * proportion to theirs, which keeps the cell's mass, so the body's mass
   * and momentum.
   */
  class BodyInertia
  {
  public:
    /**
     * `scheme` gives the step's formulas; `massless` are the dofs on a
     * contact boundary (redistributed mass); `where` names the body for
     * messages.
     */
    BodyInertia(const Body                                      &body,
                const TimeIntegrationSettings                   &settings,
                std::shared_ptr<const InertiaScheme>             scheme,
                const std::set<dealii::types::global_dof_index> &massless,
                const std::string                               &where);

    /** The velocity at t = 0 from the body's Initial velocity. */
    void
    set_initial_velocity(const Body &body);

    /**
     * The acceleration at t = 0 that balances `residual` (F_ext - F_int -
     * the viscous force at t = 0 on every dof, unconstrained: M a_0 = R_0
     * - a_M M v_0 on the free dofs, condensed by the body's constraints;
     * zero on the massless ones).
     */
    void
    initialize(const Body &body, const dealii::Vector<double> &residual);

    /** The predictors of a step of length dt from the displacement u_n,
     *  ending at t. */
    void
    begin_step(const dealii::Vector<double> &u_n,
               const double                  dt,
               const double                  t);

    /**
     * Forces of the start state that the step's equation carries as loads
     * (InertiaScheme::start_state_forces): Moreau-Jean's (1 - theta) /
     * theta (F_ext - F_int)_n; for Newmark none, but on the rows without
     * mass.
     */
    const dealii::Vector<double> &
    step_forces() const
    {
      return old_forces;
    }

    /**
     * The inertia terms of one cell at the displacement u: the cell's
     * residual loses M (c_M (u - u~) + a_M v(u)) and its tangent gains
     * (c_M + a_M c_v) M. `work` is the caller's room for the cell's
     * accelerations (no allocation per cell).
     */
    void
    add_cell_terms(const unsigned int                                  cell,
                   const std::vector<dealii::types::global_dof_index> &dofs,
                   const dealii::Vector<double>                       &u,
                   dealii::FullMatrix<double> &cell_matrix,
                   dealii::Vector<double>     &cell_rhs,
                   std::vector<double>        &work) const;

    /** Stiffness damping's a_K (Time integration/Stiffness damping). */
    double
    stiffness_damping() const
    {
      return settings.stiffness_damping;
    }

    /** dv/du of the step's end state (0 before the first step). */
    double
    velocity_factor() const
    {
      return step > 0. ? c_v : 0.;
    }

    /**
     * The velocity v(u) of the dofs `dofs` at the displacement u: the
     * scheme's end-state velocity in a step, the initial one before.
     */
    void
    cell_velocity(const std::vector<dealii::types::global_dof_index> &dofs,
                  const dealii::Vector<double>                       &u,
                  std::vector<double> &velocity) const;

    /** The viscous forces (stiffness damping) of the body's last assembly,
     *  on every dof. */
    void
    set_viscous_forces(const dealii::Vector<double> &forces)
    {
      viscous_forces = forces;
    }

    /**
     * After a converged step to the body's displacement: a and v of the
     * end state, and the work of the step done on the body by its loads
     * and supports, by contact and by the damping, added to `account`
     * (EnergyAccount: the trapezoidal rule over the step).
     */
    void
    accept_step(const Body &body, EnergyAccount &account);


    /**
     * The force that would change the body's momentum by itself over one
     * step, |M v~| / dt: the scale of the residual of a body in flight,
     * whose internal and external forces may both be nil.
     */
    double
    force_scale() const;

    /**
     * The body's linear momentum, int rho v dV: e_c . M v with e_c the
     * unit translation along c (its value dofs of component c at 1).
     */
    std::array<double, 2>
    momentum() const;

    /** The unit translation along c: its value dofs of component c at 1,
     *  its derivative dofs (a Hermite body's) at 0. */
    const dealii::Vector<double> &
    unit_translation(const unsigned int c) const
    {
      return translation[c];
    }

    /** 1/2 v . M v */
    double
    kinetic_energy() const;

    /**
     * The moment of inertia about `centre` of the mass as the scheme has
     * it (redistributed or kept): w . M w for the unit rotation w = e_3 x
     * (X - centre) of the reference configuration.
     */
    double
    moment_of_inertia(const Body &body, const dealii::Point<2> &centre) const;

    /**
     * The angular momentum about `centre`, w . M v with w the unit rotation
     * about it (of the reference positions: about a centre that moves, add
     * its motion's moment).
     */
    double
    angular_momentum(const Body &body, const dealii::Point<2> &centre) const;

    const dealii::Vector<double> &
    velocity() const
    {
      return v;
    }
    const dealii::Vector<double> &
    acceleration() const
    {
      return a;
    }

    /** The state a checkpoint holds: velocity, acceleration and the forces
     *  of the last accepted state. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      // clang-format off
      archive & v & a & a_smooth & applied_before & contact_before
              & mass_damping_before & viscous_before & smooth_before
              & frame_before & old_forces;
      // clang-format on
    }

  private:
    /**
     * The forces of the start state that the next step carries as loads
     * (step_forces()), from f = F_ext - F_int - F_v of the accepted state,
     * by the scheme's rule (InertiaScheme::start_state_forces).
     */
    void
    set_start_state_forces(const dealii::Vector<double> &f);

    /**
     * The mass M assembled and condensed by the body's constraints without
     * their values (mass_constraints), the identity on the rows of the free
     * dofs without mass (without_mass), and the mass_factor where contact
     * dofs carry mass under a scheme whose predictor takes the
     * acceleration.
     */
    void
    prepare_mass_system(const Body                   &body,
                        dealii::SparsityPattern      &sparsity,
                        dealii::SparseMatrix<double> &M);

    /**
     * The dof values of a field of the reference positions: a value dof
     * takes the field at its support point, a Hermite derivative dof its
     * derivative there.
     */
    dealii::Vector<double>
    field_at_dofs(const Body                                &body,
                  const std::function<double(const dealii::Point<2> &,
                                             unsigned int)> &field) const;

    /** The velocity field e_3 x (X - centre) of a unit rotation. */
    dealii::Vector<double>
    unit_rotation(const Body &body, const dealii::Point<2> &centre) const;

    /** M x, the mass applied to a global vector. */
    dealii::Vector<double>
    apply_mass(const dealii::Vector<double> &x) const;

    const TimeIntegrationSettings                             settings;
    const std::shared_ptr<const InertiaScheme>                scheme;
    std::vector<std::vector<dealii::types::global_dof_index>> cell_dofs;
    /** Each cell's mass matrix (diagonal when lumped or redistributed). */
    std::vector<dealii::FullMatrix<double>> cell_mass;
    /** The same masses summed into one matrix (apply_mass). */
    dealii::SparsityPattern      mass_sparsity;
    dealii::SparseMatrix<double> mass_matrix;
    dealii::Vector<double>       v, a;
    dealii::Vector<double>       u_start, u_predicted, v_predicted;
    /** The body's mesh is shared out over the processes: the masses are
     *  this process's cells', and products with M are summed. */
    bool shared_out = false;
    /** The unit translations along x and y (value dofs at 1). */
    std::array<dealii::Vector<double>, 2> translation;
    double                                step = 0.;
    /** |M v~| / dt, the step's inertia force scale (begin_step). */
    double predicted_force = 0.;
    /** The step's coefficients (InertiaScheme::StepCoefficients): the
     *  inertia force M c_M (u - u~), the end state's v = v~ + c_v (u - u~)
     *  and a = c_a (u - u~). */
    double c_M = 0., c_a = 0., c_v = 0.;
    /** StepCoefficients::impulse_velocity. */
    double impulse_velocity = 0.;
    /** The start state's forces the step carries (step_forces()). */
    dealii::Vector<double> old_forces;
    /** The forces of the last accepted state, for the next step's work:
     *  loads and supports, contact, mass damping, viscous stress, and the
     *  internal forces (Moreau-Jean's own dissipation). */
    dealii::Vector<double> applied_before, contact_before, mass_damping_before,
      viscous_before, smooth_before, frame_before;
    /** The forces of a turning frame (Body <name>/Turning frame), or none. */
    std::unique_ptr<TurningFrame> frame;
    /**
     * The acceleration of the smooth forces alone (without the contact's
     * impulse), which the next step's predictors take.
     */
    dealii::Vector<double> a_smooth;
    /** The dofs the contact pairs touch, and the free dofs without mass. */
    std::vector<dealii::types::global_dof_index> contact_dofs;
    std::vector<bool>                            without_mass;
    /**
     * With contact dofs that carry mass, under a scheme whose predictor
     * takes the acceleration: the factorised mass, condensed by the body's
     * constraints without their values, for M^-1 F_c at each accepted
     * step.
     */
    std::unique_ptr<DirectSolver>     mass_factor;
    dealii::AffineConstraints<double> mass_constraints;
    /** The last assembly's viscous forces (stiffness damping). */
    dealii::Vector<double> viscous_forces;
  };
} // namespace glissade
