#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/identity_matrix.h>
#include <deal.II/lac/vector.h>

#include <glissade/base/input_error.h>
#include <glissade/body/body.h>
#include <glissade/contact/discretisation/contact_discretisation.h>
#include <glissade/contact/discretisation/mortar_curve_point.h>
#include <glissade/contact/discretisation/mortar_variables.h>
#include <glissade/contact/surfaces/curve_surface.h>
#include <glissade/contact/surfaces/master_chain.h>
#include <glissade/contact/surfaces/nurbs_boundary.h>
#include <glissade/description/scene_description.h>
#include <glissade/fe/nurbs_space.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using mortar::Accumulated;
    using mortar::add_curve_variables;
    using mortar::add_scaled;
    using mortar::DualPoint;
    using mortar::LocalVariables;
    using mortar::merge_entries;
    using mortar::MortarDual;

    /** The curve points' dual variables start here (mortar_variables.h:
     *  the slave span's p + 1 <= 4 control points and the master segment's
     *  two nodes come first). */
    constexpr unsigned int first_curve_variable = 12;
    constexpr unsigned int n_gauss_points       = 4;

    /** What NurbsSlaveMortar::update() finds for each slave point A. */
    struct PointState
    {
      /** D_A over int R_A on the whole slave curve (1: fully covered). */
      double coverage = 0.;
      /** Against an obstacle: a point of its spans had no counterpart. */
      bool uncovered = false;
      /** A point of its spans was past an open obstacle's end (integrated
       *  against the end's tangent line): it counts only if its Greville
       *  point is not past the end itself. */
      bool next_to_open_end = false;
      /** Where its Greville point stands against that end (project()). */
      mortar::OpenEndPlace open_end;
      /** int psi_A n (the point's mean normal, for its frame). */
      Tensor<1, 2> mean_normal;
      /** D_A = int R_A: the point's share of the covered slave curve. */
      Accumulated D;
      /** int psi_A n . (x - y) and int psi_A t . (motion of x - motion of
       *  y), x the slave curve, y its master point on the normal n. */
      Accumulated G, U;
      /** int psi_A R_k (n_x, n_y) by slave control point k: where a unit
       *  normal reaction goes on the slave; a tangential one by
       *  t = (n_y, -n_x). */
      std::map<unsigned int, std::array<Accumulated, 2>> S;
      /** int psi_A w (n_c, t_c) by (master dof, component c), w the master
       *  curve's force weights: where they go on the master. */
      std::map<std::pair<types::global_dof_index, unsigned int>,
               std::array<Accumulated, 2>>
        F;
    };



    /**
     * The span's functions R_m, point x and tangent dx at a dual
     * parameter s, the span's control points P: R_m(s) to first order in
     * s's dual part, which is all the derivatives need.
     */
    void
    evaluate_span(const NurbsCurve             &curve,
                  const unsigned int            segment,
                  const MortarDual             &s,
                  const std::vector<DualPoint> &P,
                  std::vector<MortarDual>      &R,
                  DualPoint                    &x,
                  DualPoint                    &dx)
    {
      thread_local std::vector<double> r, dr, d2r;
      curve.rational_functions(segment, s.value, r, dr, d2r);
      const MortarDual ds = s - s.value;
      R.resize(r.size());
      x = dx = {MortarDual(0.), MortarDual(0.)};
      for (unsigned int m = 0; m < r.size(); ++m)
        {
          R[m] = r[m] + dr[m] * ds;
          x    = x + R[m] * P[m];
          dx   = dx + (dr[m] + d2r[m] * ds) * P[m];
        }
    }



    /** What one slave span adds to each of its functions' points, as
     *  duals (PointState's integrals). */
    struct SpanIntegrals
    {
      struct OfFunction
      {
        MortarDual              D = 0., G = 0., U = 0.;
        Tensor<1, 2>            mean_normal;
        std::vector<MortarDual> S; // (function l, component)
        std::map<std::pair<types::global_dof_index, unsigned int>,
                 std::array<MortarDual, 2>>
          F;
      };
      std::vector<OfFunction> of;

      explicit SpanIntegrals(const unsigned int n_functions)
        : of(n_functions)
      {
        for (OfFunction &f : of)
          f.S.assign(2 * n_functions, MortarDual(0.));
      }

      /**
       * A Gauss point of weight w (its length in it), the span's functions
       * R there and the multiplier's psi, the slave normal n, the gap
       * n . (x - y) and the slip, and where the master takes a unit force
       * (none for an obstacle).
       */
      void
      add(const MortarDual                            &w,
          const std::vector<MortarDual>               &R,
          const std::vector<MortarDual>               &psi,
          const DualPoint                             &n,
          const MortarDual                            &gap,
          const MortarDual                            &slip,
          const std::vector<mortar::CurveForceWeight> &forces)
      {
        // (t = (n_y, -n_x))
        const MortarDual directions[4] = {n.x, n.y, n.y, -n.x};
        for (unsigned int m = 0; m < of.size(); ++m)
          {
            OfFunction      &in   = of[m];
            const MortarDual wpsi = w * psi[m];
            in.D += w * R[m];
            in.G += wpsi * gap;
            in.U += wpsi * slip;
            in.mean_normal += wpsi.value * Tensor<1, 2>({n.x.value, n.y.value});
            for (unsigned int l = 0; l < of.size(); ++l)
              {
                const MortarDual wpsiR = wpsi * R[l];
                in.S[2 * l] += wpsiR * n.x;
                in.S[2 * l + 1] += wpsiR * n.y;
              }
            for (const mortar::CurveForceWeight &f : forces)
              {
                auto &[normal, tangential] = in.F[{f.dof, f.component}];
                normal += wpsi * f.weight * directions[f.component];
                tangential += wpsi * f.weight * directions[2 + f.component];
              }
          }
      }
    };



    /**
     * Mortar contact with a NURBS slave (Discretisation = mortar on a body
     * of Element/Space = nurbs): the slave side is the body's own boundary
     * curve, the multiplier of slave point A is lambda_A psi_A, psi_A the
     * element-wise dual function of the boundary's rational function R_A
     * of control point A (dual_of_span: int psi_A R_k = delta_Ak int R_A
     * on each span, sum_A psi_A = 1). Each point's constraint is its
     * weighted gap written per unit D_A = int R_A,
     *
     *   g_A = int psi_A n . (x - y) / D_A,
     *
     * x the slave curve, n its normal there (C^(p-1): continuous), y where
     * that normal meets the master curve (against a rigid obstacle: the
     * obstacle's point closest to x, each span integrated whole), and the
     * reaction r_A = D_A lambda_A goes to slave control point k by int
     * psi_A R_k n / D_A and to the master by its curve's force weights,
     * int psi_A w n / D_A (the tangential reaction likewise with t): the
     * force is the weighted gap's work. A uniform lambda makes the
     * consistent loads of a uniform pressure on both sides, so the
     * contact patch test holds on any pair of patches, and on a curved
     * interface the force keeps the normal's turn across each function's
     * support (with a nodal normal n_A in its place the interference fit
     * converged like h^2; with the curve's own it sits at its converged
     * figure from 8 elements on). Mortar multipliers = standard takes R_A
     * in place of psi_A (De Lorenzis, Temizer, Wriggers & Zavarise 2011):
     * it also passes the patch test, but its lambda_A alternate from point
     * to point on Hertz's cylinder (by 18 % of p0: an alternating
     * multiplier's compliance is smaller by about the square of the mass
     * matrix's symbol there); it holds where the dual functions' negative
     * lobes make a point near a contact edge unstable (the NURBS ironing
     * die). Each slave span is cut where
     * the master segment's ends fall along the slave normals and
     * integrated with four Gauss points a cut, every integral
     * differentiated exactly (forward mode). doc/contact.md, "Isogeometric
     * contact", "Mortar with a NURBS slave".
     */
    class NurbsSlaveMortar : public ContactDiscretisation
    {
    public:
      explicit NurbsSlaveMortar(const Context &context);

      void
      update() override;

      bool
      project(ContactNode &node, bool keep_segment) const override;

    private:
      /** One knot span of a slave curve. */
      struct Span
      {
        unsigned int curve, segment;
      };

      /** A slave point's Greville point and its control point. */
      struct Greville
      {
        unsigned int curve, segment;
        double       s;
        unsigned int control; // numbered over all slave curves
      };

      /** The span's end points on the current slave curve. */
      std::array<Point<2>, 2>
      span_ends(const Span &span) const;

      /**
       * Master segment i faces the span and lies within `reach` of it
       * (beyond the two chords' lengths), in plain numbers.
       */
      bool
      within_reach(const Span &span, unsigned int i, double reach) const;

      /**
       * Cheap tests in plain numbers: master segment i faces the span and
       * lies within `reach`, and its ends' images along the slave
       * normals, s_c and s_d, overlap the span.
       */
      bool
      may_overlap(const Span  &span,
                  unsigned int i,
                  double       reach,
                  double      &s_c,
                  double      &s_d) const;

      /**
       * Where the slave normal through y meets span's curve: the s with
       * (x(s) - y) . x'(s) = 0, by Newton from `start`; NaN if it leaves.
       */
      double
      image(const Span &span, const Point<2> &y, double start) const;

      /**
       * The multiplier's functions on a span, psi_m = sum_l a_ml R_l
       * (dual_of_span): biorthogonal to the span's R_l.
       */
      void
      multiplier_functions(unsigned int                   span,
                           const std::vector<MortarDual> &R,
                           std::vector<MortarDual>       &psi) const;

      /** Adds the integrals of the span over master segment i, if it
       *  lies within `reach` (may_overlap()). */
      void
      integrate(unsigned int span, unsigned int i, double reach);

      /**
       * The spans to integrate against the master: those within the alert
       * distance of a master segment, and with them every span of the
       * points they carry, so that each point's weighted gap is an
       * integral over its whole function (a dual function's lobes make a
       * part of it meaningless: cut at the alert distance, a p = 3 point
       * read gaps of 0.044 and 0.005 where the curve was 0.020 away, and
       * its compliance turned negative). Each with the reach its segments
       * are searched within (negative: not integrated); `carried` marks
       * the points within the alert distance, the others' integrals
       * being cut.
       */
      std::vector<double>
      reach_of_spans(std::vector<bool> &carried) const;

      /** Adds the integrals of the span against a rigid obstacle. */
      void
      integrate_on_obstacle(unsigned int span);

      /** The span's control points as the first dual variables; their
       *  indices over all slave curves. */
      std::vector<unsigned int>
      add_span_variables(const Span &span, LocalVariables &variables) const;

      /** The slave's motion since the increment began at a point of the
       *  span, sum_k R_k (u_k - u0_k), changing with the control points. */
      std::array<MortarDual, 2>
      slave_motion(const std::vector<MortarDual>   &R,
                   const std::vector<unsigned int> &controls,
                   const LocalVariables            &variables) const;

      /** The span's integrals added to its points' states; the curve
       *  points' variables by their kinematics (none on an obstacle). */
      void
      add_to_points(const std::vector<unsigned int>               &controls,
                    const SpanIntegrals                           &integrals,
                    const LocalVariables                          &variables,
                    const std::vector<std::vector<SurfaceWeight>> &kinematics);

      /** The dof forces of a unit reaction at point A (state s):
       *  `direction` 0 normal, 1 tangential. */
      void
      add_unit_reaction(const PointState &s,
                        unsigned int      direction,
                        DofVector        &out) const;

      const Body          &slave;
      const MasterSurface &surface;
      /** nullptr for a rigid obstacle (no master body, curve or chain). */
      const Body         *master;
      const CurveSurface *curve_surface;
      const MasterChain  *chain;
      const double        search_distance;

      std::vector<NurbsBoundary> slave_curves;
      /** The first control point of each slave curve in the numbering
       *  over all of them. */
      std::vector<unsigned int>                           first_control;
      std::vector<std::array<types::global_dof_index, 2>> control_dofs;
      std::vector<Span>                                   spans;
      /**
       * For each span, a = D M^-1 (row m, column l: a_ml), with M_ml = int
       * R_m R_l and D = diag(int R_m) over the span in the reference
       * configuration: the element-wise dual basis psi_m = sum_l a_ml R_l,
       * int psi_m R_l = delta_ml int R_m on the span (Seitz, Farah,
       * Kremheller, Wohlmuth, Wall & Popp 2016); the identity for Mortar
       * multipliers = standard.
       */
      std::vector<FullMatrix<double>> dual_of_span;
      std::vector<Greville>           greville_of_point;
      std::vector<unsigned int>       point_of_control;
      /** The slave points by their reference place (project() gets copies
       *  of the pair's nodes too). */
      std::map<std::pair<double, double>, unsigned int> point_of_place;
      std::vector<SlaveShares>                          master_node_shares;

      std::vector<PointState> state;
      /** The current slave control points, their motion since the
       *  increment began, the current master nodes, and int R_A over each
       *  slave curve. */
      std::vector<Point<2>>     control_positions;
      std::vector<Tensor<1, 2>> control_motions;
      std::vector<Point<2>>     master_positions;
      std::vector<double>       function_integrals;
    };



    NurbsSlaveMortar::NurbsSlaveMortar(const Context &context)
      : slave(context.slave)
      , surface(context.surface)
      , master(context.master)
      , curve_surface(context.master ?
                        &dynamic_cast<const CurveSurface &>(context.surface) :
                        nullptr)
      , chain(curve_surface ? &curve_surface->master_chain() : nullptr)
      , search_distance(context.description.alert_distance)
    {
      const auto &space = dynamic_cast<const NurbsSpace &>(slave.space());
      const std::string &entry = context.description.entry;
      for (const MasterChain &slave_chain :
           MasterChain::build_all(slave,
                                  context.description.slave_boundary,
                                  entry + "/Slave boundary"))
        {
          NurbsBoundary boundary   = NurbsBoundary::build(space, slave_chain);
          const unsigned int curve = slave_curves.size();
          const unsigned int first = control_dofs.size();
          first_control.push_back(first);
          control_dofs.insert(control_dofs.end(),
                              boundary.control_dofs.begin(),
                              boundary.control_dofs.end());
          for (unsigned int i = 0; i < boundary.curve->n_segments(); ++i)
            spans.push_back({curve, i});
          // The pair's points are these curves' Greville points, in this
          // order (append_nurbs_slave_points).
          for (const auto &g : boundary.curve->greville_points())
            greville_of_point.push_back(
              {curve, g.segment, g.s, first + g.control});
          slave_curves.push_back(std::move(boundary));
        }
      AssertThrow(greville_of_point.size() == context.nodes.size(),
                  ExcMessage("a slave point per control point"));
      const bool standard = context.description.mortar_multipliers ==
                            ContactDescription::MortarMultipliers::standard;
      for (const Span &span : spans)
        {
          // (the curves are in the reference configuration until update())
          const NurbsCurve  &curve = *slave_curves[span.curve].curve;
          const unsigned int n     = curve.degree_of_curve() + 1;
          // (Mortar multipliers = standard: psi_m = R_m)
          FullMatrix<double> a{IdentityMatrix(n)};
          if (!standard)
            {
              const QGauss<1>     rule(n + 2);
              std::vector<double> D(n, 0.), r, dr, d2r;
              a = 0.;
              for (unsigned int q = 0; q < rule.size(); ++q)
                {
                  const auto dx =
                    curve.derivative(span.segment, rule.point(q)[0]);
                  const double dA = std::hypot(dx[0], dx[1]) * rule.weight(q);
                  curve.rational_functions(
                    span.segment, rule.point(q)[0], r, dr, d2r);
                  for (unsigned int m = 0; m < n; ++m)
                    {
                      D[m] += r[m] * dA;
                      for (unsigned int l = 0; l < n; ++l)
                        a(m, l) += r[m] * r[l] * dA;
                    }
                }
              a.gauss_jordan();
              for (unsigned int m = 0; m < n; ++m)
                for (unsigned int l = 0; l < n; ++l)
                  a(m, l) *= D[m];
            }
          dual_of_span.push_back(std::move(a));
        }
      point_of_control.resize(control_dofs.size());
      for (unsigned int j = 0; j < context.nodes.size(); ++j)
        {
          const Point<2> &X            = context.nodes[j].reference_position;
          point_of_place[{X[0], X[1]}] = j;
          point_of_control[greville_of_point[j].control] = j;
        }
      for (unsigned int k = 0; chain && k < chain->vertices.size(); ++k)
        master_node_shares.push_back(curve_surface->node_shares(k));
      state.resize(context.nodes.size());
    }



    double
    NurbsSlaveMortar::image(const Span     &span,
                            const Point<2> &y,
                            const double    start) const
    {
      const NurbsCurve  &curve = *slave_curves[span.curve].curve;
      double             s     = start;
      MasterCurve::Point x{}, dx{}, ddx{};
      for (unsigned int it = 0; it < 30; ++it)
        {
          curve.evaluate(span.segment, s, x, dx, ddx);
          const double rx = x[0] - y[0], ry = x[1] - y[1];
          const double F = rx * dx[0] + ry * dx[1];
          const double dF =
            dx[0] * dx[0] + dx[1] * dx[1] + rx * ddx[0] + ry * ddx[1];
          const double step = F / dF;
          s -= step;
          if (!std::isfinite(s) || std::abs(s) > 10.)
            return std::numeric_limits<double>::quiet_NaN();
          if (std::abs(step) < 1e-15)
            break;
        }
      return s;
    }



    std::array<Point<2>, 2>
    NurbsSlaveMortar::span_ends(const Span &span) const
    {
      const NurbsCurve &curve = *slave_curves[span.curve].curve;
      const auto        a     = curve.value(span.segment, 0.),
                 b            = curve.value(span.segment, 1.);
      return {{Point<2>(a[0], a[1]), Point<2>(b[0], b[1])}};
    }



    bool
    NurbsSlaveMortar::within_reach(const Span        &span,
                                   const unsigned int i,
                                   const double       reach) const
    {
      const auto [xa, xb] = span_ends(span);
      const Point<2> &yc  = master_positions[i],
                     &yd  = master_positions[(i + 1) % master_positions.size()];
      // The chains have their bodies on the right: the left normals of
      // the chords point out of each, and face each other.
      const Tensor<1, 2> slave_out({-(xb - xa)[1], (xb - xa)[0]});
      const Tensor<1, 2> master_out({-(yd - yc)[1], (yd - yc)[0]});
      return slave_out * master_out < 0. &&
             (0.5 * (xa + xb)).distance(0.5 * (yc + yd)) <=
               reach + (xb - xa).norm() + (yd - yc).norm();
    }



    bool
    NurbsSlaveMortar::may_overlap(const Span        &span,
                                  const unsigned int i,
                                  const double       reach,
                                  double            &s_c,
                                  double            &s_d) const
    {
      if (!within_reach(span, i, reach))
        return false;
      const auto [xa, xb] = span_ends(span);
      const Point<2> &yc  = master_positions[i],
                     &yd  = master_positions[(i + 1) % master_positions.size()];
      const auto chord_estimate = [&](const Point<2> &y) {
        return (y - xa) * (xb - xa) / (xb - xa).norm_square();
      };
      s_c = image(span, yc, chord_estimate(yc));
      s_d = image(span, yd, chord_estimate(yd));
      return std::isfinite(s_c) && std::isfinite(s_d) &&
             std::min(1., std::max(s_c, s_d)) -
                 std::max(0., std::min(s_c, s_d)) >
               1e-12;
    }



    void
    NurbsSlaveMortar::multiplier_functions(const unsigned int             span,
                                           const std::vector<MortarDual> &R,
                                           std::vector<MortarDual> &psi) const
    {
      const FullMatrix<double> &a = dual_of_span[span];
      psi.assign(R.size(), MortarDual(0.));
      for (unsigned int m = 0; m < R.size(); ++m)
        for (unsigned int l = 0; l < R.size(); ++l)
          psi[m] += a(m, l) * R[l];
    }



    std::vector<unsigned int>
    NurbsSlaveMortar::add_span_variables(const Span     &span,
                                         LocalVariables &variables) const
    {
      std::vector<unsigned int> controls;
      for (const unsigned int m :
           slave_curves[span.curve].curve->segment_data(span.segment).controls)
        {
          const unsigned int k = first_control[span.curve] + m;
          controls.push_back(k);
          variables.add(0, {{control_dofs[k], 1.}}, control_positions[k]);
        }
      return controls;
    }



    std::array<MortarDual, 2>
    NurbsSlaveMortar::slave_motion(const std::vector<MortarDual>   &R,
                                   const std::vector<unsigned int> &controls,
                                   const LocalVariables &variables) const
    {
      std::array<MortarDual, 2> moved = {{0., 0.}};
      for (unsigned int m = 0; m < controls.size(); ++m)
        for (unsigned int k = 0; k < 2; ++k)
          {
            const MortarDual &P =
              k == 0 ? variables.coordinates[m].x : variables.coordinates[m].y;
            moved[k] +=
              R[m] * (control_motions[controls[m]][k] + (P - P.value));
          }
      return moved;
    }



    void
    NurbsSlaveMortar::add_to_points(
      const std::vector<unsigned int>               &controls,
      const SpanIntegrals                           &integrals,
      const LocalVariables                          &variables,
      const std::vector<std::vector<SurfaceWeight>> &kinematics)
    {
      const unsigned int n_used = variables.n_used();
      const auto         add    = [&](Accumulated &to, const MortarDual &v) {
        to.add(v, variables.dofs, n_used);
        add_curve_variables(v, kinematics, first_curve_variable, to);
      };
      for (unsigned int m = 0; m < controls.size(); ++m)
        {
          PointState &to = state[point_of_control[controls[m]]];
          const SpanIntegrals::OfFunction &in = integrals.of[m];
          add(to.D, in.D);
          add(to.G, in.G);
          add(to.U, in.U);
          to.mean_normal += in.mean_normal;
          for (unsigned int l = 0; l < controls.size(); ++l)
            for (unsigned int e = 0; e < 2; ++e)
              add(to.S[controls[l]][e], in.S[2 * l + e]);
          for (const auto &[key, weights] : in.F)
            for (unsigned int e = 0; e < 2; ++e)
              add(to.F[key][e], weights[e]);
        }
    }



    void
    NurbsSlaveMortar::integrate(const unsigned int span_index,
                                const unsigned int i,
                                const double       reach)
    {
      const Span        &span  = spans[span_index];
      const NurbsCurve  &curve = *slave_curves[span.curve].curve;
      const unsigned int c = i, d = (i + 1) % master_positions.size();
      double             s_c = 0., s_d = 0.;
      if (!may_overlap(span, i, reach, s_c, s_d))
        return;

      // The local variables: the span's control points, then the master
      // segment's end nodes; the curve points' from first_curve_variable.
      LocalVariables                  variables;
      const std::vector<unsigned int> controls =
        add_span_variables(span, variables);
      const unsigned int n_functions = controls.size();
      const unsigned int lc =
        variables.add(1, master_node_shares[c], master_positions[c]);
      const unsigned int ld =
        variables.add(1, master_node_shares[d], master_positions[d]);
      const DualPoint              Yc = variables.coordinates[lc];
      const DualPoint              Yd = variables.coordinates[ld];
      const std::vector<DualPoint> P(variables.coordinates.begin(),
                                     variables.coordinates.begin() +
                                       n_functions);

      // A master end's image: one Newton step on the duals from the plain
      // root s of (x(s) - y) . x'(s) = 0.
      std::vector<double> r, dr, d2r;
      const auto          cut = [&](const DualPoint &y, const double s) {
        curve.rational_functions(span.segment, s, r, dr, d2r);
        DualPoint x{MortarDual(0.), MortarDual(0.)}, dx = x, ddx = x;
        for (unsigned int m = 0; m < n_functions; ++m)
          {
            x   = x + MortarDual(r[m]) * P[m];
            dx  = dx + MortarDual(dr[m]) * P[m];
            ddx = ddx + MortarDual(d2r[m]) * P[m];
          }
        const DualPoint  to = x - y;
        const MortarDual F  = to.x * dx.x + to.y * dx.y;
        const MortarDual dF =
          dx.x * dx.x + dx.y * dx.y + to.x * ddx.x + to.y * ddx.y;
        return s - F / dF;
      };
      const MortarDual  sc = cut(Yc, s_c), sd = cut(Yd, s_d);
      const MortarDual &first = sd.value < sc.value ? sd : sc;
      const MortarDual &last  = sd.value < sc.value ? sc : sd;
      const MortarDual  lower = first.value > 0. ? first : MortarDual(0.);
      const MortarDual  upper = last.value < 1. ? last : MortarDual(1.);

      SpanIntegrals                           integrals(n_functions);
      std::vector<std::vector<SurfaceWeight>> kinematics(n_gauss_points);
      std::vector<MortarDual>                 R, psi;
      // Gauss-Legendre, four points a cut: exact for the flat patch
      // (R_A R_k of degree 2p <= 6 on straight spans of uniform speed).
      static const QGauss<1> gauss(n_gauss_points);
      for (unsigned int q = 0; q < n_gauss_points; ++q)
        {
          const MortarDual s = lower + gauss.point(q)[0] * (upper - lower);
          DualPoint        x, dx;
          evaluate_span(curve, span.segment, s, P, R, x, dx);
          multiplier_functions(span_index, R, psi);
          const MortarDual speed = sqrt(dx.x * dx.x + dx.y * dx.y);
          const MortarDual w     = gauss.weight(q) * (upper - lower) * speed;
          // The slave normal, from the master into the slave (as a master
          // surface's normal points): minus the chain's left normal.
          const DualPoint n{dx.y / speed, -dx.x / speed};
          const double    eta_estimate =
            (mortar::cross(x - Yc, n) / mortar::cross(Yd - Yc, n)).value;
          mortar::CurvePoint point;
          if (!mortar::find_curve_point(*curve_surface,
                                        *master,
                                        i,
                                        first_curve_variable + 2 * q,
                                        x,
                                        n,
                                        eta_estimate,
                                        {{Yc, Yd}},
                                        {{chain->value_dofs[c],
                                          chain->value_dofs[d]}},
                                        point))
            return; // (the normal runs along the master: nothing added)
          kinematics[q]          = std::move(point.kinematics);
          const auto       moved = slave_motion(R, controls, variables);
          const MortarDual gap =
            n.x * (x.x - point.y[0]) + n.y * (x.y - point.y[1]);
          const MortarDual slip = n.y * (moved[0] - point.motion[0]) -
                                  n.x * (moved[1] - point.motion[1]);
          integrals.add(w, R, psi, n, gap, slip, point.forces);
        }
      add_to_points(controls, integrals, variables, kinematics);
    }



    void
    NurbsSlaveMortar::integrate_on_obstacle(const unsigned int span_index)
    {
      const Span                     &span  = spans[span_index];
      const NurbsCurve               &curve = *slave_curves[span.curve].curve;
      LocalVariables                  variables;
      const std::vector<unsigned int> controls =
        add_span_variables(span, variables);
      const std::vector<DualPoint> &P = variables.coordinates;

      // Six Gauss points over the whole span: the obstacle's points are
      // not polynomial in s (a point not facing the obstacle uncovers the
      // span's points: they have no counterpart).
      static const QGauss<1>  gauss(6);
      SpanIntegrals           integrals(controls.size());
      std::vector<MortarDual> R, psi;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          DualPoint x, dx;
          evaluate_span(
            curve, span.segment, MortarDual(gauss.point(q)[0]), P, R, x, dx);
          multiplier_functions(span_index, R, psi);
          const MortarDual   speed = sqrt(dx.x * dx.x + dx.y * dx.y);
          const MortarDual   w     = gauss.weight(q) * speed;
          const DualPoint    n{dx.y / speed, -dx.x / speed};
          const SurfacePoint point =
            surface.project(Point<2>(x.x.value, x.y.value));
          if (point.beyond_open_end)
            for (const unsigned int k : controls)
              state[point_of_control[k]].next_to_open_end = true;
          else if (!point.valid)
            {
              for (const unsigned int k : controls)
                state[point_of_control[k]].uncovered = true;
              return;
            }
          // The closest point (or past an open end, the point on the end's
          // tangent line) and its material's motion, moving with x.
          const mortar::CurvePoint on_obstacle =
            mortar::obstacle_point(point, x);
          const auto      &y      = on_obstacle.y;
          const auto      &motion = on_obstacle.motion;
          const auto       moved  = slave_motion(R, controls, variables);
          const MortarDual gap    = n.x * (x.x - y[0]) + n.y * (x.y - y[1]);
          const MortarDual slip =
            n.y * (moved[0] - motion[0]) - n.x * (moved[1] - motion[1]);
          integrals.add(w, R, psi, n, gap, slip, {});
        }
      add_to_points(controls, integrals, variables, {});
    }



    std::vector<double>
    NurbsSlaveMortar::reach_of_spans(std::vector<bool> &carried) const
    {
      const unsigned int n_segments =
        master_positions.size() - (chain->closed ? 0 : 1);
      std::vector<double> reach(spans.size(), -1.), chord(spans.size());
      carried.assign(control_dofs.size(), false);
      for (unsigned int f = 0; f < spans.size(); ++f)
        {
          const NurbsCurve &curve = *slave_curves[spans[f].curve].curve;
          const auto [a, b]       = span_ends(spans[f]);
          chord[f]                = a.distance(b);
          for (unsigned int i = 0; i < n_segments && reach[f] < 0.; ++i)
            if (within_reach(spans[f], i, search_distance))
              reach[f] = search_distance;
          if (reach[f] >= 0.)
            for (const unsigned int m :
                 curve.segment_data(spans[f].segment).controls)
              carried[first_control[spans[f].curve] + m] = true;
        }
      // Those spans and the other spans of their points are integrated
      // whole: against every master segment that their points' normals
      // meet, searched within the alert distance and the chords of the p
      // spans on either side (a support's length; the spans of a curve are
      // consecutive). (A segment cut at the alert distance alone left a
      // span that reached it half integrated.)
      for (unsigned int f = 0; f < spans.size(); ++f)
        {
          const NurbsCurve &curve  = *slave_curves[spans[f].curve].curve;
          bool              needed = false;
          for (const unsigned int m :
               curve.segment_data(spans[f].segment).controls)
            needed = needed || carried[first_control[spans[f].curve] + m];
          if (!needed)
            continue;
          const int p = curve.degree_of_curve();
          reach[f]    = search_distance;
          for (int g = std::max(0, int(f) - p);
               g <= std::min(int(spans.size()) - 1, int(f) + p);
               ++g)
            if (spans[g].curve == spans[f].curve)
              reach[f] += chord[g];
        }
      return reach;
    }



    void
    NurbsSlaveMortar::update()
    {
      const Vector<double> &u  = slave.displacement();
      const Vector<double> &u0 = slave.stored_displacement();
      control_positions.resize(control_dofs.size());
      control_motions.resize(control_dofs.size());
      for (unsigned int c = 0; c < slave_curves.size(); ++c)
        {
          NurbsBoundary                  &boundary = slave_curves[c];
          std::vector<MasterCurve::Point> current;
          for (unsigned int m = 0; m < boundary.control_points.size(); ++m)
            {
              const unsigned int k = first_control[c] + m;
              for (unsigned int e = 0; e < 2; ++e)
                {
                  control_positions[k][e] =
                    boundary.control_points[m][e] + u(control_dofs[k][e]);
                  control_motions[k][e] =
                    u(control_dofs[k][e]) - u0(control_dofs[k][e]);
                }
              current.push_back(
                {{control_positions[k][0], control_positions[k][1]}});
            }
          boundary.curve->update(current);
        }
      master_positions.resize(master_node_shares.size());
      for (unsigned int k = 0; k < master_node_shares.size(); ++k)
        {
          master_positions[k] = chain->reference_points[k];
          for (const SlaveShare &share : master_node_shares[k])
            for (unsigned int e = 0; e < 2; ++e)
              master_positions[k][e] +=
                share.weight * master->displacement()(share.dofs[e]);
        }

      // int R_A over each whole slave curve: what covers a point fully.
      function_integrals.assign(control_dofs.size(), 0.);
      for (const Span &span : spans)
        {
          const NurbsCurve   &curve = *slave_curves[span.curve].curve;
          const QGauss<1>     rule(curve.degree_of_curve() + 3);
          std::vector<double> r, dr, d2r;
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              const auto dx = curve.derivative(span.segment, rule.point(q)[0]);
              curve.rational_functions(
                span.segment, rule.point(q)[0], r, dr, d2r);
              const auto &local = curve.segment_data(span.segment).controls;
              for (unsigned int m = 0; m < local.size(); ++m)
                function_integrals[first_control[span.curve] + local[m]] +=
                  r[m] * std::hypot(dx[0], dx[1]) * rule.weight(q);
            }
        }

      for (PointState &s : state)
        s = PointState();
      std::vector<bool> carried(control_dofs.size(), true);
      if (chain == nullptr)
        {
          for (unsigned int f = 0; f < spans.size(); ++f)
            integrate_on_obstacle(f);
          // Next to an open obstacle's end, a point counts as a
          // node-to-segment node does: if its Greville point is not past
          // the end.
          for (unsigned int j = 0; j < state.size(); ++j)
            if (state[j].next_to_open_end && !state[j].uncovered)
              {
                const Greville    &g = greville_of_point[j];
                MasterCurve::Point c0{}, c1{}, c2{};
                slave_curves[g.curve].curve->evaluate(
                  g.segment, g.s, c0, c1, c2);
                state[j].open_end =
                  mortar::open_end_place(surface, Point<2>(c0[0], c0[1]));
              }
        }
      else
        {
          const std::vector<double> reach = reach_of_spans(carried);
          for (unsigned int f = 0; f < spans.size(); ++f)
            if (reach[f] >= 0.)
              for (unsigned int i = 0;
                   i + (chain->closed ? 0 : 1) < master_positions.size();
                   ++i)
                integrate(f, i, reach[f]);
        }

      for (unsigned int j = 0; j < state.size(); ++j)
        {
          PointState &s = state[j];
          // (against an obstacle every span is integrated whole: the
          // point is covered unless a point of its spans had no
          // counterpart)
          s.coverage =
            chain == nullptr ?
              (s.uncovered ? 0. : 1.) :
            s.F.empty() || !carried[greville_of_point[j].control] ?
              0. :
              s.D.value / function_integrals[greville_of_point[j].control];
          for (Accumulated *a : {&s.D, &s.G, &s.U})
            merge_entries(a->gradient);
          for (auto &[k, S] : s.S)
            for (Accumulated &a : S)
              merge_entries(a.gradient);
          for (auto &[key, F] : s.F)
            for (Accumulated &a : F)
              merge_entries(a.gradient);
        }
    }



    void
    NurbsSlaveMortar::add_unit_reaction(const PointState  &s,
                                        const unsigned int direction,
                                        DofVector         &out) const
    {
      // The slave's control point k with int psi_A R_k n / D_A (or t), the
      // master's dofs with minus int psi_A w n / D_A.
      const double D = s.D.value;
      // (t = (n_y, -n_x))
      for (const auto &[k, S] : s.S)
        for (unsigned int c = 0; c < 2; ++c)
          out.push_back({0,
                         control_dofs[k][c],
                         (direction == 0 ? S[c].value :
                          c == 0         ? S[1].value :
                                           -S[0].value) /
                           D});
      for (const auto &[key, F] : s.F)
        out.push_back({1, key.first, -F[direction].value / D});
    }



    bool
    NurbsSlaveMortar::project(ContactNode &node, const bool keep_segment) const
    {
      const auto at = point_of_place.find(
        {node.reference_position[0], node.reference_position[1]});
      if (at == point_of_place.end())
        return false;
      // Half the point's function covered to come into contact, a
      // twentieth to keep its counterpart within the increment (as for Q1
      // slaves, mortar.cc).
      const PointState &s = state[at->second];
      if (s.coverage <= (keep_segment && node.active ? 0.05 : 0.5))
        return false;
      // (past an open obstacle's end: only a point held there)
      if (!s.open_end.counts(keep_segment, node.active, node.segment_switches))
        return false;
      const double D = s.D.value;

      ContactLinearization l;
      l.gap  = s.G.value / D;
      l.slip = s.U.value / D;
      add_unit_reaction(s, 0, l.normal_force);
      add_unit_reaction(s, 1, l.tangential_force);
      // d(G / D) = dG / D - g dD / D, and the slip likewise.
      add_scaled(l.gap_row, 1. / D, s.G.gradient);
      add_scaled(l.gap_row, -l.gap / D, s.D.gradient);
      add_scaled(l.slip_row, 1. / D, s.U.gradient);
      add_scaled(l.slip_row, -l.slip / D, s.D.gradient);

      // The contact tangent at fixed reaction (r_t, r_n): each force
      // entry r_n N / D + r_t T / D changes with its integrals and D.
      const double r_t = node.reaction[0], r_n = node.reaction[1];
      // (tangential_sign: the slave's t_y = -n_x)
      const auto change_of = [&](const Accumulated &normal,
                                 const Accumulated &tangential,
                                 const double       tangential_sign = 1.) {
        const double t = tangential_sign * r_t;
        DofVector    dw;
        add_scaled(dw, r_n / D, normal.gradient);
        add_scaled(dw, t / D, tangential.gradient);
        add_scaled(dw,
                   -(r_n * normal.value + t * tangential.value) / D / D,
                   s.D.gradient);
        return dw;
      };
      if (r_n != 0. || r_t != 0.)
        {
          for (const auto &[k, S] : s.S)
            {
              l.tangent_terms.push_back(
                {{{0, control_dofs[k][0], 1.}}, change_of(S[0], S[1])});
              l.tangent_terms.push_back(
                {{{0, control_dofs[k][1], 1.}}, change_of(S[1], S[0], -1.)});
            }
          for (const auto &[key, F] : s.F)
            l.tangent_terms.push_back(
              {{{1, key.first, -1.}}, change_of(F[0], F[1])});
        }
      // (each term's load is one dof: the contact problem sums them over
      // the nodes, ContactProblem::active_nodes)
      merge_entries(l.gap_row);
      merge_entries(l.slip_row);
      // The point's frame: its mean normal int psi_A n / D_A, whose length
      // (1 where the curve is straight) is what a unit reaction's forces
      // sum to.
      const Tensor<1, 2> n  = s.mean_normal / s.mean_normal.norm();
      node.resultant_factor = s.mean_normal.norm() / D;
      node.segment          = -1;
      node.s                = 0.;
      node.at_vertex        = false;
      node.normal           = n;
      node.tangent          = Tensor<1, 2>({n[1], -n[0]});
      node.gap              = l.gap;
      node.linearization    = std::move(l);
      return true;
    }
  } // namespace



  std::unique_ptr<ContactDiscretisation>
  create_nurbs_slave_mortar(const ContactDiscretisation::Context &context)
  {
    const std::string &entry = context.description.entry;
    const auto &space = dynamic_cast<const NurbsSpace &>(context.slave.space());
    // The slave span's p + 1 control points and the master segment's two
    // nodes take the first twelve dual variables (mortar_variables.h).
    if (space.polynomial_degree() > 3)
      throw InputError(entry + "/Discretisation",
                       "mortar contact with a NURBS slave is built for "
                       "degrees 2 and 3; body '" +
                         context.slave.name() + "' has Element/Degree = " +
                         std::to_string(space.polynomial_degree()) +
                         ": use node-to-segment");
    return std::make_unique<NurbsSlaveMortar>(context);
  }
} // namespace glissade
