#include <deal.II/base/timer.h>

#include <glissade/base/input_error.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/bspline_curve.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/faceted_curve.h>
#include <glissade/contact/hermite_curve.h>
#include <glissade/fe/hermite_space.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace glissade
{
  ContactPair::ContactPair(const ContactDescription &description,
                           Body                     &slave,
                           Body                     *master,
                           const std::string        &source,
                           TimerOutput              &timer)
    : description(description)
    , slave_body(slave)
    , master_body(master)
    , timer(timer)
  {
    const std::string entry = description.entry;
    if (master_body == nullptr)
      obstacle = std::make_unique<RigidObstacle>(description);

    // Node-to-segment contact works on the vertices of the contact
    // boundaries (and, for Hermite masters, their derivatives). Elements
    // with nodes along their edges (q2, q3, q8, q12) would have those nodes
    // left out of contact: refused rather than answered wrongly.
    for (const auto &[body, role] :
         {std::pair<const Body *, const char *>{&slave, "/Slave body"},
          std::pair<const Body *, const char *>{master, "/Master body"}})
      if (body != nullptr &&
          body->space().finite_element().n_dofs_per_line() > 0)
        throw InputError(entry + role,
                         "body '" + body->name() + "' uses the element space '" +
                           body->space().name() +
                           "', whose nodes along the element edges "
                           "node-to-segment contact would leave out; contact "
                           "bodies must use q1 or hermite");

    // The slave nodes: the vertices of the declared contact area.
    const types::boundary_id slave_id =
      slave.boundary_id(description.slave_boundary, entry + "/Slave boundary");
    std::set<unsigned int> seen;
    for (const auto &cell : slave.dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == slave_id)
          for (const unsigned int v : {0u, 1u})
            {
              const unsigned int vertex = cell->face(f)->vertex_index(v);
              if (!seen.insert(vertex).second)
                continue;
              ContactNode node;
              node.vertex             = vertex;
              node.reference_position = cell->face(f)->vertex(v);
              node.dofs = BoundaryConditions::cell_vertex_dofs(
                cell, GeometryInfo<2>::face_to_cell_vertices(f, v), slave.space());
              slave_nodes.push_back(node);
            }

    if (master_body == nullptr)
      return;

    build_master_chain(source);
    if (description.surface == "faceted")
      curve = std::make_unique<FacetedCurve>(closed);
    else if (description.surface == "bspline")
      curve = std::make_unique<BSplineCurve>(
        closed ? BSplineCurve::EndCondition::periodic :
                 BSplineCurve::EndCondition::double_vertex);
    else
      {
        if (master_body->space().name() != "hermite")
          throw InputError(entry + "/Surface",
                           "a hermite surface needs a master body of "
                           "Hermite elements (body '" +
                             master_body->name() + "' uses " +
                             master_body->space().name() + ")");
        curve = std::make_unique<HermiteCurve>(closed);
      }
    const unsigned int minimum = closed ? 3 : 2;
    if (master_points.size() < minimum)
      throw InputError(entry + "/Master boundary",
                       "the master boundary has too few nodes for a curve");
  }



  void
  ContactPair::build_master_chain(const std::string &)
  {
    const std::string entry = description.entry + "/Master boundary";
    const types::boundary_id id =
      master_body->boundary_id(description.master_boundary, entry);

    struct Face
    {
      unsigned int                            v0, v1;
      typename DoFHandler<2>::active_cell_iterator cell;
      unsigned int                            face;
    };
    std::vector<Face>                                  faces;
    std::map<unsigned int, std::vector<unsigned int>> at_vertex;
    for (const auto &cell : master_body->dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
          {
            faces.push_back({cell->face(f)->vertex_index(0),
                             cell->face(f)->vertex_index(1),
                             cell,
                             f});
            at_vertex[faces.back().v0].push_back(faces.size() - 1);
            at_vertex[faces.back().v1].push_back(faces.size() - 1);
          }

    // Walk the faces as one chain: from an end if the boundary is open.
    unsigned int start = faces[0].v0, n_ends = 0;
    for (const auto &[vertex, list] : at_vertex)
      {
        if (list.size() > 2)
          throw InputError(entry,
                           "the master boundary branches (more than two "
                           "faces at a vertex): it must be one curve");
        if (list.size() == 1)
          {
            if (n_ends == 0)
              start = vertex;
            ++n_ends;
          }
      }
    closed = (n_ends == 0);
    std::vector<unsigned int> chain = {start};
    std::vector<unsigned int> chain_faces;
    std::vector<bool>         used(faces.size(), false);
    while (true)
      {
        int next_face = -1;
        for (const unsigned int f : at_vertex[chain.back()])
          if (!used[f])
            next_face = f;
        if (next_face < 0)
          break;
        used[next_face] = true;
        chain_faces.push_back(next_face);
        const Face &face = faces[next_face];
        chain.push_back(face.v0 == chain.back() ? face.v1 : face.v0);
      }
    if (chain_faces.size() != faces.size())
      throw InputError(entry,
                       "the master boundary is not connected: it must be "
                       "one curve");
    if (closed)
      chain.pop_back(); // the walk came back to its start

    // The master body must lie to the right of the direction of travel,
    // so that n = e3 x t points out of it.
    const auto  &vertices = master_body->triangulation().get_vertices();
    const Face  &first    = faces[chain_faces[0]];
    const Tensor<1, 2> t  = vertices[chain[1]] - vertices[chain[0]];
    const Tensor<1, 2> outward =
      first.cell->face(first.face)->center() - first.cell->center();
    if (-t[1] * outward[0] + t[0] * outward[1] < 0.)
      {
        std::reverse(chain.begin(), chain.end());
        std::reverse(chain_faces.begin(), chain_faces.end());
        if (closed)
          {
            // Keep segment i joining chain[i] and chain[i + 1]: after the
            // reversal the closing face comes first.
            std::rotate(chain_faces.begin(), chain_faces.begin() + 1,
                        chain_faces.end());
          }
      }

    for (const unsigned int v : chain)
      {
        master_points.push_back(vertices[v]);
        master_dofs.push_back(BoundaryConditions::vertex_dofs(
          master_body->dof_handler(), master_body->space(), v));
      }

    // Hermite masters: derivative dofs and reference tangents per segment.
    const auto *hermite =
      dynamic_cast<const HermiteSpace *>(&master_body->space());
    if (hermite == nullptr)
      return;
    const FiniteElement<2> &fe = master_body->space().finite_element();
    master_hermite_dofs.resize(chain.size());
    for (unsigned int i = 0; i < chain_faces.size(); ++i)
      {
        const Face        &face = faces[chain_faces[i]];
        const unsigned int a    = i, b = (i + 1) % chain.size();
        const auto edge = HermiteQuadrilateral::edge_from_dealii_face(face.face);
        const auto ends = HermiteQuadrilateral::edge_nodes(edge.edge);
        const auto dir  = HermiteQuadrilateral::edge_reference_direction(edge.edge);
        const auto &element = hermite->element(face.cell->active_cell_index());
        std::array<Tensor<1, 2>, 2> tangent_at_end;
        for (unsigned int e = 0; e < 2; ++e)
          {
            const auto ref = HermiteQuadrilateral::node_reference_point(ends[e]);
            const auto J   = element.jacobian(ref[0], ref[1]);
            // d/ds on [-1, 1] -> d/dsigma on [0, 1]: a factor 2.
            tangent_at_end[e] =
              2. * Tensor<1, 2>({J[0][0] * dir[0] + J[0][1] * dir[1],
                                 J[1][0] * dir[0] + J[1][1] * dir[1]});
            const unsigned int v = HermiteQuadrilateral::dealii_vertex_from_node(ends[e]);
            const unsigned int chain_index =
              face.cell->vertex_index(v) == chain[a] ? a : b;
            for (unsigned int k = 0; k < 6; ++k)
              master_hermite_dofs[chain_index]
                                 [fe.system_to_component_index(v * 6 + k).first] =
                face.cell->vertex_dof_index(v, k);
          }
        const bool same_direction =
          face.cell->vertex_index(
            HermiteQuadrilateral::dealii_vertex_from_node(ends[0])) == chain[a];
        segment_reference_tangents.push_back(
          same_direction ?
            std::array<Tensor<1, 2>, 2>{{tangent_at_end[0], tangent_at_end[1]}} :
            std::array<Tensor<1, 2>, 2>{{-tangent_at_end[1], -tangent_at_end[0]}});
      }
  }



  Point<2>
  ContactPair::current_position(
    const Body                                   &body,
    const std::array<types::global_dof_index, 2> &dofs,
    const Point<2>                               &X) const
  {
    return X + Tensor<1, 2>({body.displacement()(dofs[0]),
                             body.displacement()(dofs[1])});
  }



  void
  ContactPair::update_master_curve()
  {
    TimerOutput::Scope              scope(timer, timing::surface);
    std::vector<MasterCurve::Point> points;
    for (unsigned int j = 0; j < master_points.size(); ++j)
      {
        const Point<2> x =
          current_position(*master_body, master_dofs[j], master_points[j]);
        points.push_back({{x[0], x[1]}});
      }
    if (description.surface != "hermite")
      {
        curve->update(points);
        return;
      }
    // Deformed tangents d = (I + grad u) T at both ends of each segment.
    const Vector<double> &u = master_body->displacement();
    std::vector<std::array<MasterCurve::Point, 2>> tangents;
    for (unsigned int i = 0; i < segment_reference_tangents.size(); ++i)
      {
        std::array<MasterCurve::Point, 2> pair;
        for (unsigned int e = 0; e < 2; ++e)
          {
            const unsigned int  node = (i + e) % master_points.size();
            const Tensor<1, 2> &T    = segment_reference_tangents[i][e];
            const auto         &d    = master_hermite_dofs[node];
            for (unsigned int c = 0; c < 2; ++c)
              pair[e][c] = T[c] + u(d[3 * c + 1]) * T[0] + u(d[3 * c + 2]) * T[1];
          }
        tangents.push_back(pair);
      }
    static_cast<HermiteCurve &>(*curve).update(points, tangents);
  }



  bool
  ContactPair::project_on_segment(const Point<2>    &x,
                                  const unsigned int segment,
                                  double            &s,
                                  const double       margin) const
  {
    // Newton on f(s) = (c(s) - x) . c'(s), started from the last s.
    for (unsigned int it = 0; it < 30; ++it)
      {
        MasterCurve::Point c, dc, ddc;
        curve->evaluate(segment, s, c, dc, ddc);
        const double f  = (c[0] - x[0]) * dc[0] + (c[1] - x[1]) * dc[1];
        const double df = dc[0] * dc[0] + dc[1] * dc[1] +
                          (c[0] - x[0]) * ddc[0] + (c[1] - x[1]) * ddc[1];
        if (!(df > 0.))
          return false;
        const double step = f / df;
        s -= step;
        if (s < -margin - 1e-10 || s > 1. + margin + 1e-10)
          return false;
        if (std::abs(step) < 1e-15)
          break;
      }
    if (margin == 0.)
      s = std::min(1., std::max(0., s));
    return true;
  }



  void
  ContactPair::linearize(ContactNode       &node,
                         const Point<2>    &x,
                         const unsigned int segment,
                         const double       s) const
  {
    const auto t = curve->unit_tangent(segment, s);
    const auto c = curve->value(segment, s);
    node.segment = segment;
    node.s       = s;
    node.tangent = Tensor<1, 2>({t[0], t[1]});
    node.normal  = Tensor<1, 2>({-t[1], t[0]});
    node.gap     = (x[0] - c[0]) * node.normal[0] + (x[1] - c[1]) * node.normal[1];

    MasterCurve::NodeWeights weights;
    curve->weights(segment, s, weights);
    for (const auto &[j, phi] : weights)
      for (unsigned int c = 0; c < 2; ++c)
        node.kinematics.push_back({1, master_dofs[j][c], c, -phi});
    if (description.surface == "hermite")
      {
        // The tangent data d = (I + grad u) T enter with H10, H11.
        const auto ends = curve->segment_nodes(segment);
        const auto h =
          static_cast<const HermiteCurve &>(*curve).tangent_weights(segment, s);
        for (unsigned int e = 0; e < 2; ++e)
          {
            const Tensor<1, 2> &T = segment_reference_tangents[segment][e];
            const auto         &d = master_hermite_dofs[ends[e]];
            for (unsigned int c = 0; c < 2; ++c)
              for (unsigned int k = 0; k < 2; ++k)
                node.kinematics.push_back({1, d[3 * c + 1 + k], c, -h[e] * T[k]});
          }
      }

    node.forces.clear();
    if (description.surface == "bspline" &&
        description.force_transfer == "segment")
      {
        // The paper: the reaction goes to the two nodes of the straight
        // segment under the spline point.
        for (unsigned int c = 0; c < 2; ++c)
          node.forces.push_back({0, node.dofs[c], c, 1.});
        for (const auto &[j, phi] : curve->underlying_segment_weights(segment, s))
          for (unsigned int c = 0; c < 2; ++c)
            node.forces.push_back({1, master_dofs[j][c], c, -phi});
      }
    else
      node.forces = node.kinematics;
  }



  std::vector<types::global_dof_index>
  ContactPair::contact_dofs(const Body &body) const
  {
    std::vector<types::global_dof_index> dofs;
    if (&body == &slave_body)
      for (const auto &node : slave_nodes)
        dofs.insert(dofs.end(), node.dofs.begin(), node.dofs.end());
    if (&body == master_body)
      {
        for (const auto &d : master_dofs)
          dofs.insert(dofs.end(), d.begin(), d.end());
        for (const auto &d : master_hermite_dofs)
          dofs.insert(dofs.end(), d.begin(), d.end());
      }
    return dofs;
  }



  bool
  ContactPair::project(ContactNode &node, const bool keep_segment) const
  {
    const Point<2> x =
      current_position(slave_body, node.dofs, node.reference_position);
    node.kinematics.clear();
    for (unsigned int c = 0; c < 2; ++c)
      node.kinematics.push_back({0, node.dofs[c], c, 1.});

    if (obstacle)
      {
        const auto p = obstacle->project(x, time);
        node.tangent = p.tangent;
        node.normal  = p.normal;
        node.gap     = p.gap;
        node.forces  = node.kinematics;
        return true;
      }

    if (keep_segment && node.segment >= 0)
      {
        // A faceted segment is kept along its extension, up to half its
        // length past either end: in the valley between two facets (a
        // concave master vertex) the node otherwise jumps from one facet
        // to the other at every iteration and Newton cannot converge. The
        // choice is made afresh at the next increment.
        double s = node.s;
        if (project_on_segment(x,
                               node.segment,
                               s,
                               description.surface == "faceted" ? 0.5 : 0.))
          {
            linearize(node, x, node.segment, s);
            return true;
          }
      }

    const auto p = curve->project({{x[0], x[1]}});
    if (!p.valid)
      return false;
    linearize(node, x, p.segment, p.s);
    // At a convex corner of a faceted master the curve's own normal is
    // the average of the two segments': keep it, with that gap.
    if (p.on_vertex)
      {
        node.tangent = Tensor<1, 2>({p.tangent[0], p.tangent[1]});
        node.normal  = Tensor<1, 2>({p.normal[0], p.normal[1]});
        node.gap     = p.gap;
      }
    return true;
  }



  void
  ContactPair::begin_step(const double new_time)
  {
    time = new_time;
    if (curve)
      update_master_curve();
    for (auto &node : slave_nodes)
      {
        node.segment   = -1;
        node.projected = project(node);
        node.gap_at_step_start = node.gap;
        node.active = node.projected &&
                      node.gap <= description.alert_distance && can_react(node);
        if (!node.active)
          {
            node.reaction = {{0., 0.}};
            node.status   = BiPotentialSolver::NodeStatus::open;
          }
      }
  }



  void
  ContactPair::check_initial_state()
  {
    begin_step(0.);
    double       deepest = 0.;
    unsigned int behind  = 0;
    for (const auto &node : slave_nodes)
      if (node.projected && node.gap < 0.)
        {
          deepest = std::min(deepest, node.gap);
          ++behind;
        }
    for (auto &node : slave_nodes)
      {
        node.active   = false;
        node.segment  = -1;
        node.reaction = {{0., 0.}};
        node.status   = BiPotentialSolver::NodeStatus::open;
      }
    const double size =
      master_body ? std::min(slave_body.size(), master_body->size()) :
                    slave_body.size();
    // Interference fits and the sagitta of a faceted circle stay well
    // below this; a master that faces away puts the slave a whole
    // thickness behind it.
    if (deepest < -0.05 * size)
      {
        std::ostringstream message;
        message << "at t = 0, " << behind << " slave nodes of '"
                << description.slave_body << "/" << description.slave_boundary
                << "' lie up to " << -deepest << " behind the master "
                << (master_body ? "surface '" + description.master_body + "/" +
                                    description.master_boundary + "'" :
                                  std::string("obstacle"))
                << ", more than 5 % of the bodies' size (" << size
                << "): the master must face the slave";
        throw InputError(description.entry +
                           (master_body ? "/Master boundary" : "/Obstacle"),
                         message.str());
      }
  }



  bool
  ContactPair::can_react(const ContactNode &node) const
  {
    // A node whose gap depends only on prescribed dofs (a supported slave
    // corner against a rigid obstacle, or against a supported part of the
    // master) has no compliance at all, W_kk = 0: no reaction can change
    // its gap. It is left out rather than handed to the local solver, which
    // would refuse it. The dofs are those of the node's last projection.
    for (const auto &e : node.kinematics)
      {
        const Body &b = e.body == 0 ? slave_body : *master_body;
        if (e.weight != 0. && !b.dof_is_prescribed(e.dof))
          return true;
      }
    return false;
  }



  unsigned int
  ContactPair::activate_penetrating_nodes()
  {
    if (curve)
      update_master_curve();
    // Round-off of a node resting on the master is not a penetration.
    const double tolerance = 1e-10 * slave_body.size();
    unsigned int activated = 0;
    for (auto &node : slave_nodes)
      {
        if (node.active)
          continue;
        ContactNode trial = node;
        trial.segment     = -1;
        if (!project(trial) || trial.gap >= -tolerance || !can_react(trial))
          continue;
        // The gap at the start of the increment that the linear follow-up
        // of Frame update = increment needs: g_0 = g - n . (motion since).
        Tensor<1, 2> motion;
        for (const auto &e : trial.kinematics)
          {
            const Body &b = e.body == 0 ? slave_body : *master_body;
            motion[e.component] +=
              e.weight *
              (b.displacement()(e.dof) - b.stored_displacement()(e.dof));
          }
        trial.gap_at_step_start = trial.gap - trial.normal * motion;
        trial.active            = true;
        trial.projected         = true;
        trial.reaction          = {{0., 0.}};
        trial.status            = BiPotentialSolver::NodeStatus::open;
        node                    = trial;
        ++activated;
      }
    return activated;
  }



  void
  ContactPair::update_geometry()
  {
    if (description.frame_update == "increment")
      {
        // Frame and maps of the start of the increment; the gap follows
        // linearly: g = g_0 + n . (slave - master motion since then).
        for (auto &node : slave_nodes)
          if (node.active)
            {
              Tensor<1, 2> motion;
              for (const auto &e : node.kinematics)
                {
                  const Body &b = e.body == 0 ? slave_body : *master_body;
                  motion[e.component] +=
                    e.weight * (b.displacement()(e.dof) -
                                b.stored_displacement()(e.dof));
                }
              node.gap = node.gap_at_step_start + node.normal * motion;
            }
        return;
      }
    if (curve)
      update_master_curve();
    for (auto &node : slave_nodes)
      if (node.active && !project(node, true))
        {
          // Slid off an open master: out of contact for the rest of the step.
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
    return sum;
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
