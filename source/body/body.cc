#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/base/user_function.h>
#include <glissade/body/body.h>
#include <glissade/body/viscous_stress.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/mesh/mesh_diameter.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  Body::Body(const BodyDescription &description, const std::string &source)
    : description(description)
    , source(source)
  {
    const std::string where = source + ": Body " + description.name;
    const MeshLabels  labels =
      MeshFactory::create(description.mesh, mesh, where);
    named_boundaries   = labels.boundaries;
    reference_size     = mesh_diameter(mesh);
    materials_of_cells = std::make_unique<BodyMaterials>(
      description.material,
      labels.regions,
      MeshFactory::type(description.mesh.type).from_file ?
        description.mesh.file :
        "",
      where);

    element_space = ElementSpaceRegistry::create(description.element_space);
    const bool axisymmetric =
      description.material.hypothesis == PlaneHypothesis::axisymmetric;
    if (axisymmetric)
      check_axisymmetric_mesh(where);
    // A second-order file's curved edges are followed by a mapping of
    // degree two or more; a bilinear or Hermite body would silently see
    // the chords instead.
    if (labels.second_order && (description.element_space == "q1" ||
                                description.element_space == "hermite"))
      throw InputError(where + "/Element/Space",
                       "'" + description.mesh.file +
                         "' has second-order quadrilaterals, whose curved "
                         "edges a '" +
                         description.element_space +
                         "' body cannot follow: choose q2, q8, q3 or q12, "
                         "or save the mesh first-order (gmsh -order 1)");
    dofs.reinit(mesh);
    dofs.distribute_dofs(element_space->finite_element());
    element_space->setup(dofs, element_constraints);

    boundary_conditions =
      std::make_unique<BoundaryConditions>(description, named_boundaries, mesh);
    if (!description.gravity.empty())
      gravity =
        std::make_unique<UserFunction>(description.gravity,
                                       where + "/Boundary conditions/Gravity");
    if (axisymmetric)
      boundary_conditions->hold_on_axis(dofs_on_axis());

    solution.reinit(dofs.n_dofs());
    stored_solution.reinit(dofs.n_dofs());
    unconstrained_residual.reinit(dofs.n_dofs());
    contact_forces.reinit(dofs.n_dofs());

    // The constraints at t = 0 say which dofs are constrained, which never
    // changes during a run: the system's sparsity pattern is built on them.
    // (Cholesky where the tangent is symmetric, no follower pressure.)
    AffineConstraints<double> constraints;
    boundary_conditions->make_constraints(
      dofs, *element_space, 0., solution, element_constraints, constraints);
    bool symmetric = true;
    for (const auto &load : boundary_conditions->surface_loads())
      symmetric = symmetric && !load.is_pressure;
    linear_system = std::make_unique<BodyLinearSystem>(
      dofs,
      *element_space,
      std::move(constraints),
      symmetric,
      RigidMotionSprings(
        free_motions_of_supports(), source, description.name, reference_size));
  }



  std::vector<RigidMotion>
  Body::free_motions_of_supports() const
  {
    // About the centre of the body's bounding box.
    const auto box = GridTools::compute_bounding_box(mesh);
    const auto basis =
      rigid_motion_basis(box.center(), std::max(reference_size, 1e-300));
    const std::vector<RigidMotion> all(basis.begin(), basis.end());
    const auto                     rows =
      boundary_conditions->support_rows(dofs, *element_space, basis);
    std::vector<RigidMotion> free_motions;
    if (description.material.hypothesis == PlaneHypothesis::axisymmetric)
      {
        // A body of revolution has one rigid motion, along its axis (a
        // radial translation or a rotation would strain its hoops).
        bool held = false;
        for (const auto &row : rows)
          held = held || std::abs(row[1]) > 1e-12;
        if (!held)
          free_motions.push_back(basis[1]);
      }
    else
      for (const auto &coefficients : null_space(rows, 3))
        free_motions.push_back(combine(all, coefficients));
    return free_motions;
  }



  void
  Body::check_axisymmetric_mesh(const std::string &where) const
  {
    if (description.element_space == "hermite")
      throw InputError(
        where + "/Material/Hypothesis",
        "axisymmetric bodies are not implemented for Hermite elements: "
        "their derivative dofs would need the axis condition on the "
        "derivatives of u_r too (du_r/dz = 0 on the axis), and the hoop "
        "strain u_r / r of a C1 field near the axis is not what the "
        "element was built for; use q1, q2, q3, q8 or q12");
    // r >= 0: a cell with a vertex left of the axis would have a negative
    // ring volume there.
    const double tolerance = 1e-12 * std::max(reference_size, 1e-300);
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v)[0] < -tolerance)
          {
            std::ostringstream message;
            message << "an axisymmetric body needs its mesh in x = r >= 0 "
                    << "(x is the radius, y the axis): cell "
                    << cell->active_cell_index() << " has a vertex at ("
                    << cell->vertex(v)[0] << ", " << cell->vertex(v)[1] << ")";
            throw InputError(where + "/Mesh", message.str());
          }
  }



  std::vector<types::global_dof_index>
  Body::dofs_on_axis() const
  {
    // The x dofs whose support point lies on x = 0 (every space but
    // Hermite's has one value dof per node and component).
    std::map<types::global_dof_index, Point<2>> support_points;
    DoFTools::map_dofs_to_support_points(element_space->mapping(),
                                         dofs,
                                         support_points);
    const double tolerance = 1e-12 * std::max(reference_size, 1e-300);
    std::vector<types::global_dof_index> on_axis;
    const FiniteElement<2>              &fe = dofs.get_fe();
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    radial;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          if (fe.system_to_component_index(i).first == 0)
            radial.insert(local[i]);
      }
    for (const auto &[dof, X] : support_points)
      if (radial.count(dof) && std::abs(X[0]) <= tolerance)
        on_axis.push_back(dof);
    return on_axis;
  }



  void
  Body::set_time(const double new_time)
  {
    time = new_time;
  }



  bool
  Body::assemble()
  {
    boundary_conditions->make_constraints(dofs,
                                          *element_space,
                                          time,
                                          solution,
                                          element_constraints,
                                          linear_system->constraints());

    linear_system->clear();
    unconstrained_residual = 0.;
    Vector<double> internal_forces(dofs.n_dofs());
    Vector<double> viscous_forces(inertia_terms ? dofs.n_dofs() : 0);

    const double thickness = description.material.thickness;
    const bool   axisymmetric =
      description.material.hypothesis == PlaneHypothesis::axisymmetric;
    // Small strain: the virtual strains and the equilibrium on the
    // undeformed body (F = I in them, no geometric stiffness).
    const bool small_strain =
      description.material.kinematics == Kinematics::small_strain;
    if (small_strain && kept_linear_stiffness.empty())
      kept_linear_stiffness.resize(dofs.get_triangulation().n_active_cells());
    const auto         boundary_evaluator = element_space->create_evaluator();
    const unsigned int n_local            = boundary_evaluator->dofs_per_cell();
    std::vector<unsigned int> component(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      component[i] = boundary_evaluator->displacement_component(i);

    bool admissible = true;
    problem.clear();
    if (!std::isfinite(solution.l2_norm()))
      {
        problem = "the displacement of body '" + name() +
                  "' is not finite: the Newton correction was, from a "
                  "singular tangent (a rigid-body motion that no support "
                  "holds? see Boundary conditions)";
        return false;
      }

    // The cells are integrated on every core (deal.II's WorkStream); what
    // each one adds to the global vectors and matrix is added by one
    // thread, cell after cell in the order of the mesh, so the sums are
    // the same bits as in a sequential loop (ctest -R determinism). The
    // surface loads are added there too: their muParser functions hold a
    // time and are not safe to share between threads.
    struct Scratch
    {
      Scratch(const ElementSpace &space, const unsigned int n_local)
        : space(space)
        , evaluator(space.create_evaluator())
        , grad(n_local)
        , dE(n_local)
        , D_dE(n_local)
      {}
      Scratch(const Scratch &other)
        : Scratch(other.space, other.grad.size())
      {}
      const ElementSpace                &space;
      std::unique_ptr<CellEvaluator>     evaluator;
      std::vector<Tensor<1, 2>>          grad;
      std::vector<SymmetricTensor<2, 2>> dE, D_dE;
      // (axisymmetric: each dof's hoop strain variation dE_33 and the hoop
      // stress variation dS_33 it causes)
      std::vector<double> dE33 = std::vector<double>(grad.size()),
                          dS33 = std::vector<double>(grad.size());
      // (stiffness damping: the cell's velocity dofs)
      std::vector<double> cell_velocity = std::vector<double>(grad.size());
      // (small strain: the cell's displacement or velocity dofs, and K_e
      // times them)
      Vector<double> cell_values  = Vector<double>(grad.size()),
                     cell_product = Vector<double>(grad.size());
    };
    struct CellContribution
    {
      explicit CellContribution(const unsigned int n_local)
        : cell_matrix(n_local, n_local)
        , cell_rhs(n_local)
        , viscous_force(n_local)
        , local_dofs(n_local)
      {}
      // The surface loads are added to them in the (sequential) copier,
      // which WorkStream hands a const reference.
      mutable FullMatrix<double>           cell_matrix;
      mutable Vector<double>               cell_rhs;
      Vector<double>                       viscous_force;
      std::vector<types::global_dof_index> local_dofs;
      std::string                          rejection; // why, if inadmissible
      typename DoFHandler<2>::active_cell_iterator cell;
    };

    const auto integrate =
      [&](const typename DoFHandler<2>::active_cell_iterator &cell,
          Scratch                                            &scratch,
          CellContribution                                   &data) {
        CellEvaluator &evaluator   = *scratch.evaluator;
        auto          &grad        = scratch.grad;
        auto          &dE          = scratch.dE;
        auto          &D_dE        = scratch.D_dE;
        auto          &dE33        = scratch.dE33;
        auto          &dS33        = scratch.dS33;
        auto          &cell_matrix = data.cell_matrix;
        auto          &cell_rhs    = data.cell_rhs;
        data.cell                  = cell;
        data.rejection.clear();
        cell->get_dof_indices(data.local_dofs);
        cell_matrix        = 0.;
        cell_rhs           = 0.;
        data.viscous_force = 0.;
        const Material &cell_material =
          materials_of_cells->of_cell(cell->material_id());
        // Stiffness damping: the material at rest and the cell's velocity.
        const double damping_a_K =
          inertia_terms ? inertia_terms->stiffness_damping() : 0.;
        MaterialPointResponse at_rest;
        if (damping_a_K > 0.)
          {
            if (!small_strain)
              at_rest = cell_material.evaluate(Tensor<2, 2>(), 0.);
            inertia_terms->cell_velocity(data.local_dofs,
                                         solution,
                                         scratch.cell_velocity);
          }
        // A small-strain cell's stiffness K_e does not depend on u: it is
        // integrated once and kept, and its forces are K_e u_e (each cell
        // writes its own slot: safe on every thread).
        FullMatrix<double> &kept =
          small_strain ? kept_linear_stiffness[cell->active_cell_index()] :
                         cell_matrix;
        const bool integrate_points = !small_strain || kept.empty();
        if (integrate_points)
          evaluator.reinit(cell);

        for (unsigned int q = 0;
             integrate_points && q < evaluator.n_quadrature_points();
             ++q)
          {
            // Every shape function is primitive: Grad N_i has a single
            // non-zero row (its component c_i), which makes every
            // contraction below a small dot product.
            Tensor<2, 2> H; // displacement gradient
            for (unsigned int i = 0; i < n_local; ++i)
              {
                grad[i] = evaluator.shape_grad(i, q);
                H[component[i]] += solution(data.local_dofs[i]) * grad[i];
              }
            const Tensor<2, 2> F = small_strain ?
                                     Tensor<2, 2>(unit_symmetric_tensor<2>()) :
                                     unit_symmetric_tensor<2>() + H;
            // Axisymmetric: the hoop stretch F_33 = 1 + u_r / r, r the
            // reference radius of the point (> 0 at every quadrature point
            // of a mesh in r >= 0), and the volume of the ring 2 pi r dA.
            double       hoop = 0.;
            const double r    = evaluator.quadrature_point(q)[0];
            if (axisymmetric)
              {
                for (unsigned int i = 0; i < n_local; ++i)
                  if (component[i] == 0)
                    hoop += solution(data.local_dofs[i]) *
                            evaluator.shape_value(i, q);
                hoop /= r;
              }
            const double J =
              determinant(unit_symmetric_tensor<2>() + H) * (1. + hoop);
            if (!(J > 0.) || !std::isfinite(J) || !(1. + hoop > 0.))
              {
                std::ostringstream why;
                why << "is inverted, det F = " << J
                    << " (an increment too large for the deformation, or a "
                       "mesh too coarse for it)";
                if (data.rejection.empty())
                  data.rejection = why.str();
                continue;
              }
            const MaterialPointResponse response =
              cell_material.evaluate(H, hoop);
            // The tangent too: at u = 0 the stress is zero however large
            // E is, and only the stiffness overflows.
            if (!std::isfinite(response.stress.norm()) ||
                !std::isfinite(response.tangent.norm()))
              {
                std::ostringstream why;
                const auto [young_modulus, entry] =
                  materials_of_cells->young_modulus_of_cell(
                    cell->material_id());
                why << "has a stress or stiffness that is not finite: the "
                    << entry << " (" << young_modulus
                    << ") times the strain is beyond double precision; "
                       "express the scene in other units";
                if (data.rejection.empty())
                  data.rejection = why.str();
                continue;
              }
            const Tensor<2, 2> P = F * Tensor<2, 2>(response.stress);
            const double       dV =
              evaluator.JxW(q) * (axisymmetric ? 2. * M_PI * r : thickness);

            for (unsigned int i = 0; i < n_local; ++i)
              {
                const unsigned int c = component[i];
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int b = a; b < 2; ++b)
                    dE[i][a][b] =
                      0.5 * (F[c][a] * grad[i][b] + F[c][b] * grad[i][a]);
                D_dE[i] = response.tangent * dE[i];
                cell_rhs(i) -= (P[c] * grad[i]) * dV;
                if (axisymmetric)
                  {
                    // dE_33 = F_33 du_r / r; the hoop stress works on it.
                    dE33[i] = c == 0 ? (small_strain ? 1. : 1. + hoop) *
                                         evaluator.shape_value(i, q) / r :
                                       0.;
                    D_dE[i] += response.hoop_coupling * dE33[i];
                    dS33[i] = response.hoop_coupling * dE[i] +
                              response.hoop_stiffness * dE33[i];
                    cell_rhs(i) -= response.hoop_stress * dE33[i] * dV;
                  }
              }
            for (unsigned int i = 0; i < n_local; ++i)
              {
                const Tensor<1, 2> S_grad_i =
                  Tensor<2, 2>(response.stress) * grad[i];
                for (unsigned int j = 0; j <= i; ++j)
                  {
                    double k = dE[j] * D_dE[i];
                    if (component[i] == component[j] && !small_strain)
                      k += S_grad_i * grad[j];
                    if (axisymmetric)
                      {
                        k += dE33[j] * dS33[i];
                        // d(dE_33)/du_r = N_i N_j / r^2 (radial dofs)
                        if (component[i] == 0 && component[j] == 0 &&
                            !small_strain)
                          k += response.hoop_stress *
                               evaluator.shape_value(i, q) *
                               evaluator.shape_value(j, q) / (r * r);
                      }
                    cell_matrix(i, j) += k * dV;
                  }
              }
            if (damping_a_K > 0. && !small_strain)
              add_viscous_stress_terms(
                damping_a_K,
                inertia_terms->velocity_factor(),
                ViscousStressPoint{at_rest, F, 1. + hoop, r, axisymmetric, dV},
                evaluator,
                q,
                component,
                grad,
                dE,
                dE33,
                scratch.cell_velocity,
                cell_matrix,
                cell_rhs,
                data.viscous_force);
          }
        if (integrate_points)
          for (unsigned int i = 0; i < n_local; ++i)
            for (unsigned int j = i + 1; j < n_local; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);
        if (small_strain)
          {
            if (integrate_points)
              kept = cell_matrix;
            else
              {
                // F_int = K_e u_e, exactly (linear elasticity).
                cell_matrix = kept;
                for (unsigned int i = 0; i < n_local; ++i)
                  scratch.cell_values(i) = solution(data.local_dofs[i]);
                kept.vmult(scratch.cell_product, scratch.cell_values);
                cell_rhs -= scratch.cell_product;
              }
            // The viscous stress a_K D_0 : d(epsilon)/dt: a_K K_e v_e, its
            // tangent a_K c_v K_e.
            if (damping_a_K > 0.)
              {
                for (unsigned int i = 0; i < n_local; ++i)
                  scratch.cell_values(i) = scratch.cell_velocity[i];
                kept.vmult(data.viscous_force, scratch.cell_values);
                data.viscous_force *= damping_a_K;
                cell_rhs -= data.viscous_force;
                cell_matrix.add(damping_a_K * inertia_terms->velocity_factor(),
                                kept);
              }
          }
        // A dynamic scheme's inertia (BodyInertia: read only, so shared by
        // the threads).
        if (inertia_terms)
          inertia_terms->add_cell_terms(cell->active_cell_index(),
                                        data.local_dofs,
                                        solution,
                                        cell_matrix,
                                        cell_rhs);
      };

    // The first cell that makes the state inadmissible names the problem.
    const auto add = [&](const CellContribution &data) {
      auto       &cell_matrix = data.cell_matrix;
      auto       &cell_rhs    = data.cell_rhs;
      const auto &cell        = data.cell;
      if (!data.rejection.empty())
        {
          if (admissible)
            {
              std::ostringstream message;
              message << "cell " << cell->active_cell_index() << " of body '"
                      << name() << "' at (" << cell->center()[0] << ", "
                      << cell->center()[1] << ") " << data.rejection;
              problem = message.str();
            }
          admissible = false;
        }
      for (unsigned int i = 0; i < n_local; ++i)
        internal_forces(data.local_dofs[i]) -= cell_rhs(i);
      if (viscous_forces.size() > 0)
        for (unsigned int i = 0; i < n_local; ++i)
          viscous_forces(data.local_dofs[i]) += data.viscous_force(i);

      if (cell->at_boundary())
        assemble_surface_loads(
          cell, data.local_dofs, *boundary_evaluator, cell_matrix, cell_rhs);
      if (gravity)
        assemble_weight(cell, *boundary_evaluator, cell_rhs);

      for (unsigned int i = 0; i < n_local; ++i)
        unconstrained_residual(data.local_dofs[i]) -= cell_rhs(i);
      linear_system->add_cell(cell_matrix, cell_rhs, data.local_dofs);
    };

    WorkStream::run(dofs.begin_active(),
                    dofs.end(),
                    integrate,
                    add,
                    Scratch(*element_space, n_local),
                    CellContribution(n_local));

    if (inertia_terms)
      inertia_terms->set_viscous_forces(viscous_forces);

    Vector<double> point_loads(dofs.n_dofs());
    boundary_conditions->add_point_loads(dofs,
                                         *element_space,
                                         time,
                                         point_loads);
    // (a Moreau-Jean step carries its start state's forces as loads)
    if (inertia_terms)
      point_loads += inertia_terms->step_forces();
    unconstrained_residual -= point_loads;
    linear_system->add_nodal_forces(point_loads);

    internal_force_norm = internal_forces.l2_norm();
    external_forces     = internal_forces;
    external_forces -= unconstrained_residual;
    external_force_norm = external_forces.l2_norm();
    if (admissible && !std::isfinite(unconstrained_residual.l2_norm()))
      problem = "the residual of body '" + name() +
                "' is not finite (a load or a prescribed displacement out of "
                "the range of double precision?)";
    return admissible && problem.empty();
  }



  void
  Body::assemble_surface_loads(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>         &local_dofs,
    CellEvaluator                                      &evaluator,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_rhs) const
  {
    const auto &loads = boundary_conditions->surface_loads();
    if (loads.empty())
      return;
    const double thickness = description.material.thickness;
    const bool   axisymmetric =
      description.material.hypothesis == PlaneHypothesis::axisymmetric;
    const bool small_strain =
      description.material.kinematics == Kinematics::small_strain;
    const unsigned int n_local = evaluator.dofs_per_cell();

    for (const unsigned int f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        for (const auto &load : loads)
          {
            if (load.boundary != cell->face(f)->boundary_id())
              continue;
            evaluator.reinit(cell, f);
            load.function->set_time(time);
            std::vector<double> cell_values(n_local);
            for (unsigned int i = 0; i < n_local; ++i)
              cell_values[i] = solution(local_dofs[i]);
            for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
              {
                const Point<2>     X  = evaluator.quadrature_point(q);
                const Tensor<1, 2> N0 = evaluator.normal_vector(q);
                // (axisymmetric: the ring of the reference surface,
                // 2 pi R dS; a traction is per unit reference area)
                const double dA = evaluator.JxW(q) *
                                  (axisymmetric ? 2. * M_PI * X[0] : thickness);
                if (!load.is_pressure)
                  {
                    // Dead traction per unit reference length.
                    const Tensor<1, 2> t(
                      {load.function->value(X, 0), load.function->value(X, 1)});
                    for (unsigned int i = 0; i < n_local; ++i)
                      cell_rhs(i) += evaluator.shape_value(i, q) *
                                     t[evaluator.displacement_component(i)] *
                                     dA;
                    continue;
                  }
                // Follower pressure: f = -p n da = -p cof(F) N0 dA (Nanson),
                // with cof(F) linear in F in 2D, hence the simple tangent.
                // Axisymmetric: da is the current ring, 2 pi x_r ds, that
                // is F_33 = x_r / R times the reference one (3D Nanson).
                // (small strain: on the undeformed body, a dead load)
                const Tensor<2, 2> F =
                  small_strain ? Tensor<2, 2>(unit_symmetric_tensor<2>()) :
                                 unit_symmetric_tensor<2>() +
                                   evaluator.gradient(cell_values, q);
                const double       p = load.function->value(X);
                const Tensor<1, 2> cof_F_N0(
                  {F[1][1] * N0[0] - F[1][0] * N0[1],
                   -F[0][1] * N0[0] + F[0][0] * N0[1]});
                const double hoop_stretch =
                  axisymmetric && !small_strain ?
                    1. + evaluator.value(cell_values, q)[0] / X[0] :
                    1.;
                for (unsigned int i = 0; i < n_local; ++i)
                  {
                    const unsigned int ci = evaluator.displacement_component(i);
                    const double       Ni = evaluator.shape_value(i, q);
                    cell_rhs(i) -= p * Ni * cof_F_N0[ci] * hoop_stretch * dA;
                    for (unsigned int j = 0; j < n_local && !small_strain; ++j)
                      {
                        const unsigned int cj =
                          evaluator.displacement_component(j);
                        const Tensor<1, 2> g = evaluator.shape_grad(j, q);
                        double             d = 0.;
                        if (ci == 1 && cj == 0)
                          d = -g[1] * N0[0] + g[0] * N0[1];
                        else if (ci == 0 && cj == 1)
                          d = g[1] * N0[0] - g[0] * N0[1];
                        d *= hoop_stretch;
                        if (axisymmetric && cj == 0)
                          d +=
                            cof_F_N0[ci] * evaluator.shape_value(j, q) / X[0];
                        cell_matrix(i, j) += p * Ni * d * dA;
                      }
                  }
              }
          }
      }
  }



  void
  Body::assemble_weight(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    CellEvaluator                                      &evaluator,
    Vector<double>                                     &cell_rhs) const
  {
    // rho g per unit reference volume: the mass is the reference one
    // (total Lagrangian), so the weight is a dead load. (In the sequential
    // copier: muParser's functions hold a time and are not thread safe.)
    const double rho = materials_of_cells->density_of_cell(cell->material_id());
    if (!(rho > 0.))
      return;
    const bool axisymmetric =
      description.material.hypothesis == PlaneHypothesis::axisymmetric;
    gravity->set_time(time);
    evaluator.reinit(cell);
    for (unsigned int q = 0; q < evaluator.n_quadrature_points(); ++q)
      {
        const Point<2> X = evaluator.quadrature_point(q);
        const double   dV =
          evaluator.JxW(q) *
          (axisymmetric ? 2. * M_PI * X[0] : description.material.thickness);
        const std::array<double, 2> g = {
          {gravity->value(X, 0), gravity->value(X, 1)}};
        for (unsigned int i = 0; i < evaluator.dofs_per_cell(); ++i)
          cell_rhs(i) += rho * g[evaluator.displacement_component(i)] *
                         evaluator.shape_value(i, q) * dV;
      }
  }



  double
  Body::residual_norm() const
  {
    // The equilibrium equations of the free dofs are the condensed ones: a
    // constrained dof a = sum_b w_b u_b + g hands its residual on to the
    // dofs b (serendipity interiors, Hermite tangential derivatives).
    const AffineConstraints<double> &constraints = linear_system->constraints();
    Vector<double>                   condensed   = unconstrained_residual;
    condensed -= contact_forces;
    constraints.condense(condensed);
    for (const auto &line : constraints.get_lines())
      condensed(line.index) = 0.;
    return condensed.l2_norm();
  }



  double
  Body::force_scale() const
  {
    // A stress-free motion (a rigid translation driven by prescribed
    // displacements) has no force to compare the residual with; the floor
    // is the force a strain of 1e-4 |u| / L would carry over the length L
    // (round-off of a rigid motion stays 1e-12 (L / h) below it).
    // (axisymmetric: a ring of the body's size stands for the thickness)
    const double depth =
      description.material.hypothesis == PlaneHypothesis::axisymmetric ?
        2. * M_PI * reference_size :
        description.material.thickness;
    const double floor = 1e-4 * materials_of_cells->largest_young_modulus() *
                         depth * solution.linfty_norm();
    return std::max({internal_force_norm,
                     external_force_norm,
                     contact_forces.l2_norm(),
                     floor,
                     inertia_terms ? inertia_terms->force_scale() : 0.});
  }



  types::boundary_id
  Body::boundary_id(const std::string &boundary, const std::string &entry) const
  {
    const Location where = BoundaryConditions::resolve(
      boundary, named_boundaries, mesh, description.name, entry);
    if (where.is_vertex)
      throw InputError(entry, "expected a boundary name, not a point");
    return where.boundary;
  }



  void
  Body::update(const Vector<double> &increment)
  {
    solution += increment;
  }



  void
  Body::store_state()
  {
    stored_solution       = solution;
    stored_contact_forces = contact_forces;
  }



  void
  Body::restore_state()
  {
    solution       = stored_solution;
    contact_forces = stored_contact_forces;
  }
} // namespace glissade
