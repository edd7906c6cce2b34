// A body: its set-up from the description, its state, and the assembly
// that puts its parts together (include/glissade/body/body.h).

#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/base/processes.h>
#include <glissade/base/text.h>
#include <glissade/body/body.h>
#include <glissade/fe/element_space_registry.h>
#include <glissade/mesh/mesh_diameter.h>
#include <glissade/mesh/process_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using BodyCell = DoFHandler<2>::active_cell_iterator;

    /**
     * An axisymmetric body: refuses a space that cannot take one and a mesh
     * with a vertex at x = r < 0, naming the cell.
     */
    void
    check_axisymmetric_body(const ElementSpace     &space,
                            const Triangulation<2> &mesh,
                            const double            reference_size,
                            const std::string      &where)
    {
      const std::string why_not = space.capabilities().not_axisymmetric_because;
      if (!why_not.empty())
        throw InputError(where + "/Material/Hypothesis",
                         "axisymmetric bodies are not implemented for '" +
                           space.name() + "' elements: " + why_not + "; use " +
                           ElementSpaceRegistry::names_that(
                             [](const ElementSpace::Capabilities &c) {
                               return c.not_axisymmetric_because.empty();
                             }));
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
                      << cell->vertex(v)[0] << ", " << cell->vertex(v)[1]
                      << ")";
              throw InputError(where + "/Mesh", message.str());
            }
    }



    /** The radial dofs of the nodes on the axis x = 0. */
    std::vector<types::global_dof_index>
    radial_dofs_on_axis(const DoFHandler<2> &dofs,
                        const ElementSpace  &space,
                        const double         reference_size)
    {
      const double tolerance = 1e-12 * std::max(reference_size, 1e-300);
      std::vector<types::global_dof_index> on_axis;
      // (a space whose dofs are not nodal values: the x dofs of its
      // control points on the axis, which make the trace of u_r there zero)
      const auto points = space.interpolation_points();
      if (!points.empty())
        {
          for (const auto &point : points)
            if (point.component == 0 && std::abs(point.point[0]) <= tolerance)
              on_axis.push_back(point.dof);
          return on_axis;
        }
      // The x dofs whose support point lies on x = 0 (every space but
      // Hermite's has one value dof per node and component).
      std::map<types::global_dof_index, Point<2>> support_points;
      DoFTools::map_dofs_to_support_points(space.mapping(),
                                           dofs,
                                           support_points);
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



    /**
     * The rigid motions the supports leave free, about the centre of the
     * body's bounding box.
     */
    std::vector<RigidMotion>
    motions_free_of_supports(const BoundaryConditions &conditions,
                             const DoFHandler<2>      &dofs,
                             const ElementSpace       &space,
                             const BoundingBox<2>     &box,
                             const double              reference_size,
                             const bool                of_revolution)
    {
      const auto basis =
        rigid_motion_basis(box.center(), std::max(reference_size, 1e-300));
      const std::vector<RigidMotion> all(basis.begin(), basis.end());
      const auto rows = conditions.support_rows(dofs, space, basis);
      std::vector<RigidMotion> free_motions;
      if (of_revolution)
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



    /**
     * The points that the body's supports and loads name (point(x, y)):
     * a distributed mesh holds the cells around them on every process.
     */
    std::vector<Point<2>>
    named_points(const BodyDescription &description)
    {
      std::vector<std::string> locations;
      for (const auto &d : description.dirichlet)
        locations.push_back(d.location);
      for (const auto &n : description.neumann)
        locations.push_back(n.location);
      std::vector<Point<2>> points;
      double                x, y;
      for (const auto &location : locations)
        if (text::parse_point_location(location, x, y))
          points.emplace_back(x, y);
      return points;
    }



    /** Every vertex and node of the whole mesh, with their value dofs. */
    Body::WholeMeshNodes
    nodes_of(const DoFHandler<2> &dofs, const ElementSpace &space)
    {
      // (the x and y values of a node: the shape functions of the first
      // and second displacement components at the same support point)
      const FiniteElement<2> &fe      = dofs.get_fe();
      const unsigned int      per_dim = space.components_per_displacement();
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == 0)
          for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
            if (fe.system_to_component_index(j) ==
                std::make_pair(per_dim, fe.system_to_component_index(i).second))
              pairs.emplace_back(i, j);
      Body::WholeMeshNodes nodes;
      const auto          &mesh = dofs.get_triangulation();
      std::vector<bool>    vertex_seen(mesh.n_vertices(), false);
      std::vector<bool>    node_seen(dofs.n_dofs(), false);
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        {
          for (const unsigned int v : cell->vertex_indices())
            if (!vertex_seen[cell->vertex_index(v)])
              {
                vertex_seen[cell->vertex_index(v)] = true;
                nodes.vertices.push_back(cell->vertex(v));
                nodes.vertex_dofs.push_back(
                  BoundaryConditions::cell_vertex_dofs(cell, v, space));
              }
          cell->get_dof_indices(local);
          for (const auto &[i, j] : pairs)
            if (!node_seen[local[i]])
              {
                node_seen[local[i]] = true;
                nodes.node_dofs.push_back({{local[i], local[j]}});
              }
        }
      return nodes;
    }



    /** False where follower pressure makes the tangent unsymmetric. */
    bool
    without_follower_pressure(const BoundaryConditions &conditions)
    {
      for (const auto &load : conditions.surface_loads())
        if (load.is_pressure)
          return false;
      return true;
    }
  } // namespace



  Body::Body(const BodyDescription &description, const std::string &source)
    : description(description)
    , source(source)
    , body_hypothesis(description.material.hypothesis,
                      description.material.thickness)
  {
    const std::string where = source + ": Body " + description.name;
    // (the space first: a NURBS space's exact geometry is checked before a
    // mesh is read)
    element_space = ElementSpaceRegistry::create(description.element_space,
                                                 description.element_degree);
    if (element_space->capabilities().needs_exact_patch)
      element_space->use_patches(exact_patch(where));
    auto             serial = std::make_unique<Triangulation<2>>();
    const MeshLabels labels =
      MeshFactory::create(description.mesh, *serial, where);
    element_space->place_vertices(*serial);
    named_boundaries   = labels.boundaries;
    reference_size     = mesh_diameter(*serial);
    n_mesh_cells       = serial->n_active_cells();
    materials_of_cells = std::make_unique<BodyMaterials>(
      description.material,
      labels.regions,
      MeshFactory::type(description.mesh.type).from_file ?
        description.mesh.file :
        "",
      where);

    evaluators = std::make_unique<EvaluatorPool>(*element_space);
    check_space_for_mesh(*serial, labels.second_order, where);
    const auto box = GridTools::compute_bounding_box(*serial);
    // (a body of revolution: its radial dofs on the axis are held, and its
    // only rigid motion is along the axis)
    const bool of_revolution = body_hypothesis.strains_the_hoop();
    const std::vector<types::global_dof_index> axis_dofs =
      place_mesh_and_dofs(std::move(serial));

    boundary_conditions = std::make_unique<BoundaryConditions>(description,
                                                               *element_space,
                                                               named_boundaries,
                                                               *mesh);
    loads               = std::make_unique<DistributedLoads>(description,
                                               *boundary_conditions,
                                               *materials_of_cells,
                                               where);
    if (of_revolution)
      boundary_conditions->hold_on_axis(axis_dofs);

    solution.reinit(dofs.n_dofs());
    stored_solution.reinit(dofs.n_dofs());
    unconstrained_residual.reinit(dofs.n_dofs());
    contact_forces.reinit(dofs.n_dofs());
    cell_integration =
      std::make_unique<CellIntegration>(*element_space,
                                        *materials_of_cells,
                                        description.material,
                                        mesh->n_active_cells());

    // The constraints at t = 0 say which dofs are constrained, which never
    // changes during a run: the system's sparsity pattern is built on them.
    AffineConstraints<double> constraints;
    boundary_conditions->make_constraints(
      dofs, *element_space, 0., solution, element_constraints, constraints);
    // (an elastic foundation holds every rigid motion)
    std::vector<RigidMotion> free_motions =
      description.elastic_foundation > 0. ?
        std::vector<RigidMotion>() :
        motions_free_of_supports(*boundary_conditions,
                                 dofs,
                                 *element_space,
                                 box,
                                 reference_size,
                                 of_revolution);
    linear_system = std::make_unique<BodyLinearSystem>(
      dofs,
      *element_space,
      std::move(constraints),
      // (a turning frame's Coriolis and Euler forces make the tangent
      // unsymmetric)
      without_follower_pressure(*boundary_conditions) &&
        !description.turning_frame.active(),
      RigidMotionSprings(
        std::move(free_motions), source, description.name, reference_size),
      own_cells());
  }



  NurbsMultipatch
  Body::exact_patch(const std::string &where) const
  {
    const std::string space = "Element/Space = " + element_space->name();
    const auto       &type  = MeshFactory::type(description.mesh.type);
    if (!type.exact_patch)
      throw InputError(
        where + "/Mesh/Type",
        space +
          " needs a mesh type with an exact geometry "
          "(rectangle, square, half ring, ring or nurbs patch); a " +
          description.mesh.type + " mesh has none");
    if (description.turning_frame.active())
      throw InputError(where + "/Turning frame",
                       "is not built for " + space +
                         " (its dofs are control points, not nodes)");
    NurbsMultipatch geometry =
      type.exact_patch(description.mesh, description.element_degree, where);
    // (a distorted NURBS body: the control points off each patch's
    // boundary moved, and the mesh's vertices put on the patches' knot
    // points after; a joined side is on both patches' boundaries)
    if (description.mesh.distortion > 0.)
      for (NurbsPatch &patch : geometry.patches)
        patch.distort(description.mesh.distortion);
    return geometry;
  }



  void
  Body::check_space_for_mesh(const Triangulation<2> &serial,
                             const bool              second_order,
                             const std::string      &where) const
  {
    if (body_hypothesis.strains_the_hoop())
      check_axisymmetric_body(*element_space, serial, reference_size, where);
    // A second-order file's curved edges are followed by a mapping of
    // degree two or more; a bilinear or Hermite body would silently see
    // the chords instead.
    if (second_order && !element_space->capabilities().follows_curved_edges)
      throw InputError(where + "/Element/Space",
                       "'" + description.mesh.file +
                         "' has second-order quadrilaterals, whose curved "
                         "edges a '" +
                         description.element_space +
                         "' body cannot follow: choose " +
                         ElementSpaceRegistry::names_that(
                           [](const ElementSpace::Capabilities &c) {
                             return c.follows_curved_edges;
                           }) +
                         ", or save the mesh first-order (gmsh -order 1)");
  }



  std::vector<types::global_dof_index>
  Body::place_mesh_and_dofs(std::unique_ptr<Triangulation<2>> serial)
  {
    // On several processes a body holds its share of the mesh
    // (distribute_mesh), its dofs numbered as one process numbers them; the
    // serial mesh and its dofs are let go once what needs the whole mesh is
    // known (the element constraints, the axis, the nodes). (a mesh whose
    // boundary ids include the one of the cut faces stays whole)
    const bool of_revolution = body_hypothesis.strains_the_hoop();
    const auto boundary_ids  = serial->get_boundary_ids();
    const bool distribute =
      processes::shared_out() &&
      std::find(boundary_ids.begin(), boundary_ids.end(), cut_boundary_id) ==
        boundary_ids.end();
    const FiniteElement<2>              &fe = element_space->finite_element();
    std::vector<types::global_dof_index> axis_dofs;
    if (!distribute)
      {
        mesh = std::move(serial);
        dofs.reinit(*mesh);
        dofs.distribute_dofs(fe);
        element_space->setup(dofs, element_constraints);
        if (of_revolution)
          axis_dofs = radial_dofs_on_axis(dofs, *element_space, reference_size);
        return axis_dofs;
      }
    DoFHandler<2> serial_dofs(*serial);
    serial_dofs.distribute_dofs(fe);
    element_space->setup(serial_dofs, element_constraints);
    if (of_revolution)
      axis_dofs =
        radial_dofs_on_axis(serial_dofs, *element_space, reference_size);
    nodes_of_whole_mesh = nodes_of(serial_dofs, *element_space);
    mesh                = distribute_mesh(*serial,
                           named_points(description),
                           processes::communicator());
    dofs.reinit(*mesh);
    dofs.distribute_dofs(fe);
    number_dofs_as_serial(dofs, serial_dofs);
    // (deal.II's distributed vectors, which DataOut makes, want each
    // process's dofs a contiguous range of numbers, which shares by ranges
    // of cells give (distribute_mesh); should a mesh not, every process
    // keeps the whole mesh rather than wait for ever)
    if (processes::maximum(dofs.locally_owned_dofs().is_contiguous() ? 0 : 1) >
        0)
      {
        dofs.reinit(*serial);
        mesh = std::move(serial);
        dofs.distribute_dofs(fe);
        nodes_of_whole_mesh = WholeMeshNodes();
      }
    element_space->attach(dofs);
    return axis_dofs;
  }



  void
  Body::set_time(const double new_time)
  {
    time = new_time;
  }



  bool
  Body::residual_alone_is_cheap() const
  {
    return description.material.kinematics == Kinematics::small_strain;
  }



  bool
  Body::assemble(const bool with_tangent)
  {
    boundary_conditions->make_constraints(dofs,
                                          *element_space,
                                          time,
                                          solution,
                                          element_constraints,
                                          linear_system->constraints());
    linear_system->clear(with_tangent);
    unconstrained_residual = 0.;
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
    // loads are added there too (DistributedLoads).
    using Scratch      = CellIntegration::Scratch;
    using Contribution = CellIntegration::CellContribution;
    Vector<double>     internal_forces(dofs.n_dofs());
    Vector<double>     viscous_forces(inertia_terms ? dofs.n_dofs() : 0);
    bool               admissible         = true;
    const auto         boundary_evaluator = evaluators->borrow();
    const unsigned int n_local            = cell_integration->dofs_per_cell();
    const auto         integrate =
      [&](const std::vector<BodyCell>::const_iterator &place,
          Scratch                                     &scratch,
          Contribution                                &data) {
        cell_integration->integrate(
          *place, solution, inertia_terms.get(), scratch, data);
      };
    const auto add = [&](const Contribution &data) {
      add_cell(
        data, *boundary_evaluator, internal_forces, viscous_forces, admissible);
    };
    // Each process integrates its share of the cells (own_cells: all of
    // them on one process) and the sums are made whole on every process.
    WorkStream::run(own_cells().begin(),
                    own_cells().end(),
                    integrate,
                    add,
                    Scratch(*evaluators, n_local),
                    Contribution(n_local));
    linear_system->sum_right_hand_side_over_processes();
    processes::sum(internal_forces.begin(), internal_forces.size());
    processes::sum(viscous_forces.begin(), viscous_forces.size());
    processes::sum(unconstrained_residual.begin(),
                   unconstrained_residual.size());
    problem    = processes::first_message(problem);
    admissible = problem.empty();
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



  const std::vector<BodyCell> &
  Body::own_cells()
  {
    if (own_cell_list.empty())
      for (const auto &cell : dofs.active_cell_iterators())
        if (is_own_cell(cell))
          own_cell_list.push_back(cell);
    return own_cell_list;
  }



  bool
  Body::is_own_cell(const Triangulation<2>::cell_iterator &cell) const
  {
    // A distributed mesh: the cells this process owns. A whole mesh on
    // several processes: a contiguous range of the active cells (their
    // order is the mesh's, which the mesh types number row by row),
    // process p of P taking cells n p / P to n (p + 1) / P; the same cells
    // as distribute_mesh gives it.
    if (mesh_is_distributed())
      return cell->is_active() && cell->is_locally_owned();
    const auto [first, end] = processes::share(n_mesh_cells);
    return cell->is_active() && cell->active_cell_index() >= first &&
           cell->active_cell_index() < end;
  }



  void
  Body::add_cell(const CellIntegration::CellContribution &data,
                 CellEvaluator                           &boundary_evaluator,
                 Vector<double>                          &internal_forces,
                 Vector<double>                          &viscous_forces,
                 bool                                    &admissible)
  {
    const auto &cell = data.cell;
    // The first cell that makes the state inadmissible names the problem.
    if (!data.rejection.empty())
      {
        if (admissible)
          {
            std::ostringstream message;
            message << "cell " << serial_cell_index(cell) << " of body '"
                    << name() << "' at (" << cell->center()[0] << ", "
                    << cell->center()[1] << ") " << data.rejection;
            problem = message.str();
          }
        admissible = false;
      }
    const unsigned int n_local = data.local_dofs.size();
    for (unsigned int i = 0; i < n_local; ++i)
      internal_forces(data.local_dofs[i]) -= data.cell_rhs(i);
    if (viscous_forces.size() > 0)
      for (unsigned int i = 0; i < n_local; ++i)
        viscous_forces(data.local_dofs[i]) += data.viscous_force(i);

    loads->add_cell_loads(cell,
                          data.local_dofs,
                          solution,
                          time,
                          boundary_evaluator,
                          data.cell_matrix,
                          data.cell_rhs);

    for (unsigned int i = 0; i < n_local; ++i)
      unconstrained_residual(data.local_dofs[i]) -= data.cell_rhs(i);
    linear_system->add_cell(data.cell_matrix, data.cell_rhs, data.local_dofs);
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
    // (a body of revolution: a ring of the body's size stands for the
    // thickness)
    const double depth = body_hypothesis.out_of_plane_size(reference_size);
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
      boundary, named_boundaries, *mesh, description.name, entry);
    if (where.is_vertex)
      throw InputError(entry, "expected a boundary name, not a point");
    return where.boundary;
  }



  void
  Body::update(const Vector<double> &increment)
  {
    nodal_view_current = false;
    solution += increment;
  }



  const Vector<double> &
  Body::nodal_displacement() const
  {
    if (element_space->capabilities().dofs_are_nodal_values)
      return solution;
    if (!nodal_view_current)
      element_space->nodal_values(dofs, solution, nodal_view);
    nodal_view_current = true;
    return nodal_view;
  }



  unsigned int
  Body::n_unknowns() const
  {
    return element_space->n_unknowns(dofs);
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
