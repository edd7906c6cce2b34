#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>

#include <glissade/base/input_error.h>
#include <glissade/base/processes.h>
#include <glissade/body/body.h>
#include <glissade/body/body_inertia.h>
#include <glissade/lac/direct_solver.h>

#include <cmath>
#include <map>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The cell's mass lumped by the HRZ rule, component by component: the
     * diagonal scaled so that it sums to the component's mass in the cell
     * (positive for every Lagrange space, where row sums are not).
     */
    void
    lump(FullMatrix<double> &m, const std::vector<unsigned int> &component)
    {
      const unsigned int n = m.m();
      for (unsigned int c = 0; c < 2; ++c)
        {
          double total = 0., diagonal = 0.;
          for (unsigned int i = 0; i < n; ++i)
            if (component[i] == c)
              {
                diagonal += m(i, i);
                for (unsigned int j = 0; j < n; ++j)
                  if (component[j] == c)
                    total += m(i, j);
              }
          for (unsigned int i = 0; i < n; ++i)
            if (component[i] == c)
              {
                const double d =
                  diagonal > 0. ? m(i, i) * total / diagonal : 0.;
                for (unsigned int j = 0; j < n; ++j)
                  m(i, j) = 0.;
                m(i, i) = d;
              }
        }
    }
  } // namespace



  BodyInertia::BodyInertia(const Body                              &body,
                           const TimeIntegrationSettings           &settings,
                           std::shared_ptr<const InertiaScheme>     scheme,
                           const std::set<types::global_dof_index> &massless,
                           const std::string                       &where)
    : settings(settings)
    , scheme(std::move(scheme))
    , contact_dofs(massless.begin(), massless.end())
  {
    // (a lumped mass, diagonal, is one value per dof: a space with
    // derivative dofs (Hermite) has none for them. Control points (NURBS),
    // whose functions are positive, take it as nodes do.)
    const ElementSpace &space = body.space();
    const bool          nodal = space.capabilities().dofs_are_nodal_values;
    if (space.components_per_displacement() != 1 && settings.lumped_mass)
      throw InputError(where + "/Material",
                       "Time integration/Mass = lumped is for spaces of "
                       "values (nodes or control points); body '" +
                         body.name() + "' uses " + space.name() +
                         ", whose derivative dofs have no lumped mass: use "
                         "Mass = consistent");
    const Hypothesis         &hypothesis = body.hypothesis();
    auto                      evaluator  = space.create_evaluator();
    const unsigned int        n          = evaluator->dofs_per_cell();
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = evaluator->displacement_component(i);
    // (a Hermite body keeps its mass where it touches: its derivative dofs
    // would need their own redistribution, not derived here. A NURBS
    // body's contact control points give theirs to the others of their
    // cells, as nodes do.)
    const bool redistribute = settings.redistribute_contact_mass &&
                              space.components_per_displacement() == 1;

    // (on a mesh shared out over the processes, the masses of this
    // process's cells; apply_mass sums the processes' products)
    shared_out = body.mesh_is_distributed();
    cell_dofs.resize(body.triangulation().n_active_cells());
    cell_mass.resize(cell_dofs.size());
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        if (shared_out && !body.is_own_cell(cell))
          continue;
        const unsigned int index = cell->active_cell_index();
        space.cell_dof_indices(cell, cell_dofs[index]);
        const double rho =
          body.materials().density_of_cell(cell->material_id());
        FullMatrix<double> &m = cell_mass[index];
        m.reinit(n, n);
        evaluator->reinit(cell);
        for (unsigned int q = 0; q < evaluator->n_quadrature_points(); ++q)
          {
            const double dV =
              evaluator->JxW(q) *
              hypothesis.out_of_plane_measure(evaluator->quadrature_point(q));
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                if (component[i] == component[j])
                  m(i, j) += rho * evaluator->shape_value(i, q) *
                             evaluator->shape_value(j, q) * dV;
          }

        std::vector<bool> without_mass(n, false);
        bool              touches = false;
        if (redistribute)
          for (unsigned int i = 0; i < n; ++i)
            {
              without_mass[i] = massless.count(cell_dofs[index][i]) > 0;
              touches         = touches || without_mass[i];
            }
        if (settings.lumped_mass || touches)
          lump(m, component);
        if (!touches)
          continue;
        // The massless dofs' share to the others of their component, in
        // proportion to theirs: the cell keeps its mass. A cell all of
        // whose nodes of a component touch keeps its own.
        for (unsigned int c = 0; c < 2; ++c)
          {
            double moved = 0., kept = 0.;
            for (unsigned int i = 0; i < n; ++i)
              if (component[i] == c)
                (without_mass[i] ? moved : kept) += m(i, i);
            if (!(kept > 0.))
              continue;
            for (unsigned int i = 0; i < n; ++i)
              if (component[i] == c)
                m(i, i) = without_mass[i] ? 0. : m(i, i) * (1. + moved / kept);
          }
      }
    // The cells' masses as one sparse matrix, their non-zero entries
    // alone (a lumped mass is diagonal): products with M are a step's
    // most frequent operation after the assembly.
    {
      DynamicSparsityPattern pattern(body.n_dofs());
      for (unsigned int c = 0; c < cell_dofs.size(); ++c)
        for (unsigned int i = 0; i < cell_dofs[c].size(); ++i)
          for (unsigned int j = 0; j < cell_dofs[c].size(); ++j)
            if (cell_mass[c](i, j) != 0.)
              pattern.add(cell_dofs[c][i], cell_dofs[c][j]);
      mass_sparsity.copy_from(pattern);
      mass_matrix.reinit(mass_sparsity);
      for (unsigned int c = 0; c < cell_dofs.size(); ++c)
        for (unsigned int i = 0; i < cell_dofs[c].size(); ++i)
          for (unsigned int j = 0; j < cell_dofs[c].size(); ++j)
            if (cell_mass[c](i, j) != 0.)
              mass_matrix.add(cell_dofs[c][i],
                              cell_dofs[c][j],
                              cell_mass[c](i, j));
    }
    v.reinit(body.n_dofs());
    a.reinit(body.n_dofs());
    old_forces.reinit(body.n_dofs());
    // The unit translations: every value dof of a component at 1 (a
    // Hermite body's derivative dofs at 0).
    const unsigned int      per_dim = space.components_per_displacement();
    const FiniteElement<2> &fe      = body.dof_handler().get_fe();
    for (unsigned int c = 0; c < 2; ++c)
      translation[c].reinit(body.n_dofs());
    // (a space whose dofs are not nodal values: each of its dofs, whose
    // functions sum to one)
    for (const auto &point : space.interpolation_points())
      translation[point.component](point.dof) = 1.;
    if (nodal)
      for (unsigned int k = 0; k < cell_dofs.size(); ++k)
        for (unsigned int i = 0; i < cell_dofs[k].size(); ++i)
          {
            const unsigned int system = fe.system_to_component_index(i).first;
            if (system % per_dim == 0)
              translation[system / per_dim](cell_dofs[k][i]) = 1.;
          }
    // (each process has set the value dofs of its own cells)
    if (shared_out)
      for (auto &t : translation)
        {
          processes::sum(t.begin(), t.size());
          for (auto &value : t)
            value = value > 0. ? 1. : 0.;
        }

    const TurningFrameDescription &turning =
      body.description_of_body().turning_frame;
    if (turning.active())
      {
        frame = std::make_unique<TurningFrame>(
          body,
          turning,
          field_at_dofs(body,
                        [&](const Point<2> &X, const unsigned int c) {
                          return X[c] - turning.centre[c];
                        }),
          where);
        frame->set_time(0.);
      }
  }



  void
  BodyInertia::set_initial_velocity(const Body &body)
  {
    // The initial velocity at each dof (field_at_dofs).
    const auto                   &description = body.description_of_body();
    FunctionParser<2>             velocity(2);
    std::map<std::string, double> constants = {{"pi", M_PI}};
    try
      {
        velocity.initialize("x, y",
                            description.initial_velocity[0] + ";" +
                              description.initial_velocity[1],
                            constants);
      }
    catch (...)
      {
        throw InputError(body.source_name() + ": Body " + body.name() +
                           "/Initial velocity",
                         "cannot read '" + description.initial_velocity[0] +
                           ", " + description.initial_velocity[1] + "'");
      }
    v = field_at_dofs(body, [&](const Point<2> &X, const unsigned int c) {
      const double value = velocity.value(X, c);
      if (!std::isfinite(value))
        throw InputError(body.source_name() + ": Body " + body.name() +
                           "/Initial velocity",
                         "is not finite at (" + std::to_string(X[0]) + ", " +
                           std::to_string(X[1]) + ")");
      return value;
    });
    body.system().constraints().distribute(v);
  }



  Vector<double>
  BodyInertia::field_at_dofs(
    const Body                                                  &body,
    const std::function<double(const Point<2> &, unsigned int)> &field) const
  {
    // A value dof takes the field at its support point, a Hermite
    // derivative dof the field's derivative there (by a central
    // difference, exact for the linear fields of rigid motions and uniform
    // velocities).
    Vector<double> values(body.n_dofs());
    // (a space whose dofs are not nodal values says where each takes the
    // field)
    const auto points = body.space().interpolation_points();
    if (!points.empty())
      {
        for (const auto &point : points)
          values(point.dof) = field(point.point, point.component);
        return values;
      }
    std::map<types::global_dof_index, Point<2>> support;
    DoFTools::map_dofs_to_support_points(body.space().mapping(),
                                         body.dof_handler(),
                                         support);
    const unsigned int per_dim = body.space().components_per_displacement();
    const FiniteElement<2>              &fe = body.dof_handler().get_fe();
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    const double h = 1e-6 * std::max(body.size(), 1e-300);
    // (on a mesh shared out, each dof's owner sets it, then the processes'
    // vectors are summed)
    const IndexSet owned = body.dof_handler().locally_owned_dofs();
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        if (shared_out && !body.is_own_cell(cell))
          continue;
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            if (shared_out && !owned.is_element(local[i]))
              continue;
            const unsigned int system = fe.system_to_component_index(i).first;
            const unsigned int c = system / per_dim, kind = system % per_dim;
            const Point<2>    &X = support.at(local[i]);
            if (kind == 0)
              values(local[i]) = field(X, c);
            else
              {
                Tensor<1, 2> e;
                e[kind - 1] = h;
                values(local[i]) =
                  (field(X + e, c) - field(X - e, c)) / (2. * h);
              }
          }
      }
    if (shared_out)
      processes::sum(values.begin(), values.size());
    return values;
  }



  Vector<double>
  BodyInertia::unit_rotation(const Body &body, const Point<2> &centre) const
  {
    return field_at_dofs(body, [&](const Point<2> &X, const unsigned int c) {
      return c == 0 ? -(X[1] - centre[1]) : X[0] - centre[0];
    });
  }



  double
  BodyInertia::moment_of_inertia(const Body &body, const Point<2> &centre) const
  {
    const Vector<double> w = unit_rotation(body, centre);
    return apply_mass(w) * w;
  }



  double
  BodyInertia::angular_momentum(const Body &body, const Point<2> &centre) const
  {
    return apply_mass(unit_rotation(body, centre)) * v;
  }



  void
  BodyInertia::prepare_mass_system(const Body           &body,
                                   SparsityPattern      &sparsity,
                                   SparseMatrix<double> &M)
  {
    // The mass condensed by the body's constraints without their values
    // (element relations, supports), a free massless dof's row the
    // identity.
    mass_constraints.clear();
    for (const auto &line : body.system().constraints().get_lines())
      {
        mass_constraints.add_line(line.index);
        mass_constraints.add_entries(line.index, line.entries);
      }
    mass_constraints.close();
    DynamicSparsityPattern pattern(body.n_dofs());
    if (body.space().capabilities().dofs_are_nodal_values)
      DoFTools::make_sparsity_pattern(body.dof_handler(),
                                      pattern,
                                      mass_constraints,
                                      false);
    else
      // (the functions of a cell reach beyond it: its dofs as the space
      // gives them, and the numbering's spare dofs' diagonal)
      {
        for (const auto &dofs_of_cell : cell_dofs)
          mass_constraints.add_entries_local_to_global(dofs_of_cell,
                                                       pattern,
                                                       false);
        for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
          pattern.add(i, i);
      }
    sparsity.copy_from(pattern);
    M.reinit(sparsity);
    for (unsigned int c = 0; c < cell_dofs.size(); ++c)
      if (!cell_dofs[c].empty())
        mass_constraints.distribute_local_to_global(cell_mass[c],
                                                    cell_dofs[c],
                                                    M);
    // (on a mesh shared out, M is each process's cells' share, which MUMPS
    // sums: the whole diagonal is the sum of the shares', and a massless
    // dof's 1 is put by the process that owns it)
    std::vector<double> diagonal(M.m());
    for (types::global_dof_index i = 0; i < M.m(); ++i)
      diagonal[i] = M.el(i, i);
    if (shared_out)
      processes::sum(diagonal);
    const IndexSet owned = body.dof_handler().locally_owned_dofs();
    without_mass.assign(body.n_dofs(), false);
    for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
      if (!mass_constraints.is_constrained(i) && !(diagonal[i] > 0.))
        {
          if (!shared_out || owned.is_element(i))
            M.set(i, i, 1.);
          without_mass[i] = true;
        }
    // (the numbering's spare dofs of a space that is not nodal: no cell
    // has them, so their constrained rows are empty; the 1 put once)
    if (!body.space().capabilities().dofs_are_nodal_values)
      for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
        if (mass_constraints.is_constrained(i) && diagonal[i] == 0. &&
            (!shared_out || owned.is_element(i)))
          M.set(i, i, 1.);

    // A scheme whose predictor takes the acceleration (Newmark's family),
    // with contact dofs that carry mass (Contact mass = kept, or a Hermite
    // body): the contact impulse's share of each step's acceleration,
    // M^-1 F_c, is taken out of the next step's predictor, so the mass is
    // factorised once for it.
    bool contact_with_mass = false;
    for (const auto dof : contact_dofs)
      contact_with_mass =
        contact_with_mass ||
        (!mass_constraints.is_constrained(dof) && !without_mass[dof]);
    if (scheme->predictor_takes_acceleration() && contact_with_mass)
      {
        mass_factor = std::make_unique<DirectSolver>();
        mass_factor->use_cholesky(true, {});
        mass_factor->factorize(M);
      }
  }



  void
  BodyInertia::initialize(const Body &body, const Vector<double> &residual)
  {
    // M a_0 = R_0 on the dofs that have mass and are free.
    SparsityPattern      sparsity;
    SparseMatrix<double> M;
    prepare_mass_system(body, sparsity, M);
    Vector<double> damping_0 = apply_mass(v);
    damping_0 *= settings.mass_damping;
    Vector<double> rhs = residual;
    rhs -= damping_0;
    mass_constraints.condense(rhs);
    for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
      if (without_mass[i])
        rhs(i) = 0.;
    a = rhs;
    if (shared_out)
      {
        DirectSolver solver;
        solver.use_cholesky(true, {});
        solver.factorize(M);
        solver.solve(a);
      }
    else
      {
        SparseDirectUMFPACK solver;
        solver.initialize(M);
        solver.solve(a);
      }
    mass_constraints.distribute(a);
    a_smooth = a;

    // The forces of the initial state: F_ext + F_support = M a_0 + a_M M
    // v_0 + F_int + F_v - F_c, F_int + F_v - F_ext being -residual (the
    // free dofs without mass, where M a_0 = residual does not hold, have
    // no support: F_ext alone); the smooth forces s = F_ext + F_support -
    // F_int - a_M M v - F_v.
    mass_damping_before = apply_mass(v);
    mass_damping_before *= settings.mass_damping;
    viscous_before.reinit(body.n_dofs());
    if (viscous_forces.size() == viscous_before.size())
      viscous_before = viscous_forces;
    applied_before = apply_mass(a);
    applied_before += mass_damping_before;
    applied_before -= residual;
    applied_before += body.applied_loads();
    applied_before -= body.get_contact_forces();
    for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
      if (without_mass[i])
        applied_before(i) += residual(i);
    contact_before          = body.get_contact_forces();
    Vector<double> internal = body.applied_loads();
    internal -= residual;
    internal -= viscous_before;
    frame_before.reinit(body.n_dofs());
    if (frame)
      {
        frame_before =
          frame->forces([&](const Vector<double> &x) { return apply_mass(x); },
                        body.displacement(),
                        v);
        internal += frame_before;
      }
    smooth_before = applied_before;
    smooth_before += frame_before;
    smooth_before -= internal;
    smooth_before -= mass_damping_before;
    smooth_before -= viscous_before;
    set_start_state_forces(residual);
  }



  void
  BodyInertia::set_start_state_forces(const Vector<double> &f)
  {
    const InertiaScheme::StartState state = {f,
                                             without_mass,
                                             [this]() {
                                               return apply_mass(a_smooth);
                                             },
                                             [this]() {
                                               Vector<double> force =
                                                 apply_mass(v);
                                               force *= settings.mass_damping;
                                               return force;
                                             }};
    scheme->start_state_forces(state, old_forces);
  }



  void
  BodyInertia::cell_velocity(const std::vector<types::global_dof_index> &dofs,
                             const Vector<double>                       &u,
                             std::vector<double> &velocity) const
  {
    for (unsigned int j = 0; j < dofs.size(); ++j)
      velocity[j] = step > 0. ? v_predicted(dofs[j]) +
                                  c_v * (u(dofs[j]) - u_predicted(dofs[j])) :
                                v(dofs[j]);
  }



  void
  BodyInertia::begin_step(const Vector<double> &u_n,
                          const double          dt,
                          const double          t)
  {
    step    = dt;
    u_start = u_n;
    if (frame)
      frame->set_time(t);
    // (the smooth acceleration: the contact acts by the step's impulse)
    const InertiaScheme::StepCoefficients c =
      scheme->predict(u_n, v, a_smooth, dt, u_predicted, v_predicted);
    c_M              = c.inertia;
    c_v              = c.velocity;
    c_a              = c.acceleration;
    impulse_velocity = c.impulse_velocity;
    predicted_force  = apply_mass(v_predicted).l2_norm() / dt;
  }



  void
  BodyInertia::add_cell_terms(const unsigned int                          cell,
                              const std::vector<types::global_dof_index> &dofs,
                              const Vector<double>                       &u,
                              FullMatrix<double>  &cell_matrix,
                              Vector<double>      &cell_rhs,
                              std::vector<double> &work) const
  {
    // (no step yet: the assembly of the initial state, whose residual
    // gives the initial acceleration)
    if (step == 0.)
      {
        // (the frame's forces of the initial state, at its velocity)
        if (frame)
          {
            std::vector<double> velocity(dofs.size());
            for (unsigned int j = 0; j < dofs.size(); ++j)
              velocity[j] = v(dofs[j]);
            frame->add_cell_terms(
              cell_mass[cell], dofs, u, velocity, 0., nullptr, cell_rhs);
          }
        return;
      }
    const double              a_M = settings.mass_damping;
    const FullMatrix<double> &m   = cell_mass[cell];
    const unsigned int        n   = dofs.size();
    // M (c_M (u - u~) + a_M v(u)) = M ((c_M + a_M c_v) (u - u~) + a_M v~)
    const double factor = c_M + a_M * c_v;
    work.resize(n);
    for (unsigned int j = 0; j < n; ++j)
      work[j] = factor * (u(dofs[j]) - u_predicted(dofs[j])) +
                a_M * v_predicted(dofs[j]);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (m(i, j) != 0.)
          {
            cell_rhs(i) -= m(i, j) * work[j];
            cell_matrix(i, j) += factor * m(i, j);
          }
    if (frame)
      {
        std::vector<double> velocity(n);
        for (unsigned int j = 0; j < n; ++j)
          velocity[j] =
            v_predicted(dofs[j]) + c_v * (u(dofs[j]) - u_predicted(dofs[j]));
        frame->add_cell_terms(
          m, dofs, u, velocity, c_v, &cell_matrix, cell_rhs);
      }
  }



  void
  BodyInertia::accept_step(const Body &body, EnergyAccount &account)
  {
    const Vector<double> &u       = body.displacement();
    const Vector<double> &contact = body.get_contact_forces();
    if (without_mass.empty())
      {
        // (a run continued from a checkpoint: the state was read, the
        // mass's structure is made here)
        SparsityPattern      sparsity;
        SparseMatrix<double> M;
        prepare_mass_system(body, sparsity, M);
      }
    // With contact dofs that carry mass, under a scheme whose predictor
    // takes the acceleration: q = M^-1 F_c (zero on the massless dofs,
    // whose forces move no mass).
    Vector<double> contact_acceleration(u.size());
    if (mass_factor)
      {
        contact_acceleration = contact;
        for (types::global_dof_index i = 0; i < u.size(); ++i)
          if (without_mass[i])
            contact_acceleration(i) = 0.;
        mass_constraints.condense(contact_acceleration);
        mass_factor->solve(contact_acceleration);
        mass_constraints.distribute(contact_acceleration);
      }
    const double kinetic_before = kinetic_energy();
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      {
        v(i) = v_predicted(i) + c_v * (u(i) - u_predicted(i));
        a(i) = c_a * (u(i) - u_predicted(i));
      }
    a_smooth = a;
    if (mass_factor)
      {
        // Kane et al.'s contact-implicit scheme: the contact's impulse P =
        // w dt F_c changes the velocity by M^-1 P = w dt q, the smooth
        // forces by the scheme's rule. The end equation's inertia force
        // balances F_c by u - u~ = q / c_M, which the formulas count in the
        // end state's a (c_a / c_M q): the next predictor takes the smooth
        // acceleration alone, and v the impulse's change
        // (StepCoefficients::impulse_velocity).
        a_smooth.add(-c_a / c_M, contact_acceleration);
        v.add(impulse_velocity, contact_acceleration);
      }

    // The converged assembly's unbalanced forces are F_int + M (c_M (u -
    // u~) + a_M v) + F_v - F_ext - f_old on every dof (f_old: the start
    // state's forces the step carries), its applied loads F_ext + f_old;
    // where a dof is constrained, the equation of motion gives the
    // support's reaction.
    Vector<double> inertia(u.size());
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      inertia(i) = c_M * (u(i) - u_predicted(i)) +
                   settings.mass_damping *
                     (v_predicted(i) + c_v * (u(i) - u_predicted(i)));
    const Vector<double> inertia_force = apply_mass(inertia);
    // F_ext + F_support = F_int + M (..) + F_v - F_c - f_old
    Vector<double> applied = body.unbalanced_forces();
    applied += body.applied_loads();
    applied -= contact;
    applied -= old_forces;
    Vector<double> viscous(u.size());
    if (viscous_forces.size() == u.size())
      viscous = viscous_forces;
    Vector<double> internal = body.unbalanced_forces();
    internal += body.applied_loads();
    internal -= inertia_force;
    internal -= viscous;
    Vector<double> mass_damping(u.size());
    if (settings.mass_damping != 0.)
      {
        mass_damping = apply_mass(v);
        mass_damping *= settings.mass_damping;
      }
    // A turning frame's forces, at the velocity of the step's equation (the
    // assembly counted them with the inertia: they are loads here).
    Vector<double> frame_forces(u.size());
    if (frame)
      {
        Vector<double> v_equation = v_predicted;
        for (types::global_dof_index i = 0; i < u.size(); ++i)
          v_equation(i) += c_v * (u(i) - u_predicted(i));
        frame_forces =
          frame->forces([&](const Vector<double> &x) { return apply_mass(x); },
                        u,
                        v_equation);
        internal += frame_forces;
      }
    // The smooth forces s = F_ext + F_support + F_frame - F_int - a_M M v -
    // F_v.
    Vector<double> smooth = applied;
    smooth += frame_forces;
    smooth -= internal;
    smooth -= mass_damping;
    smooth -= viscous;

    Vector<double> du = u;
    du -= u_start;
    const auto trapezoid = [&](const Vector<double> &before,
                               const Vector<double> &now) {
      return 0.5 * (before * du + now * du);
    };
    account.work_of_loads += trapezoid(applied_before, applied) +
                             trapezoid(frame_before, frame_forces);
    account.damping_dissipation +=
      trapezoid(mass_damping_before, mass_damping) +
      trapezoid(viscous_before, viscous);
    // The contact acts by the step's impulse P, whose force in the
    // equation of the end state is F_c = P / (w dt): its work on the step's
    // motion is P . du / dt.
    const double contact_work =
      scheme->contact_impulse_weight() * (contact * du);
    account.contact_work += contact_work;
    // The scheme's own dissipation: what the kinetic energy lacks of the
    // work of the step's mean smooth force and of the contact impulse
    // (zero to round-off for the trapezoidal rule; (theta - 1/2)
    // (|v_n+1 - v_n|_M^2 + |du|_K^2) for Moreau-Jean on a linear body).
    account.scheme_dissipation += trapezoid(smooth_before, smooth) +
                                  contact_work -
                                  (kinetic_energy() - kinetic_before);

    applied_before      = applied;
    contact_before      = contact;
    mass_damping_before = mass_damping;
    viscous_before      = viscous;
    smooth_before       = smooth;
    frame_before        = frame_forces;
    // F_ext - F_int - F_v (+ F_frame) at the end state, on every dof.
    Vector<double> f = inertia_force;
    f -= old_forces;
    f -= body.unbalanced_forces();
    set_start_state_forces(f);
  }



  Vector<double>
  BodyInertia::apply_mass(const Vector<double> &x) const
  {
    Vector<double> y(x.size());
    mass_matrix.vmult(y, x);
    // (every process calls it: the processes' shares summed)
    if (shared_out)
      processes::sum(y.begin(), y.size());
    return y;
  }



  double
  BodyInertia::force_scale() const
  {
    return step > 0. ? predicted_force : 0.;
  }



  std::array<double, 2>
  BodyInertia::momentum() const
  {
    const Vector<double> p = apply_mass(v);
    return {{translation[0] * p, translation[1] * p}};
  }



  double
  BodyInertia::kinetic_energy() const
  {
    return 0.5 * (apply_mass(v) * v);
  }



} // namespace glissade
