#include <deal.II/base/quadrature_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/contact/discretisation/contact_discretisation.h>
#include <glissade/contact/discretisation/mortar_curve_point.h>
#include <glissade/contact/discretisation/mortar_variables.h>
#include <glissade/contact/surfaces/composite_surface.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/description/scene_description.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using mortar::Accumulated;
    using mortar::add_scaled;
    using mortar::DualPoint;
    using mortar::LocalVariables;
    using mortar::merge_entries;
    using mortar::merge_proportional_terms;
    using mortar::MortarDual;
    using mortar::root_near_linear;

    /** What Mortar::update() finds for each slave point. */
    struct NodeState
    {
      /** D_j over the node's tributary length (1: fully covered). */
      double                              coverage = 0.;
      Point<2>                            x;
      Tensor<1, 2>                        normal, tangent, motion;
      DofVector                           rotation_row; // d theta / dU
      Accumulated                         D;
      std::map<unsigned int, Accumulated> M; // by master point
      /**
       * On a smooth curve, int Phi_j w by (master dof, component), w the
       * curve's force weights there: where the reaction goes.
       */
      std::map<std::pair<types::global_dof_index, unsigned int>, Accumulated> F;
      /**
       * Against a rigid obstacle or a smooth curve: int Phi_j y and
       * int Phi_j m (the obstacle's closest points or the curve's
       * points, and their material's motion), per component.
       */
      std::array<Accumulated, 2> Y, moved;
      /** A face point had no counterpart on the obstacle. */
      bool uncovered = false;
      /**
       * A point of one of its faces was past an open obstacle's end (and
       * integrated against the end's tangent line): the node counts only
       * if it is not past the end itself.
       */
      bool next_to_open_end = false;
      /** Where its own point stands against that end (project()). */
      mortar::OpenEndPlace open_end;
    };



    /**
     * On a smooth curve, what a slave face's integrals over a segment
     * add up besides D and M: int Phi y and int Phi m (the curve's points
     * and their motion) per slave node and component, the curve point's
     * dof weights at each Gauss point (which map the variables 12 + 2q,
     * 13 + 2q to the dofs), and the force weights' integrals int Phi w
     * by (dof, component).
     */
    struct CurveIntegrals
    {
      std::array<DualPoint, 2>                segment_ends;
      MortarDual                              Y[2][2] = {}, moved[2][2] = {};
      std::vector<std::vector<SurfaceWeight>> kinematics =
        std::vector<std::vector<SurfaceWeight>>(4);
      std::map<std::pair<types::global_dof_index, unsigned int>,
               std::array<MortarDual, 2>>
        F;
    };



    /**
     * Segment-to-segment mortar contact with dual Lagrange multipliers
     * (Wohlmuth 2000; Popp, Gee and Wall 2009; Yang, Laursen and Meng
     * 2005 for the large-sliding 2D case), integrated segment by segment:
     * doc/contact.md, "Mortar".
     *
     * The slave side is its boundary's straight faces with their linear
     * shape functions N_j and the dual functions Phi_j (on a face from
     * node a to node b, s in [0, 1]: Phi_a = 2 - 3 s, Phi_b = 3 s - 1,
     * biorthogonal to N: int Phi_j N_k = delta_jk int N_j). Each slave node
     * has the normal n_j of the faces that meet there; a slave point's
     * normal is the interpolation of the nodal ones, and its master point
     * is where that normal meets the master. On the cells where a slave
     * face and a master segment overlap (cut by the master nodes projected
     * along the slave normal field), Gauss quadrature gives
     *
     *   D_j  = int Phi_j,     M_jk = int Phi_j N_k(master),
     *
     * and the node's constraint is its weighted gap D_j n_j . (x_j - y_j)
     * with the mortar point y_j = sum_k m_jk y_k, m_jk = M_jk / D_j
     * (sum_k m_jk = 1): a node-to-segment constraint against y_j, with the
     * reaction r_j = D_j lambda_j (so that the outputs, which read a
     * node's reaction as a force, read mortar's as well; the pressure is
     * lambda_j = r_j / D_j, what the contact tables report). Dividing by
     * D_j > 0 changes neither the constraint's solution nor its
     * multiplier's sign.
     *
     * Against a rigid obstacle, and on a smooth (B-spline) master, y_j is
     * int Phi_j y / D_j instead, y the obstacle's closest point or the
     * curve's point on the normal; on the curve, the reaction still goes
     * to the underlying segments' nodes by the weights m_jk (doc/contact.md).
     *
     * Every integral is differentiated exactly (forward-mode, Dual), so
     * the gap and slip rows and the contact tangent (the turn of n_j and
     * the change of every m_jk at fixed reaction) are consistent.
     */
    class Mortar : public ContactDiscretisation
    {
    public:
      explicit Mortar(const Context &context);

      void
      update() override;

      bool
      project(ContactNode &node, bool keep_segment) const override;

    private:
      /** A point of either side: body 0 the slave, 1 the master. */
      struct SidePoint
      {
        unsigned int body;
        /** A node's value dofs (a faceted master's weights go to them). */
        std::array<types::global_dof_index, 2> dofs;
        Point<2>                               reference;
        /** What the point moves with: the node's dofs, or a NURBS curve's
         *  control points (CurveSurface::node_shares). */
        SlaveShares shares;
      };

      /** The current position and the motion since the increment began. */
      Point<2>
      position(const SidePoint &p) const;
      Tensor<1, 2>
      motion(const SidePoint &p) const;

      /** Adds the integrals of slave face f over master segment i. */
      void
      integrate(unsigned int f, unsigned int i);

      /**
       * Cheap tests, in plain numbers: master segment i faces slave face
       * f, lies within reach of it, and its nodes' images overlap it;
       * [eta_low, eta_high] the segment's extent (an open master's end
       * segments continue past its ends).
       */
      bool
      may_overlap(unsigned int f,
                  unsigned int i,
                  double      &eta_low,
                  double      &eta_high) const;


      /**
       * The curve point of Gauss point q on segment i, where the slave
       * normal n through x meets it, added with the weights wa, wb of the
       * face's two nodes; eta becomes its parameter (along the chord where
       * the reaction goes by segment transfer). False if there is none.
       */
      bool
      add_curve_point(unsigned int      i,
                      unsigned int      q,
                      const DualPoint  &x,
                      const DualPoint  &n,
                      const MortarDual &wa,
                      const MortarDual &wb,
                      MortarDual       &eta,
                      CurveIntegrals   &on_curve) const;

      /**
       * Adds the integrals of slave face f against a rigid obstacle: the
       * obstacle's points y(x) closest to the face's points, and the
       * motion of its material there since the increment began.
       */
      void
      integrate_on_obstacle(unsigned int f);

      /**
       * The dof forces of a unit reaction v at node `node` (and the weights
       * of x - y), added to `out`.
       */
      void
      add_unit_reaction(const NodeState    &s,
                        const ContactNode  &node,
                        const Tensor<1, 2> &v,
                        DofVector          &out) const;

      /**
       * What the change of the node's weights adds: the gap and slip rows'
       * dm_k terms (faceted master), and the contact tangent at fixed
       * reaction, the turn of the nodal normal and each weight's change.
       */
      void
      add_weight_changes(const NodeState      &s,
                         const ContactNode    &node,
                         ContactLinearization &l) const;

      /** The unit normal at slave node j as Duals over `local`'s points. */
      DualPoint
      nodal_normal(unsigned int                                j,
                   const std::vector<DualPoint>               &coordinates,
                   const std::map<unsigned int, unsigned int> &local) const;

      const Body &slave;
      /** nullptr for a rigid obstacle (no master body, no chain). */
      const Body          *master;
      const MasterChain   *chain;
      const MasterSurface &surface;
      /**
       * A smooth master (B-spline, Hermite) as the integration geometry;
       * nullptr for the faceted one (its straight segments) and for
       * obstacles.
       */
      const CurveSurface *curve_surface = nullptr;
      const MasterCurve  *curve         = nullptr;
      const double        search_distance;

      std::vector<SidePoint>               slave_points, master_points;
      std::map<unsigned int, unsigned int> point_of_vertex;
      /** Slave faces (a, b), oriented with the slave on the right. */
      std::vector<std::array<unsigned int, 2>> faces;
      std::vector<std::vector<unsigned int>>   faces_of_point;

      /**
       * Self-contact (the master is the slave's own boundary): each slave
       * face's segment on the master chain (-1 where the face is not on
       * it), and which segments a face may integrate against
       * (sees_in_self_contact()).
       */
      bool             self_contact = false;
      std::vector<int> segment_of_face;

      /**
       * In self-contact, whether slave face f may meet master segment i:
       * not its own segment, nor the two next to it on each side (whose
       * points face the same way as the face, or nearly), and only the
       * segments that come later along the chain, so that two stretches of
       * the boundary that face each other are held once, by the earlier
       * stretch's faces (as node-to-segment holds them:
       * CurveSurface::project_facing). Held twice, each node-on-node pair
       * would be constrained twice and the condensed problem singular.
       */
      bool
      sees_in_self_contact(unsigned int f, unsigned int i) const;

      std::vector<NodeState> state;
      /** The current positions of the slave and master points. */
      std::vector<Point<2>> slave_positions, master_positions;
    };



    Mortar::Mortar(const Context &context)
      : slave(context.slave)
      , master(context.master)
      , chain(context.master ?
                &dynamic_cast<const CurveSurface &>(context.surface)
                   .master_chain() :
                nullptr)
      , surface(context.surface)
      , curve_surface(context.master &&
                          context.description.surface != "faceted" ?
                        &dynamic_cast<const CurveSurface &>(context.surface) :
                        nullptr)
      , curve(curve_surface ? &curve_surface->master_curve() : nullptr)
      , search_distance(context.description.alert_distance)
    {
      for (const ContactNode &node : context.nodes)
        {
          point_of_vertex[node.vertex] = slave_points.size();
          // (mortar's slave nodes are vertices, one share each: ContactPair
          // refuses a NURBS slave)
          slave_points.push_back({0,
                                  node.shares.front().dofs,
                                  node.reference_position,
                                  node.shares});
        }
      for (unsigned int k = 0; chain && k < chain->vertices.size(); ++k)
        master_points.push_back({1,
                                 chain->value_dofs[k],
                                 chain->reference_points[k],
                                 curve_surface ?
                                   curve_surface->node_shares(k) :
                                   SlaveShares{{chain->value_dofs[k], 1.}}});

      // The slave faces, each oriented so that its left normal points out
      // of its cell (the master chain's convention, MasterChain).
      std::set<unsigned int> slave_vertices;
      for (const auto &[vertex, index] : point_of_vertex)
        slave_vertices.insert(vertex);
      faces_of_point.resize(slave_points.size());
      for (const auto &cell : slave.dof_handler().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              slave_vertices.count(cell->face(f)->vertex_index(0)) &&
              slave_vertices.count(cell->face(f)->vertex_index(1)))
            {
              // (A face between two slave vertices that is not on a slave
              // boundary cannot exist on a boundary of Q1 cells but for a
              // one-cell-thick strip; ContactPair's nodes come from the
              // slave boundary's faces, so their boundary ids decide.)
              if (!context.slave_boundary_ids.count(
                    cell->face(f)->boundary_id()))
                continue;
              unsigned int a =
                point_of_vertex.at(cell->face(f)->vertex_index(0));
              unsigned int b =
                point_of_vertex.at(cell->face(f)->vertex_index(1));
              const Tensor<1, 2> along =
                slave_points[b].reference - slave_points[a].reference;
              const Tensor<1, 2> out({-along[1], along[0]});
              if (out * (cell->face(f)->center() - cell->center()) < 0.)
                std::swap(a, b);
              faces.push_back({{a, b}});
              faces_of_point[a].push_back(faces.size() - 1);
              faces_of_point[b].push_back(faces.size() - 1);
            }
      for (unsigned int j = 0; j < slave_points.size(); ++j)
        if (faces_of_point[j].size() > 2)
          throw InputError(
            context.description.entry + "/Slave boundary",
            "mortar contact needs the slave boundary as "
            "curves: the node at (" +
              std::to_string(slave_points[j].reference[0]) + ", " +
              std::to_string(slave_points[j].reference[1]) + ") joins " +
              std::to_string(faces_of_point[j].size()) + " faces");
      state.resize(slave_points.size());

      // Self-contact: each face's place on the chain, from its nodes'
      // (ContactPair's facing views).
      self_contact = master == &slave;
      if (self_contact)
        {
          const int n = chain->vertices.size();
          segment_of_face.assign(faces.size(), -1);
          for (unsigned int f = 0; f < faces.size(); ++f)
            {
              // (slave point j is context.nodes[j])
              const int pa = context.nodes[faces[f][0]].facing_view.master_node,
                        pb = context.nodes[faces[f][1]].facing_view.master_node;
              if (pa < 0 || pb < 0)
                continue;
              const auto next = [&](const int k) {
                return chain->closed ? (k + 1) % n : k + 1;
              };
              if (pb == next(pa))
                segment_of_face[f] = pa;
              else if (pa == next(pb))
                segment_of_face[f] = pb;
            }
        }
    }



    bool
    Mortar::sees_in_self_contact(const unsigned int f,
                                 const unsigned int i) const
    {
      const int own = segment_of_face[f];
      if (own < 0)
        return true;
      const int n_segments = chain->vertices.size() - (chain->closed ? 0 : 1);
      return int(i) >= own + 3 &&
             (!chain->closed || int(i) + 3 <= own + n_segments);
    }



    Point<2>
    Mortar::position(const SidePoint &p) const
    {
      const Vector<double> &u = (p.body == 0 ? slave : *master).displacement();
      Point<2>              x = p.reference;
      for (const SlaveShare &share : p.shares)
        for (unsigned int c = 0; c < 2; ++c)
          x[c] += share.weight * u(share.dofs[c]);
      return x;
    }



    Tensor<1, 2>
    Mortar::motion(const SidePoint &p) const
    {
      const Body           &body = p.body == 0 ? slave : *master;
      const Vector<double> &u    = body.displacement();
      const Vector<double> &u0   = body.stored_displacement();
      Tensor<1, 2>          d;
      for (const SlaveShare &share : p.shares)
        for (unsigned int c = 0; c < 2; ++c)
          d[c] += share.weight * (u(share.dofs[c]) - u0(share.dofs[c]));
      return d;
    }



    DualPoint
    Mortar::nodal_normal(
      const unsigned int                          j,
      const std::vector<DualPoint>               &coordinates,
      const std::map<unsigned int, unsigned int> &local) const
    {
      // The faces' left normals (out of the slave, as long as the face)
      // summed, turned inwards: n_j points from the master to the slave,
      // as a master surface's normal does.
      DualPoint sum{MortarDual(0.), MortarDual(0.)};
      for (const unsigned int f : faces_of_point[j])
        sum = sum + left_normal(coordinates[local.at(faces[f][1])] -
                                coordinates[local.at(faces[f][0])]);
      const MortarDual length = sqrt(sum.x * sum.x + sum.y * sum.y);
      return {-sum.x / length, -sum.y / length};
    }



    void
    Mortar::integrate(const unsigned int f, const unsigned int i)
    {
      const unsigned int a = faces[f][0], b = faces[f][1];
      const unsigned int c = i, d = (i + 1) % master_points.size();

      double eta_low = 0., eta_high = 1.;
      if (!may_overlap(f, i, eta_low, eta_high))
        return;

      // The local variables: the slave points of both nodal normals, then
      // the master segment's nodes.
      std::map<unsigned int, unsigned int> local; // slave point -> local
      LocalVariables                       variables;
      for (const unsigned int j : {a, b})
        for (const unsigned int g : faces_of_point[j])
          for (const unsigned int p : faces[g])
            if (!local.count(p))
              local[p] =
                variables.add(0, slave_points[p].shares, slave_positions[p]);
      const unsigned int lc =
        variables.add(1, master_points[c].shares, master_positions[c]);
      const unsigned int ld =
        variables.add(1, master_points[d].shares, master_positions[d]);
      const unsigned int            n_used      = variables.n_used();
      const auto                   &dofs        = variables.dofs;
      const std::vector<DualPoint> &coordinates = variables.coordinates;

      const DualPoint &Xa = coordinates[local.at(a)];
      const DualPoint &Xb = coordinates[local.at(b)];
      const DualPoint &Yc = coordinates[lc];
      const DualPoint &Yd = coordinates[ld];
      const DualPoint  Na = nodal_normal(a, coordinates, local);
      const DualPoint  Nb = nodal_normal(b, coordinates, local);
      const DualPoint  dX = Xb - Xa, dN = Nb - Na;

      // Where the slave normal field through a master node y meets the
      // face: (x(s) - y) x n(s) = 0, quadratic in s, solved in plain
      // numbers, then one Newton step on the Duals for the derivatives.
      const auto slave_coordinate = [&](const DualPoint &Y, bool &found) {
        const DualPoint  r = Xa - Y;
        const MortarDual A = cross(dX, dN);
        const MortarDual B = cross(r, dN) + cross(dX, Na);
        const MortarDual C = cross(r, Na);
        const double     s = root_near_linear(A.value, B.value, C.value);
        found              = std::isfinite(s);
        return s - (A * s * s + B * s + C) / (2. * s * A + B);
      };
      bool             found_c = false, found_d = false;
      const MortarDual sc =
        slave_coordinate(Yc + MortarDual(eta_low) * (Yd - Yc), found_c);
      const MortarDual sd =
        slave_coordinate(Yc + MortarDual(eta_high) * (Yd - Yc), found_d);
      if (!found_c || !found_d)
        return;
      // The overlap in s: between the two master nodes' images (the
      // master runs against the slave, so d comes first), within the face.
      const MortarDual &first = sd.value < sc.value ? sd : sc;
      const MortarDual &last  = sd.value < sc.value ? sc : sd;
      const MortarDual  lower = first.value > 0. ? first : MortarDual(0.);
      const MortarDual  upper = last.value < 1. ? last : MortarDual(1.);
      if (upper.value - lower.value <= 1e-12)
        return;

      // Gauss-Legendre, four points on [0, 1]: exact for the flat case
      // (degree 2) and ample for the rational integrand of curved ones.
      static const QGauss<1> gauss(4);
      const MortarDual       length = sqrt(dX.x * dX.x + dX.y * dX.y);
      MortarDual             Da(0.), Db(0.), Mac(0.), Mad(0.), Mbc(0.), Mbd(0.);
      CurveIntegrals         on_curve;
      on_curve.segment_ends = {{Yc, Yd}};
      for (unsigned int q = 0; q < 4; ++q)
        {
          const MortarDual s    = lower + gauss.point(q)[0] * (upper - lower);
          const MortarDual w    = gauss.weight(q) * (upper - lower) * length;
          const DualPoint  x    = Xa + s * dX;
          const DualPoint  n    = Na + s * dN;
          const MortarDual phia = 2. - 3. * s, phib = 3. * s - 1.;
          // The master point on the normal: (y(eta) - x) x n = 0.
          MortarDual eta = cross(x - Yc, n) / cross(Yd - Yc, n);
          // (on a curve, no master point where the normal runs along it:
          // the segment pair adds nothing)
          if (curve &&
              !add_curve_point(i, q, x, n, w * phia, w * phib, eta, on_curve))
            return;
          Da += w * phia;
          Db += w * phib;
          if (!curve)
            {
              Mac += w * phia * (1. - eta);
              Mad += w * phia * eta;
              Mbc += w * phib * (1. - eta);
              Mbd += w * phib * eta;
            }
        }
      // On a curve, the curve points' variables go to its dofs.
      const auto add = [&](Accumulated &to, const MortarDual &v) {
        to.add(v, dofs, n_used);
        if (curve)
          mortar::add_curve_variables(v, on_curve.kinematics, 12, to);
      };
      add(state[a].D, Da);
      add(state[b].D, Db);
      if (!curve)
        {
          add(state[a].M[c], Mac);
          add(state[a].M[d], Mad);
          add(state[b].M[c], Mbc);
          add(state[b].M[d], Mbd);
          return;
        }
      for (unsigned int k = 0; k < 2; ++k)
        {
          add(state[a].Y[k], on_curve.Y[0][k]);
          add(state[b].Y[k], on_curve.Y[1][k]);
          add(state[a].moved[k], on_curve.moved[0][k]);
          add(state[b].moved[k], on_curve.moved[1][k]);
        }
      for (const auto &[key, weights] : on_curve.F)
        {
          add(state[a].F[key], weights[0]);
          add(state[b].F[key], weights[1]);
        }
    }



    bool
    Mortar::may_overlap(const unsigned int f,
                        const unsigned int i,
                        double            &eta_low,
                        double            &eta_high) const
    {
      const unsigned int a = faces[f][0], b = faces[f][1];
      const unsigned int c = i, d = (i + 1) % master_points.size();

      // Cheap tests first, in plain numbers: the segment faces the slave
      // face, lies within reach of it, and its nodes' images overlap it.
      const Point<2>    &xa = slave_positions[a], &xb = slave_positions[b];
      const Point<2>    &yc = master_positions[c], &yd = master_positions[d];
      const Tensor<1, 2> slave_out({-(xb - xa)[1], (xb - xa)[0]});
      const Tensor<1, 2> master_out({-(yd - yc)[1], (yd - yc)[0]});
      if (slave_out * master_out >= 0.)
        return false;
      if (self_contact)
        {
          // Not the face's neighbours, nor an earlier stretch; nor a
          // segment behind the face by more than half the face: that is
          // the body's other side, seen through it.
          if (!sees_in_self_contact(f, i))
            return false;
          const double face_length = (xb - xa).norm();
          const double in_front =
            std::max((yc - xa) * slave_out, (yd - xa) * slave_out) /
            face_length;
          if (in_front < -0.5 * face_length)
            return false;
        }
      const double reach =
        search_distance + (xb - xa).norm() + (yd - yc).norm();
      const Point<2> slave_mid = 0.5 * (xa + xb), master_mid = 0.5 * (yc + yd);
      if (slave_mid.distance(master_mid) > reach)
        return false;
      // An open master's end segments continue past its ends by half
      // their length (linear shape functions extrapolated), as a
      // node-to-segment node may keep its end segment: a slave node that
      // slides off the end loses its counterpart over half a segment, not
      // at once.
      const bool open_start = !curve && !chain->closed && i == 0;
      const bool open_end =
        !curve && !chain->closed && i + 2 == master_points.size();
      eta_low                = open_start ? -0.5 : 0.;
      eta_high               = open_end ? 1.5 : 1.;
      const Tensor<1, 2> &na = state[a].normal, &nb = state[b].normal;
      const auto cross2 = [](const Tensor<1, 2> &u, const Tensor<1, 2> &v) {
        return u[0] * v[1] - u[1] * v[0];
      };
      const auto image = [&](const Point<2> &y) {
        const Tensor<1, 2> r = xa - y, dx = xb - xa, dn = nb - na;
        return root_near_linear(cross2(dx, dn),
                                cross2(r, dn) + cross2(dx, na),
                                cross2(r, na));
      };
      const double sc = image(yc + eta_low * (yd - yc)),
                   sd = image(yc + eta_high * (yd - yc));
      return std::isfinite(sc) && std::isfinite(sd) &&
             std::min(1., std::max(sc, sd)) - std::max(0., std::min(sc, sd)) >
               1e-12;
    }



    bool
    Mortar::add_curve_point(const unsigned int i,
                            const unsigned int q,
                            const DualPoint   &x,
                            const DualPoint   &n,
                            const MortarDual  &wa,
                            const MortarDual  &wb,
                            MortarDual        &eta,
                            CurveIntegrals    &on_curve) const
    {
      mortar::CurvePoint point;
      if (!mortar::find_curve_point(
            *curve_surface,
            *master,
            i,
            12 + 2 * q,
            x,
            n,
            eta.value,
            on_curve.segment_ends,
            {{master_points[i].dofs,
              master_points[(i + 1) % master_points.size()].dofs}},
            point))
        return false;
      on_curve.kinematics[q] = std::move(point.kinematics);
      for (unsigned int k = 0; k < 2; ++k)
        {
          on_curve.Y[0][k] += wa * point.y[k];
          on_curve.Y[1][k] += wb * point.y[k];
          on_curve.moved[0][k] += wa * point.motion[k];
          on_curve.moved[1][k] += wb * point.motion[k];
        }
      for (const mortar::CurveForceWeight &e : point.forces)
        {
          auto &[to_a, to_b] = on_curve.F[{e.dof, e.component}];
          to_a += wa * e.weight;
          to_b += wb * e.weight;
        }
      return true;
    }



    void
    Mortar::integrate_on_obstacle(const unsigned int f)
    {
      const unsigned int a = faces[f][0], b = faces[f][1];
      LocalVariables     variables;
      for (const unsigned int p : faces[f])
        variables.add(0, slave_points[p].shares, slave_positions[p]);
      const auto      &dofs   = variables.dofs;
      const DualPoint  X[2]   = {variables.coordinates[0],
                                 variables.coordinates[1]};
      const DualPoint  dX     = X[1] - X[0];
      const MortarDual length = sqrt(dX.x * dX.x + dX.y * dX.y);

      // Five Gauss points: the obstacle's points are not polynomial in s.
      static const QGauss<1> gauss(5);
      MortarDual             Da(0.), Db(0.);
      MortarDual             Ya[2] = {0., 0.}, Yb[2] = {0., 0.};
      MortarDual             ma[2] = {0., 0.}, mb[2] = {0., 0.};
      for (unsigned int q = 0; q < 5; ++q)
        {
          const double       s = gauss.point(q)[0];
          const MortarDual   w = gauss.weight(q) * length;
          const DualPoint    x = X[0] + MortarDual(s) * dX;
          const SurfacePoint point =
            surface.project(Point<2>(x.x.value, x.y.value));
          if (point.beyond_open_end)
            state[a].next_to_open_end = state[b].next_to_open_end = true;
          else if (!point.valid)
            {
              state[a].uncovered = state[b].uncovered = true;
              return;
            }
          // The closest point (or past an open end, the point on the end's
          // tangent line) and its material's motion, moving with x.
          const mortar::CurvePoint on_obstacle =
            mortar::obstacle_point(point, x);
          const auto      &y    = on_obstacle.y;
          const auto      &m    = on_obstacle.motion;
          const MortarDual phia = MortarDual(2. - 3. * s),
                           phib = MortarDual(3. * s - 1.);
          Da += w * phia;
          Db += w * phib;
          for (unsigned int c = 0; c < 2; ++c)
            {
              Ya[c] += w * phia * y[c];
              Yb[c] += w * phib * y[c];
              ma[c] += w * phia * m[c];
              mb[c] += w * phib * m[c];
            }
        }
      const unsigned int n_used = variables.n_used();
      state[a].D.add(Da, dofs, n_used);
      state[b].D.add(Db, dofs, n_used);
      for (unsigned int c = 0; c < 2; ++c)
        {
          state[a].Y[c].add(Ya[c], dofs, n_used);
          state[b].Y[c].add(Yb[c], dofs, n_used);
          state[a].moved[c].add(ma[c], dofs, n_used);
          state[b].moved[c].add(mb[c], dofs, n_used);
        }
    }



    void
    Mortar::update()
    {
      slave_positions.resize(slave_points.size());
      for (unsigned int j = 0; j < slave_points.size(); ++j)
        slave_positions[j] = position(slave_points[j]);
      master_positions.resize(master_points.size());
      for (unsigned int k = 0; k < master_points.size(); ++k)
        master_positions[k] = position(master_points[k]);
      for (unsigned int j = 0; j < slave_points.size(); ++j)
        {
          NodeState &s = state[j];
          s            = NodeState();
          s.x          = slave_positions[j];
          s.motion     = motion(slave_points[j]);

          // The nodal normal and its turn, d theta = -t . dn.
          std::map<unsigned int, unsigned int> local;
          LocalVariables                       variables;
          for (const unsigned int g : faces_of_point[j])
            for (const unsigned int p : faces[g])
              if (!local.count(p))
                local[p] =
                  variables.add(0, slave_points[p].shares, slave_positions[p]);
          if (faces_of_point[j].empty())
            continue;
          const DualPoint n = nodal_normal(j, variables.coordinates, local);
          s.normal          = Tensor<1, 2>({n.x.value, n.y.value});
          s.tangent         = Tensor<1, 2>({s.normal[1], -s.normal[0]});
          Accumulated theta;
          theta.add(-(s.tangent[0] * n.x + s.tangent[1] * n.y),
                    variables.dofs,
                    variables.n_used());
          s.rotation_row = theta.gradient;
        }

      for (unsigned int f = 0; f < faces.size(); ++f)
        if (chain == nullptr)
          integrate_on_obstacle(f);
        else
          for (unsigned int i = 0;
               i + (chain->closed ? 0 : 1) < master_points.size();
               ++i)
            integrate(f, i);
      // Next to an open obstacle's end, a node counts as a node-to-segment
      // node does: if it is not past the end itself (its faces' parts past
      // the end were integrated against the end's tangent line, so that
      // the node at the end carries its whole support, and its neighbour
      // past the end none).
      if (chain == nullptr)
        for (unsigned int j = 0; j < slave_points.size(); ++j)
          if (state[j].next_to_open_end && !state[j].uncovered)
            state[j].open_end =
              mortar::open_end_place(surface, slave_positions[j]);

      // A node counts when the master covers enough of its support that
      // its weights m_jk = M_jk / D_j stay bounded: at the master's ends,
      // a partly covered node has no counterpart (as a node-to-segment
      // node beyond an open end). See project() for the two thresholds.
      for (unsigned int j = 0; j < slave_points.size(); ++j)
        {
          NodeState &s         = state[j];
          double     tributary = 0.;
          for (const unsigned int g : faces_of_point[j])
            tributary += 0.5 * position(slave_points[faces[g][0]])
                                 .distance(position(slave_points[faces[g][1]]));
          s.coverage = chain == nullptr           ? (s.uncovered ? 0. : 1.) :
                       s.M.empty() && s.F.empty() ? 0. :
                                                    s.D.value / tributary;
          merge_entries(s.D.gradient);
          for (auto &[k, M] : s.M)
            merge_entries(M.gradient);
          for (auto &[key, F] : s.F)
            merge_entries(F.gradient);
          for (unsigned int c = 0; c < 2; ++c)
            {
              merge_entries(s.Y[c].gradient);
              merge_entries(s.moved[c].gradient);
            }
        }
    }



    void
    Mortar::add_unit_reaction(const NodeState    &s,
                              const ContactNode  &node,
                              const Tensor<1, 2> &v,
                              DofVector          &out) const
    {
      // The slave node with 1, master point k with -m_k (on a curve, each
      // force weight's dof with -F / D).
      const double D = s.D.value;
      for (unsigned int c = 0; c < 2; ++c)
        out.push_back({0, node.shares.front().dofs[c], v[c]});
      for (const auto &[k, M] : s.M)
        for (unsigned int c = 0; c < 2; ++c)
          out.push_back({1, master_points[k].dofs[c], -M.value / D * v[c]});
      for (const auto &[key, F] : s.F)
        out.push_back({1, key.first, -F.value / D * v[key.second]});
    }



    void
    Mortar::add_weight_changes(const NodeState      &s,
                               const ContactNode    &node,
                               ContactLinearization &l) const
    {
      const Tensor<1, 2> &n = s.normal, &t = s.tangent;
      const double        D = s.D.value;
      // The contact tangent at fixed r: F = lambda . (e_j - sum m_k e_k)
      // with lambda = r_t t + r_n n: the turn, d lambda = theta mu with
      // mu = r_t n - r_n t, and each weight's change, -lambda on y_k.
      const Tensor<1, 2> lambda = node.reaction[0] * t + node.reaction[1] * n;
      const Tensor<1, 2> mu     = node.reaction[0] * n - node.reaction[1] * t;
      if (!s.rotation_row.empty() && mu.norm() > 0.)
        {
          ContactLinearization::Term turn;
          add_unit_reaction(s, node, mu, turn.load);
          turn.row = s.rotation_row;
          l.tangent_terms.push_back(std::move(turn));
        }
      const auto change_of = [&](const Accumulated &weight) {
        DofVector dm;
        add_scaled(dm, 1. / D, weight.gradient);
        add_scaled(dm, -weight.value / D / D, s.D.gradient);
        return dm;
      };
      for (const auto &[k, M] : s.M)
        {
          DofVector      dm = change_of(M);
          const Point<2> yk = position(master_points[k]);
          add_scaled(l.gap_row, -(n * (yk - s.x)), dm);
          add_scaled(l.slip_row,
                     -(t * (motion(master_points[k]) - s.motion)),
                     dm);
          if (lambda.norm() > 0.)
            {
              ContactLinearization::Term change;
              for (unsigned int c = 0; c < 2; ++c)
                change.load.push_back(
                  {1, master_points[k].dofs[c], -lambda[c]});
              change.row = std::move(dm);
              l.tangent_terms.push_back(std::move(change));
            }
        }
      // On a curve, y_j's change is in the Y rows above; the force
      // weights' change at fixed reaction remains.
      if (lambda.norm() > 0.)
        for (const auto &[key, F] : s.F)
          {
            ContactLinearization::Term change;
            change.load.push_back({1, key.first, -lambda[key.second]});
            change.row = change_of(F);
            l.tangent_terms.push_back(std::move(change));
          }
    }



    bool
    Mortar::project(ContactNode &node, const bool keep_segment) const
    {
      // A node needs half its support covered to come into contact, and
      // keeps its counterpart within the increment down to a twentieth: a node
      // at the master's end whose coverage crosses one threshold from one
      // Newton iteration to the next would otherwise come and go, and
      // Newton cycle (case 2's square sliding past the rings' ends). The
      // next increment's detection drops it below half.
      const NodeState &s = state[point_of_vertex.at(node.vertex)];
      if (s.coverage <= (keep_segment && node.active ? 0.05 : 0.5))
        return false;
      // Past an open obstacle's end, only a node held there.
      if (!s.open_end.counts(keep_segment, node.active, node.segment_switches))
        return false;
      const Tensor<1, 2> &n = s.normal, &t = s.tangent;
      const double        D = s.D.value;

      // The mortar point y_j = sum m_k y_k, and the master's motion there.
      Point<2>     y;
      Tensor<1, 2> master_motion;
      for (const auto &[k, M] : s.M)
        {
          const double m = M.value / D;
          y += m * Tensor<1, 2>(position(master_points[k]));
          master_motion += m * motion(master_points[k]);
        }
      // Against an obstacle or a smooth curve: y_j = int Phi_j y / D_j,
      // and its material's motion likewise (the curve's forces go by its
      // force weights F).
      const bool curve_points = chain == nullptr || curve != nullptr;
      if (curve_points)
        for (unsigned int c = 0; c < 2; ++c)
          {
            y[c]             = s.Y[c].value / D;
            master_motion[c] = s.moved[c].value / D;
          }
      const Tensor<1, 2> x_minus_y = s.x - y;
      const Tensor<1, 2> d         = s.motion - master_motion;

      ContactLinearization l;
      l.gap  = n * x_minus_y;
      l.slip = t * d;
      // In self-contact, no deeper behind than half a face: deeper, the
      // mortar point is the wall's other side seen through the body (at a
      // fold tighter than a face the slave normals turn by a quarter turn
      // over a face, and their lines meet the facing stretch far along it),
      // as node-to-segment's self-contact refuses it (the node's
      // FacingView, set by ContactPair).
      if (node.facing && l.gap < -node.facing_view.penetration_limit)
        return false;

      add_unit_reaction(s, node, n, l.normal_force);
      add_unit_reaction(s, node, t, l.tangential_force);

      // dg = -(t . (x - y)) d theta + n . d(x - y)|_m - sum (n . y_k) dm_k,
      // du_t = (n . d) d theta + t . d(x - y)|_m - sum (t . dy_k) dm_k,
      // with dm_k = dM_k / D - m_k dD / D. As sum m_k = 1 (the integrand's
      // master shape functions sum to one), sum dm_k = 0: y_k and dy_k
      // enter relative to x_j and dx_j, which keeps the terms that cancel
      // (a flat master: n . (y_k - y_l) = 0) from leaving round-off.
      for (unsigned int c = 0; c < 2; ++c)
        {
          l.gap_row.push_back({0, node.shares.front().dofs[c], n[c]});
          l.slip_row.push_back({0, node.shares.front().dofs[c], t[c]});
        }
      // (M holds the faceted master's weights only: empty on a curve or
      // an obstacle, whose y_j's change is in the Y rows below)
      for (const auto &[k, M] : s.M)
        for (unsigned int c = 0; c < 2; ++c)
          {
            l.gap_row.push_back(
              {1, master_points[k].dofs[c], -M.value / D * n[c]});
            l.slip_row.push_back(
              {1, master_points[k].dofs[c], -M.value / D * t[c]});
          }
      add_scaled(l.gap_row, -(t * x_minus_y), s.rotation_row);
      add_scaled(l.slip_row, n * d, s.rotation_row);
      // Against an obstacle or a curve, y_j and its motion change with
      // the slave face's points (and the curve's nodes): dy_j = dY / D -
      // y_j dD / D.
      if (curve_points)
        for (unsigned int c = 0; c < 2; ++c)
          {
            add_scaled(l.gap_row, -n[c] / D, s.Y[c].gradient);
            add_scaled(l.gap_row, n[c] * y[c] / D, s.D.gradient);
            add_scaled(l.slip_row, -t[c] / D, s.moved[c].gradient);
            add_scaled(l.slip_row, t[c] * master_motion[c] / D, s.D.gradient);
          }

      add_weight_changes(s, node, l);
      merge_proportional_terms(l.tangent_terms);
      merge_entries(l.gap_row);
      merge_entries(l.slip_row);
      node.segment       = -1;
      node.s             = 0.;
      node.at_vertex     = false;
      node.normal        = n;
      node.tangent       = t;
      node.gap           = l.gap;
      node.linearization = std::move(l);
      return true;
    }
  } // namespace



  std::unique_ptr<ContactDiscretisation>
  create_nurbs_slave_mortar(const ContactDiscretisation::Context &context);

  std::unique_ptr<ContactDiscretisation>
  create_mortar(const ContactDiscretisation::Context &context)
  {
    const std::string entry = context.description.entry;
    if (const auto *composite =
          dynamic_cast<const CompositeSurface *>(&context.surface))
      throw InputError(entry + "/Master boundary",
                       "mortar contact integrates over one master curve; "
                       "the boundary '" +
                         context.description.master_boundary + "' of body '" +
                         context.description.master_body + "' has " +
                         std::to_string(composite->n_curves()) +
                         " (a body with holes?): use Discretisation = "
                         "node-to-segment, or name one curve as the master "
                         "boundary (Mesh/Boundary parts)");
    if (context.master != nullptr &&
        dynamic_cast<const CurveSurface *>(&context.surface) == nullptr)
      throw InputError(entry + "/Surface",
                       "mortar contact integrates over a master curve "
                       "(Surface = faceted, bspline, hermite or nurbs); '" +
                         context.description.surface + "' is not one");
    // A slave whose dofs are control points integrates over its own
    // boundary curve (nurbs_slave_mortar.cc).
    if (!context.slave.space().capabilities().dofs_are_nodal_values)
      return create_nurbs_slave_mortar(context);
    if (context.description.mortar_multipliers ==
        ContactDescription::MortarMultipliers::standard)
      throw InputError(entry + "/Mortar multipliers",
                       "standard multipliers are built for a NURBS slave; "
                       "mortar on the faces of body '" +
                         context.slave.name() +
                         "' is dual only (set Mortar multipliers = dual)");
    return std::make_unique<Mortar>(context);
  }
} // namespace glissade
