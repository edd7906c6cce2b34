#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/discretisation/contact_discretisation.h>
#include <glissade/contact/discretisation/discrete_gradient.h>
#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/mesh/boundary_normals.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  ContactPair::ContactPair(const ContactDescription &description,
                           Body                     &slave,
                           Body                     *master,
                           TimerOutput              &timer)
    : description(description)
    , slave_body(slave)
    , master_body(master)
    , timer(timer)
    , self_contact(master == &slave)
  {
    const std::string entry = description.entry;

    // Node-to-segment contact works on the vertices of the contact
    // boundaries (and, for Hermite masters, their derivatives). Elements
    // with nodes along their edges (q2, q3, q8, q12) would have those nodes
    // left out of contact: refused rather than answered wrongly. A body of
    // NURBS elements, whose dofs are control points, is a master through
    // its exact boundary (Surface = nurbs) and a slave through its
    // boundary's Greville points.
    const bool nurbs_master =
      master != nullptr &&
      !master->space().capabilities().dofs_are_nodal_values;
    const bool nurbs_slave =
      !slave.space().capabilities().dofs_are_nodal_values;
    if (nurbs_slave && master == &slave)
      throw InputError(entry + "/Master body",
                       "self-contact of a NURBS body ('" + slave.name() +
                         "') is not built yet");
    if (nurbs_master && description.surface != "nurbs")
      throw InputError(entry + "/Surface",
                       "the master body '" + master->name() +
                         "' uses the element space '" + master->space().name() +
                         "', whose dofs are control points: its boundary's "
                         "vertices carry no displacement of their own, so "
                         "a " +
                         description.surface +
                         " surface through them cannot be built; use "
                         "Surface = nurbs, its exact boundary");
    for (const auto &[body, role] :
         {std::pair<const Body *, const char *>{&slave, "/Slave body"},
          std::pair<const Body *, const char *>{master, "/Master body"}})
      if (body != nullptr &&
          body->space().capabilities().dofs_are_nodal_values &&
          body->space().finite_element().n_dofs_per_line() > 0)
        throw InputError(entry + role,
                         "body '" + body->name() +
                           "' uses the element space '" + body->space().name() +
                           "', whose nodes along the element edges "
                           "node-to-segment contact would leave out; contact "
                           "bodies must use q1, hermite or nurbs");

    // The slave nodes: the vertices of the declared contact area, one or
    // several boundaries ("bottom, left, right"); a vertex where two of
    // them meet is one node, not two constraints on the same point.
    for (const auto &name :
         text::split_top_level(description.slave_boundary, ','))
      slave_ids.insert(
        slave.boundary_id(text::trim(name), entry + "/Slave boundary"));
    if (nurbs_slave)
      append_nurbs_slave_points(slave,
                                description.slave_boundary,
                                entry + "/Slave boundary",
                                description.discretisation == "mortar" ?
                                  SlavePointArea::function_integral :
                                  SlavePointArea::collocation,
                                slave_nodes,
                                faces);
    else
      {
        std::map<unsigned int, unsigned int> node_of_vertex;
        for (const auto &cell : slave.dof_handler().active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                slave_ids.count(cell->face(f)->boundary_id()) > 0)
              {
                std::array<unsigned int, 2> face;
                for (const unsigned int v : {0u, 1u})
                  {
                    const unsigned int vertex = cell->face(f)->vertex_index(v);
                    const auto [at, added] =
                      node_of_vertex.emplace(vertex, slave_nodes.size());
                    face[v] = at->second;
                    if (!added)
                      continue;
                    ContactNode node;
                    node.vertex             = vertex;
                    node.reference_position = cell->face(f)->vertex(v);
                    const auto dofs = BoundaryConditions::cell_vertex_dofs(
                      cell,
                      GeometryInfo<2>::face_to_cell_vertices(f, v),
                      slave.space());
                    node.shares = {{dofs, 1.}};
                    slave_nodes.push_back(node);
                  }
                faces.push_back(face);
              }
        const auto outward_normal =
          boundary_vertex_normals(slave.triangulation(),
                                  [this](const types::boundary_id id) {
                                    return slave_ids.count(id) > 0;
                                  });
        for (ContactNode &node : slave_nodes)
          node.reference_outward_normal = outward_normal.at(node.vertex);
      }
    master_surface = SurfaceRegistry::create({description, master_body});
    if (master_surface->is_rigid())
      check_obstacle_faces_slave();
    if (self_contact)
      {
        // A node may see the surface no deeper behind than half a slave
        // face: deeper, it would see through the body to its back. (Set
        // before the discretisation is made: mortar reads these views.)
        double length = 0.;
        for (const auto &[a, b] : faces)
          length += slave_nodes[a].reference_position.distance(
            slave_nodes[b].reference_position);
        std::map<unsigned int, int>     master_node_of_vertex;
        const std::vector<unsigned int> chain = master_surface->vertices();
        for (unsigned int k = 0; k < chain.size(); ++k)
          master_node_of_vertex[chain[k]] = k;
        for (ContactNode &node : slave_nodes)
          {
            node.facing                        = true;
            node.facing_view.reach             = description.alert_distance;
            node.facing_view.penetration_limit = 0.5 * length / faces.size();
            const auto on_master = master_node_of_vertex.find(node.vertex);
            node.facing_view.master_node =
              on_master == master_node_of_vertex.end() ? -1 : on_master->second;
          }
      }
    discretisation = ContactDiscretisation::create(
      description.discretisation,
      {description, slave, master, *master_surface, slave_nodes, slave_ids});
    if (master_surface->coating() != nullptr &&
        description.discretisation != "node-to-segment")
      throw InputError(entry + "/Discretisation",
                       "an abradable coating (Obstacle/Coating thickness) "
                       "caps each slave node's force: it needs "
                       "node-to-segment contact, not " +
                         description.discretisation);
  }



  std::vector<double>
  ContactPair::tributary_areas() const
  {
    const unsigned int    n = slave_nodes.size();
    std::vector<Point<2>> x(n);
    for (unsigned int k = 0; k < n; ++k)
      x[k] = position(slave_nodes[k]);
    const Hypothesis   &hypothesis = slave_body.hypothesis();
    std::vector<double> area(n, 0.);
    for (const auto &[a, b] : faces)
      {
        const double length = x[a].distance(x[b]);
        for (const auto &[k, other] : {std::make_pair(a, b), {b, a}})
          area[k] += hypothesis.node_share_of_segment(x[k], x[other], length);
      }
    // (a NURBS boundary's points: their collocation areas, in the reference
    // configuration)
    for (unsigned int k = 0; k < n; ++k)
      if (slave_nodes[k].collocation_area != 0.)
        area[k] = slave_nodes[k].collocation_area;
    return area;
  }



  void
  ContactPair::measure_corners(const double time)
  {
    const std::vector<Point<2>> ends = master_surface->open_ends();
    if (ends.empty())
      return;
    for (const ContactNode &node : slave_nodes)
      if (node.collocation_area != 0.)
        return;
    deepest_corner = std::max(deepest_corner, 0.);
    for (const auto &[a, b] : faces)
      {
        const ContactNode &A = slave_nodes[a], &B = slave_nodes[b];
        const Point<2>     xa = position(A), xb = position(B);
        const Tensor<1, 2> along  = xb - xa;
        const double       length = along.norm();
        if (length == 0.)
          continue;
        // Outward: the side of the face that the nodes' outward normals
        // took in the reference configuration (a face keeps its sides).
        const Tensor<1, 2> reference_along =
          B.reference_position - A.reference_position;
        const Tensor<1, 2> reference_outward =
          A.reference_outward_normal + B.reference_outward_normal;
        const double       side = reference_along[0] * reference_outward[1] -
                                  reference_along[1] * reference_outward[0] >
                                0. ?
                                    1. :
                                    -1.;
        const Tensor<1, 2> outward =
          side / length * Tensor<1, 2>({-along[1], along[0]});
        for (const Point<2> &c : ends)
          {
            const double s     = (c - xa) * along / (length * length);
            const double depth = -((c - xa) * outward);
            if (s >= 0. && s <= 1. && depth > deepest_corner &&
                depth < 0.5 * length)
              {
                deepest_corner      = depth;
                deepest_corner_time = time;
                deepest_corner_face = length;
              }
          }
      }
  }



  std::string
  ContactPair::corner_report() const
  {
    if (deepest_corner < 0.)
      return {};
    std::ostringstream out;
    out << std::setprecision(3) << "contact pair '" << name()
        << "': the obstacle's open ends went at most " << deepest_corner
        << " inside the slave's faces";
    if (deepest_corner > 0.)
      out << " (" << 100. * deepest_corner / deepest_corner_face
          << " % of the face there, t = " << deepest_corner_time << ")";
    out << ": the contact holds the slave's points off the obstacle, not the "
           "obstacle's corners off the slave's faces (a finer slave there "
           "makes it smaller)";
    return out.str();
  }



  std::vector<double>
  ContactPair::normal_force_caps() const
  {
    const AbradableCoating *coating = master_surface->coating();
    if (coating == nullptr)
      return std::vector<double>(slave_nodes.size(),
                                 std::numeric_limits<double>::infinity());
    // The force the local problem's reaction may reach, which the outputs
    // report times their scale.
    std::vector<double> cap = tributary_areas();
    for (double &c : cap)
      c *= coating->yield_pressure() / reported_force_scale;
    return cap;
  }



  void
  ContactPair::wear_coating()
  {
    if (master_surface->coating() == nullptr)
      return;
    const std::vector<double> cap = normal_force_caps();
    for (unsigned int k = 0; k < slave_nodes.size(); ++k)
      if (const ContactNode &node = slave_nodes[k];
          node.active && node.reaction[1] >= cap[k] * (1. - 1e-9))
        {
          const Point<2> start =
            node.reference_position +
            node.displacement(slave_body.stored_displacement());
          const Point<2> end = node.reference_position +
                               node.displacement(slave_body.displacement());
          master_surface->wear_along(start, end);
        }
  }



  void
  ContactPair::check_obstacle_faces_slave()
  {
    // An obstacle's normal points out of it, towards where the slave may be.
    // If at every slave node it points the same way as the slave boundary's
    // outward normal, the slave can only ever be behind the obstacle
    // (a line's Normal given the wrong way round, a disk where a hole was
    // meant): no contact would ever close, and the run would say nothing.
    master_surface->update(0., 0.);
    unsigned int facing_away = 0;
    for (const ContactNode &node : slave_nodes)
      {
        const SurfacePoint point =
          master_surface->project(node.reference_position);
        const Tensor<1, 2> &out = node.reference_outward_normal;
        if (point.valid && point.normal * out > 0.5 * out.norm())
          ++facing_away;
      }
    if (!slave_nodes.empty() && facing_away == slave_nodes.size())
      throw InputError(description.entry + "/Obstacle",
                       "the obstacle faces away from the slave boundary '" +
                         description.slave_boundary + "' of body '" +
                         slave_body.name() +
                         "': at every slave node its normal points the same "
                         "way as the body's outward normal, so no contact can "
                         "close. Reverse Obstacle/Normal (a line's normal "
                         "points towards the slave), or use Type = hole "
                         "for a body inside a circle (disk for outside)");
  }



  ContactPair::~ContactPair() = default;



  bool
  ContactPair::project(ContactNode &node, const bool keep_segment) const
  {
    // Under a dynamic scheme the node's normal force will be the mean of
    // the gap's gradients at the step's start and end: the contact tangent
    // is that of its end half, taken at half the normal reaction.
    const bool over_the_step =
      slave_body.inertia() != nullptr && std::isfinite(node.start_gap_in_dofs);
    const bool mean_normal = over_the_step && !node.start_normal_force.empty();
    const double normal_reaction = node.reaction[1];
    if (mean_normal)
      node.reaction[1] *= 0.5;
    const bool projected = discretisation->project(node, keep_segment);
    node.reaction[1]     = normal_reaction;
    if (!projected)
      return false;
    // Under a dynamic scheme the reaction's forces are discrete gradients
    // over the step, so that the contact's work on the bodies is what its
    // law bounds (discrete_gradient.h). A node found within the step has
    // no start gap: its forces stay the end's gradient.
    if (over_the_step)
      {
        StepMotion motion;
        motion.increment = [this](const unsigned int            side,
                                  const types::global_dof_index dof) {
          const Body &body = side == 0 ? slave_body : *master_body;
          return body.displacement()(dof) - body.stored_displacement()(dof);
        };
        if (master_body != nullptr)
          motion.translation = [this](const unsigned int            side,
                                      const types::global_dof_index dof) {
            const BodyInertia &inertia =
              *(side == 0 ? slave_body : *master_body).inertia();
            return std::array<double, 2>{{inertia.unit_translation(0)(dof),
                                          inertia.unit_translation(1)(dof)}};
          };
        motion.one_body               = self_contact;
        motion.length                 = slave_body.size();
        const ContactLinearization &l = node.linearization;
        // (the slip against a rigid obstacle counts its motion, and at a
        // faceted vertex it is the offset from the vertex: neither is the
        // dofs' alone)
        const double slip = master_body != nullptr && l.vertex_cone == 0. ?
                              l.slip :
                              std::numeric_limits<double>::quiet_NaN();
        make_forces_discrete_gradients(node.linearization,
                                       node.start_normal_force,
                                       l.gap - node.start_gap_in_dofs,
                                       slip,
                                       motion);
      }
    return true;
  }



  std::vector<types::global_dof_index>
  ContactPair::contact_dofs(const Body &body) const
  {
    std::vector<types::global_dof_index> dofs;
    if (&body == &slave_body)
      for (const auto &node : slave_nodes)
        for (const SlaveShare &share : node.shares)
          dofs.insert(dofs.end(), share.dofs.begin(), share.dofs.end());
    if (&body == master_body)
      {
        const auto surface_dofs = master_surface->dofs();
        dofs.insert(dofs.end(), surface_dofs.begin(), surface_dofs.end());
      }
    return dofs;
  }



  void
  ContactPair::begin_step(const double step_start_time, const double time)
  {
    step_start = step_start_time;
    step_end   = time;
    update_surface();
    for (auto &node : slave_nodes)
      {
        if (!may_be_near_master(node))
          {
            rest_node(node);
            continue;
          }
        node.segment          = -1;
        node.segment_switches = 0;
        node.at_vertex        = false;
        if (!node.active)
          node.reaction = {{0., 0.}};
        // (the state is the step's start: under a dynamic scheme, the gap's
        // gradient there is half the node's normal force over the step, and
        // the time integrator records the gap)
        node.start_gap_in_dofs = std::numeric_limits<double>::quiet_NaN();
        node.start_normal_force.clear();
        node.projected = project(node);
        node.active    = node.projected &&
                      node.gap <= description.alert_distance && can_react(node);
        if (node.projected && slave_body.inertia() != nullptr)
          node.start_normal_force = node.linearization.gap_row;
        if (!node.active)
          {
            node.reaction = {{0., 0.}};
            node.status   = BiPotentialSolver::NodeStatus::open;
            // Its gap stays (outputs, a time scheme's start gap); its rows
            // are projected again if it joins, and held by every far node
            // of every pair they would cost memory and copies for nothing
            // (a B-spline master's rows run over eight nodes and more).
            node.linearization.release_rows();
          }
      }
  }



  void
  ContactPair::rest(const double step_start_time, const double time)
  {
    step_start = step_start_time;
    step_end   = time;
    for (auto &node : slave_nodes)
      rest_node(node);
  }



  void
  ContactPair::rest_node(ContactNode &node)
  {
    node.active            = false;
    node.projected         = false;
    node.segment           = -1;
    node.segment_switches  = 0;
    node.at_vertex         = false;
    node.reaction          = {{0., 0.}};
    node.status            = BiPotentialSolver::NodeStatus::open;
    node.law_shift         = {{0., 0.}};
    node.start_gap         = std::numeric_limits<double>::quiet_NaN();
    node.start_gap_in_dofs = std::numeric_limits<double>::quiet_NaN();
    DofVector().swap(node.start_normal_force);
    node.linearization.release_rows();
  }



  bool
  ContactPair::may_be_near_master(const ContactNode &node) const
  {
    return !has_search_box || search_box.point_inside(position(node));
  }



  Point<2>
  ContactPair::position(const ContactNode &node) const
  {
    return node.reference_position +
           node.displacement(slave_body.displacement());
  }



  void
  ContactPair::check_initial_state()
  {
    // (the detection section holds the surface build it makes, as the
    // run's table reads them)
    TimerOutput::Scope scope(timer, timing::detection);
    begin_step(0., 0.);
    double       deepest = 0.;
    unsigned int behind  = 0;
    contacts_at_start.clear();
    for (const auto &node : slave_nodes)
      {
        if (node.projected && node.gap < 0.)
          {
            deepest = std::min(deepest, node.gap);
            ++behind;
          }
        // The frame of the slave boundary (its averaged vertex normal),
        // not the master's: what holds a body is the geometry both sides
        // share, not the tilt of a facet at a vertex (a faceted circle
        // would otherwise seem to hold a ring against turning).
        const Tensor<1, 2> &out = node.reference_outward_normal;
        if (node.active && out.norm() > 0.)
          {
            const Tensor<1, 2> n = -out / out.norm();
            contacts_at_start.push_back(
              {node.reference_position, n, Tensor<1, 2>({-n[1], n[0]})});
          }
      }
    for (auto &node : slave_nodes)
      {
        node.active   = false;
        node.segment  = -1;
        node.reaction = {{0., 0.}};
        node.status   = BiPotentialSolver::NodeStatus::open;
      }
    const double       size = master_body ?
                                std::min(slave_body.size(), master_body->size()) :
                                slave_body.size();
    std::ostringstream found;
    found << "at t = 0, " << behind << " slave nodes of '"
          << description.slave_body << "/" << description.slave_boundary
          << "' lie up to " << -deepest << " behind the master "
          << (master_body ? "surface '" + description.master_body + "/" +
                              description.master_boundary + "'" :
                            std::string("obstacle"));
    // Interference fits and the sagitta of a faceted circle stay well
    // below this; a master that faces away puts the slave a whole
    // thickness behind it, and bodies placed into each other by mistake
    // mostly more than this.
    if (deepest < -0.05 * size)
      {
        found << ", more than 5 % of the bodies' size (" << size
              << "): the bodies overlap at the start, or the master faces "
                 "away from the slave";
        throw InputError(description.entry +
                           (master_body ? "/Master boundary" : "/Obstacle"),
                         found.str());
      }
    // Less deep, it is said: the first increment pushes them out.
    overlap_at_start.clear();
    if (deepest < -description.alert_distance)
      {
        found << ", deeper than the alert distance ("
              << description.alert_distance
              << "): the first increment pushes them out, and that overlap "
                 "is a load (an interference fit's; if it is not meant, the "
                 "bodies overlap)";
        overlap_at_start = found.str();
      }
  }



  void
  ContactPair::update_surface()
  {
    TimerOutput::Scope scope(timer, timing::surface);
    master_surface->update(step_start, step_end);
    discretisation->update();
    if (self_contact)
      update_facing_views();
  }



  void
  ContactPair::update_facing_views()
  {
    // Each face's normal at the current state, turned outward as the
    // reference outward normal of its ends says, summed at its two nodes
    // (weighted by the face's length).
    std::vector<Tensor<1, 2>> normal(slave_nodes.size());
    for (const auto &[a, b] : faces)
      {
        const Tensor<1, 2> along =
          position(slave_nodes[b]) - position(slave_nodes[a]);
        const Tensor<1, 2> reference_along =
          slave_nodes[b].reference_position - slave_nodes[a].reference_position;
        const Tensor<1, 2> reference_outward =
          slave_nodes[a].reference_outward_normal +
          slave_nodes[b].reference_outward_normal;
        const double       side = reference_along[1] * reference_outward[0] -
                                  reference_along[0] * reference_outward[1] >=
                                0. ?
                                    1. :
                                    -1.;
        const Tensor<1, 2> face_normal({side * along[1], -side * along[0]});
        normal[a] += face_normal;
        normal[b] += face_normal;
      }
    for (unsigned int k = 0; k < slave_nodes.size(); ++k)
      slave_nodes[k].facing_view.outward_normal =
        normal[k] / std::max(normal[k].norm(), 1e-300);
  }



  bool
  ContactPair::can_react(const ContactNode &node) const
  {
    // A node whose gap depends only on prescribed dofs (a supported slave
    // corner against a rigid obstacle, or against a supported part of the
    // master) has no compliance at all, W_kk = 0: no reaction can change
    // its gap. It is left out rather than handed to the local solver, which
    // would refuse it. The dofs are those of the node's last projection.
    // A mortar node's row can hold round-off where biorthogonality zeroes
    // a weight exactly (a slave corner against a supported master
    // corner): the free part must be more than round-off of the whole.
    double free = 0., whole = 0.;
    for (const auto &e : node.linearization.gap_row)
      {
        const Body &b = e.body == 0 ? slave_body : *master_body;
        whole += std::abs(e.value);
        if (!b.system().dof_is_prescribed(e.dof))
          free += std::abs(e.value);
      }
    return free > 1e-12 * whole;
  }



  unsigned int
  ContactPair::activate_penetrating_nodes()
  {
    update_surface();
    // Round-off of a node resting on the master is not a penetration.
    const double tolerance = 1e-10 * slave_body.size();
    unsigned int activated = 0;
    for (auto &node : slave_nodes)
      {
        if (node.active || !may_be_near_master(node))
          continue;
        ContactNode trial = node;
        trial.segment     = -1;
        trial.reaction    = {{0., 0.}};
        if (!project(trial) || trial.gap >= -tolerance || !can_react(trial))
          continue;
        trial.active    = true;
        trial.projected = true;
        trial.status    = BiPotentialSolver::NodeStatus::open;
        node            = trial;
        ++activated;
      }
    return activated;
  }



  void
  ContactPair::update_geometry()
  {
    update_surface();
    for (auto &node : slave_nodes)
      if (node.active && !project(node, true))
        {
          // Slid off an open master. A node whose equilibrium is at the
          // master's end would otherwise slide off, come back behind the
          // master and slide off again at every iteration: it keeps the end
          // segment, continued along the end's tangent line, for the rest
          // of the increment (the next increment's detection drops it if it
          // is beyond the end).
          node.segment_switches = std::max(node.segment_switches, 2u);
          if (project(node, true))
            continue;
          node.active   = false;
          node.reaction = {{0., 0.}};
          node.status   = BiPotentialSolver::NodeStatus::open;
        }
      else if (node.active && !can_react(node))
        {
          // Activated at a trial state where its gap depended on free
          // dofs, and here no longer does (a mortar node at a supported
          // corner, whose weight on the free master node vanishes on a
          // flat master): no reaction can move it.
          node.active   = false;
          node.reaction = {{0., 0.}};
          node.status   = BiPotentialSolver::NodeStatus::open;
        }
  }



  unsigned int
  ContactPair::n_active() const
  {
    unsigned int n = 0;
    for (const auto &node : slave_nodes)
      n += node.active ? 1 : 0;
    return n;
  }



  Tensor<1, 2>
  ContactPair::total_force() const
  {
    Tensor<1, 2> sum;
    for (const auto &node : slave_nodes)
      if (node.active)
        sum += node.force();
    return reported_force_scale * sum;
  }



  std::array<Vector<double>, 2>
  ContactPair::contact_forces() const
  {
    std::array<Vector<double>, 2> forces;
    forces[0].reinit(slave_body.n_dofs());
    if (master_body)
      forces[1].reinit(master_body->n_dofs());
    for (const auto &node : slave_nodes)
      if (node.active)
        {
          for (const auto &e : node.linearization.tangential_force)
            forces[e.body](e.dof) += e.value * node.reaction[0];
          for (const auto &e : node.linearization.normal_force)
            forces[e.body](e.dof) += e.value * node.reaction[1];
        }
    return forces;
  }



  const ContactNode &
  ContactPair::node_at(const Point<2> &X) const
  {
    const ContactNode *best = &slave_nodes[0];
    for (const auto &node : slave_nodes)
      if (node.reference_position.distance(X) <
          best->reference_position.distance(X))
        best = &node;
    return *best;
  }
} // namespace glissade
