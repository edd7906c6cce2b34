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
                           const std::set<types::global_dof_index> &massless,
                           const std::string                       &where)
    : settings(settings)
  {
    const ElementSpace &space = body.space();
    if (space.components_per_displacement() != 1 && settings.lumped_mass)
      throw InputError(where + "/Material",
                       "Time integration/Mass = lumped is for nodal element "
                       "spaces; body '" +
                         body.name() + "' uses " + space.name() +
                         ", whose derivative dofs have no lumped mass: use "
                         "Mass = consistent");
    const bool axisymmetric =
      body.hypothesis() == PlaneHypothesis::axisymmetric;
    auto                      evaluator = space.create_evaluator();
    const unsigned int        n         = evaluator->dofs_per_cell();
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = evaluator->displacement_component(i);
    // (a Hermite body keeps its mass where it touches: its derivative dofs
    // would need their own redistribution, not derived here)
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
        cell_dofs[index].resize(n);
        cell->get_dof_indices(cell_dofs[index]);
        const double rho =
          body.materials().density_of_cell(cell->material_id());
        FullMatrix<double> &m = cell_mass[index];
        m.reinit(n, n);
        evaluator->reinit(cell);
        for (unsigned int q = 0; q < evaluator->n_quadrature_points(); ++q)
          {
            const double dV =
              evaluator->JxW(q) *
              (axisymmetric ? 2. * M_PI * evaluator->quadrature_point(q)[0] :
                              body.thickness());
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
    v.reinit(body.n_dofs());
    a.reinit(body.n_dofs());
    old_forces.reinit(body.n_dofs());
    // The unit translations: every value dof of a component at 1 (a
    // Hermite body's derivative dofs at 0).
    const unsigned int      per_dim = space.components_per_displacement();
    const FiniteElement<2> &fe      = body.dof_handler().get_fe();
    for (unsigned int c = 0; c < 2; ++c)
      translation[c].reinit(body.n_dofs());
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
  }



  void
  BodyInertia::set_initial_velocity(const Body &body)
  {
    // The initial velocity at each dof's support point: a value dof takes
    // v there, a Hermite derivative dof the derivative of v (by a central
    // difference of the expressions, exact for the linear fields of rigid
    // motions and uniform velocities).
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
              v(local[i]) = velocity.value(X, c);
            else
              {
                Tensor<1, 2> e;
                e[kind - 1] = h;
                v(local[i]) =
                  (velocity.value(X + e, c) - velocity.value(X - e, c)) /
                  (2. * h);
              }
            if (!std::isfinite(v(local[i])))
              throw InputError(body.source_name() + ": Body " + body.name() +
                                 "/Initial velocity",
                               "is not finite at (" + std::to_string(X[0]) +
                                 ", " + std::to_string(X[1]) + ")");
          }
      }
    if (shared_out)
      processes::sum(v.begin(), v.size());
    body.system().constraints().distribute(v);
  }



  void
  BodyInertia::initialize(const Body &body, const Vector<double> &residual)
  {
    // M a_0 = R_0 on the dofs that have mass and are free: the mass
    // condensed by the body's constraints without their values (element
    // relations, supports), a massless dof's row the identity.
    AffineConstraints<double> homogeneous;
    for (const auto &line : body.system().constraints().get_lines())
      {
        homogeneous.add_line(line.index);
        homogeneous.add_entries(line.index, line.entries);
      }
    homogeneous.close();
    DynamicSparsityPattern pattern(body.n_dofs());
    DoFTools::make_sparsity_pattern(body.dof_handler(),
                                    pattern,
                                    homogeneous,
                                    false);
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> M(sparsity);
    for (unsigned int c = 0; c < cell_dofs.size(); ++c)
      if (!cell_dofs[c].empty())
        homogeneous.distribute_local_to_global(cell_mass[c], cell_dofs[c], M);
    damping_before = apply_mass(v);
    damping_before *= settings.mass_damping;
    Vector<double> rhs = residual;
    rhs -= damping_before;
    homogeneous.condense(rhs);
    // (on a mesh shared out, M is each process's cells' share, which MUMPS
    // sums: the whole diagonal is the sum of the shares', and a massless
    // dof's 1 is put by the process that owns it)
    std::vector<double> diagonal(M.m());
    for (types::global_dof_index i = 0; i < M.m(); ++i)
      diagonal[i] = M.el(i, i);
    if (shared_out)
      processes::sum(diagonal);
    const IndexSet owned = body.dof_handler().locally_owned_dofs();
    for (types::global_dof_index i = 0; i < body.n_dofs(); ++i)
      if (!homogeneous.is_constrained(i) && !(diagonal[i] > 0.))
        {
          if (!shared_out || owned.is_element(i))
            M.set(i, i, 1.);
          rhs(i) = 0.;
        }
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
    homogeneous.distribute(a);

    // Moreau-Jean's start-state loads: (1 - theta) / theta (F_ext -
    // F_int)_0.
    old_forces.reinit(body.n_dofs());
    if (settings.scheme == TimeIntegrationSettings::Scheme::moreau_jean)
      {
        old_forces = residual;
        old_forces *= (1. - settings.theta) / settings.theta;
      }

    // The forces of the initial state, for the first step's work: F_ext +
    // F_support = M a_0 + a_M M v_0 + F_int + F_v - F_c, F_int + F_v -
    // F_ext being -residual.
    applied_before = apply_mass(a);
    applied_before += damping_before;
    applied_before -= residual;
    applied_before += body.applied_loads();
    applied_before -= body.get_contact_forces();
    contact_before = body.get_contact_forces();
    if (viscous_forces.size() == damping_before.size())
      damping_before += viscous_forces;
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
  BodyInertia::begin_step(const Vector<double> &u_n, const double dt)
  {
    step    = dt;
    u_start = u_n;
    if (settings.scheme == TimeIntegrationSettings::Scheme::moreau_jean)
      {
        const double theta = settings.theta;
        u_predicted        = u_n;
        u_predicted.add(dt, v);
        v_predicted = v;
        c_a         = 1. / (theta * theta * dt * dt);
        c_v         = 1. / (theta * dt);
        return;
      }
    const double beta = settings.beta, gamma = settings.gamma;
    u_predicted = u_n;
    u_predicted.add(dt, v, dt * dt * (0.5 - beta), a);
    v_predicted = v;
    v_predicted.add((1. - gamma) * dt, a);
    c_a = 1. / (beta * dt * dt);
    c_v = gamma / (beta * dt);
  }



  void
  BodyInertia::add_cell_terms(const unsigned int                          cell,
                              const std::vector<types::global_dof_index> &dofs,
                              const Vector<double>                       &u,
                              FullMatrix<double> &cell_matrix,
                              Vector<double>     &cell_rhs) const
  {
    // (no step yet: the assembly of the initial state, whose residual
    // gives the initial acceleration)
    if (step == 0.)
      return;
    const double              a_M = settings.mass_damping;
    const FullMatrix<double> &m   = cell_mass[cell];
    const unsigned int        n   = dofs.size();
    // M (a(u) + a_M v(u)) = M ((c_a + a_M c_v) (u - u~) + a_M v~)
    Vector<double> x(n);
    for (unsigned int j = 0; j < n; ++j)
      x(j) = (c_a + a_M * c_v) * (u(dofs[j]) - u_predicted(dofs[j])) +
             a_M * v_predicted(dofs[j]);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (m(i, j) != 0.)
          {
            cell_rhs(i) -= m(i, j) * x(j);
            cell_matrix(i, j) += (c_a + a_M * c_v) * m(i, j);
          }
  }



  void
  BodyInertia::accept_step(const Body &body, EnergyAccount &account)
  {
    const Vector<double> &u = body.displacement();
    const bool            moreau_jean =
      settings.scheme == TimeIntegrationSettings::Scheme::moreau_jean;
    const Vector<double> v_start = v;
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      {
        v(i) = v_predicted(i) + c_v * (u(i) - u_predicted(i));
        a(i) = moreau_jean ? (v(i) - v_start(i)) / step :
                             c_a * (u(i) - u_predicted(i));
      }
    // M a + C v + F_int = F_ext + F_c + F_support, and the last assembly
    // was the converged state's: F_ext + F_support = (F_int + M a + C v -
    // F_ext) + F_ext - F_c on every dof.
    Vector<double> applied = body.unbalanced_forces();
    applied += body.applied_loads();
    applied -= body.get_contact_forces();
    applied -= old_forces; // (Moreau-Jean's start-state forces: not loads)
    Vector<double> damping = apply_mass(v);
    damping *= settings.mass_damping;
    if (viscous_forces.size() == damping.size())
      damping += viscous_forces;
    Vector<double> du = u;
    du -= u_start;
    const auto trapezoid = [&](const Vector<double> &before,
                               const Vector<double> &now) {
      return 0.5 * (before * du + now * du);
    };
    account.work_of_loads += trapezoid(applied_before, applied);
    account.contact_work +=
      trapezoid(contact_before, body.get_contact_forces());
    account.damping_dissipation += trapezoid(damping_before, damping);
    applied_before = applied;
    contact_before = body.get_contact_forces();
    damping_before = damping;
    if (moreau_jean)
      {
        // f_n+1 = F_ext - F_int at the end state, from the converged
        // assembly's unbalanced forces F_int + M (a + a_M v) - F_ext -
        // (1 - theta) / theta f_n, on every dof.
        const double   theta = settings.theta;
        Vector<double> inertia(u.size());
        for (types::global_dof_index i = 0; i < u.size(); ++i)
          inertia(i) =
            c_a * (u(i) - u_predicted(i)) + settings.mass_damping * v(i);
        Vector<double> f = apply_mass(inertia);
        f -= old_forces;
        f -= body.unbalanced_forces();
        old_forces = f;
        old_forces *= (1. - theta) / theta;
      }
  }



  Vector<double>
  BodyInertia::apply_mass(const Vector<double> &x) const
  {
    Vector<double> y(x.size());
    for (unsigned int c = 0; c < cell_dofs.size(); ++c)
      for (unsigned int i = 0; i < cell_dofs[c].size(); ++i)
        for (unsigned int j = 0; j < cell_dofs[c].size(); ++j)
          y(cell_dofs[c][i]) += cell_mass[c](i, j) * x(cell_dofs[c][j]);
    // (every process calls it: the processes' shares summed)
    if (shared_out)
      processes::sum(y.begin(), y.size());
    return y;
  }



  double
  BodyInertia::force_scale() const
  {
    return step > 0. ? apply_mass(v_predicted).l2_norm() / step : 0.;
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
