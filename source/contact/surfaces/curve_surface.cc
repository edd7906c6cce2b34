#include <glissade/body/body.h>
#include <glissade/contact/surfaces/curve_surface.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  CurveSurface::CurveSurface(const Body        &master,
                             const std::string &boundary,
                             const std::string &entry,
                             const unsigned int curve)
    : master(master)
    , chain(MasterChain::build(master, boundary, entry, curve))
  {}



  void
  CurveSurface::update(const double, const double)
  {
    const Vector<double>           &u = master.displacement();
    std::vector<MasterCurve::Point> positions(chain.vertices.size());
    for (unsigned int j = 0; j < positions.size(); ++j)
      for (unsigned int c = 0; c < 2; ++c)
        positions[j][c] =
          chain.reference_points[j][c] + u(chain.value_dofs[j][c]);
    rebuild(positions);
  }



  void
  CurveSurface::rebuild(const std::vector<MasterCurve::Point> &positions)
  {
    curve->update(positions);
  }



  void
  CurveSurface::add_kinematics(const unsigned int,
                               const double,
                               std::vector<SurfaceWeight> &) const
  {}



  void
  CurveSurface::set_forces(SurfacePoint &point) const
  {
    point.forces = point.kinematics;
  }



  std::vector<types::global_dof_index>
  CurveSurface::dofs() const
  {
    std::vector<types::global_dof_index> result;
    for (const auto &d : chain.value_dofs)
      result.insert(result.end(), d.begin(), d.end());
    return result;
  }



  double
  CurveSurface::end_of_extension(const unsigned int segment,
                                 const double       s) const
  {
    if (curve->is_closed())
      return -1.;
    if (segment == curve->n_segments() - 1 && s > 1.)
      return 1.;
    if (segment == 0 && s < 0.)
      return 0.;
    return -1.;
  }



  void
  CurveSurface::evaluate(const unsigned int  segment,
                         const double        s,
                         MasterCurve::Point &c,
                         MasterCurve::Point &dc,
                         MasterCurve::Point &ddc) const
  {
    // Past an open end, the tangent line at the end: the curve continued
    // with its slope (C1), whatever the polynomial would do there.
    const double end = end_of_extension(segment, s);
    if (end < 0.)
      {
        curve->evaluate(segment, s, c, dc, ddc);
        return;
      }
    curve->evaluate(segment, end, c, dc, ddc);
    for (unsigned int d = 0; d < 2; ++d)
      {
        c[d] += (s - end) * dc[d];
        ddc[d] = 0.;
      }
  }



  bool
  CurveSurface::project_on_segment(const Point<2>    &x,
                                   const unsigned int segment,
                                   double            &s,
                                   const double       margin) const
  {
    // Newton on f(s) = (c(s) - x) . c'(s), started from the last s.
    for (unsigned int it = 0; it < 30; ++it)
      {
        MasterCurve::Point c, dc, ddc;
        evaluate(segment, s, c, dc, ddc);
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



  SurfacePoint
  CurveSurface::point_at(const Point<2>    &x,
                         const unsigned int segment,
                         const double       s) const
  {
    SurfacePoint point;
    point.valid   = true;
    point.segment = segment;
    point.s       = s;
    MasterCurve::Point c, dc, ddc;
    evaluate(segment, s, c, dc, ddc);
    const double end        = end_of_extension(segment, s);
    const auto   t          = curve->unit_tangent(segment, end < 0. ? s : end);
    point.point             = Point<2>(c[0], c[1]);
    point.first_derivative  = Tensor<1, 2>({dc[0], dc[1]});
    point.second_derivative = Tensor<1, 2>({ddc[0], ddc[1]});
    point.tangent           = Tensor<1, 2>({t[0], t[1]});
    point.normal            = Tensor<1, 2>({-t[1], t[0]});
    point.gap               = (x - point.point) * point.normal;

    // The weights, continued linearly past an open end like the curve.
    const double s_weights = end < 0. ? s : end;
    point.kinematics       = kinematics_at(segment, s_weights);
    for (auto &w : point.kinematics)
      w.value += (s - s_weights) * w.derivative;
    set_forces(point);
    return point;
  }



  std::vector<SurfaceWeight>
  CurveSurface::kinematics_at(const unsigned int segment, const double s) const
  {
    std::vector<SurfaceWeight>             kinematics;
    MasterCurve::NodeWeightsAndDerivatives weights;
    curve->weights_and_derivatives(segment, s, weights);
    for (const auto &w : weights)
      for (unsigned int comp = 0; comp < 2; ++comp)
        kinematics.push_back(
          {curve_data_dofs(w.node)[comp], comp, w.value, w.derivative});
    add_kinematics(segment, s, kinematics);
    return kinematics;
  }



  std::vector<SurfaceWeight>
  CurveSurface::forces_at(const unsigned int                segment,
                          const double                      s,
                          const std::vector<SurfaceWeight> &kinematics) const
  {
    SurfacePoint point;
    point.valid      = true;
    point.segment    = segment;
    point.s          = s;
    point.kinematics = kinematics;
    set_forces(point);
    return point.forces;
  }



  void
  CurveSurface::set_vertex_rotation(SurfacePoint &point) const
  {
    // The normal bisects the corner, so it turns by the mean of the turns
    // of the two segments' normals at the node: theta_i = n_i . delta c'_i
    // / |c'_i| with delta c'_i = sum_j phi_j' delta u_j at the node's end,
    // over every dof the curve's point moves with (kinematics_at: a
    // Hermite edge's tangent at its node is its tangent dofs alone, the
    // position weights' derivatives vanishing there).
    const unsigned int outgoing = point.segment;
    const unsigned int incoming =
      outgoing == 0 ? curve->n_segments() - 1 : outgoing - 1;
    point.vertex_rotation.clear();
    for (const auto &[segment, s] :
         {std::pair<unsigned int, double>{incoming, 1.}, {outgoing, 0.}})
      {
        const MasterCurve::Point dc     = curve->derivative(segment, s);
        const double             length = std::hypot(dc[0], dc[1]);
        if (!(length > 0.))
          continue;
        const Tensor<1, 2> n({-dc[1] / length, dc[0] / length});
        for (const SurfaceWeight &w : kinematics_at(segment, s))
          point.vertex_rotation.push_back(
            {w.dof,
             w.component,
             0.5 * w.derivative * n[w.component] / length,
             0.});
      }
  }



  SurfacePoint
  CurveSurface::corner_point(const Point<2>    &x,
                             const unsigned int segment) const
  {
    SurfacePoint point = point_at(x, segment, 0.);
    if (segment == 0 && !curve->is_closed())
      return point;
    const unsigned int incoming =
      segment == 0 ? curve->n_segments() - 1 : segment - 1;
    const auto   t_in  = curve->unit_tangent(incoming, 1.);
    const auto   t_out = curve->unit_tangent(segment, 0.);
    Tensor<1, 2> t({t_in[0] + t_out[0], t_in[1] + t_out[1]});
    // Two segments folded back on each other have no mean direction: keep
    // the outgoing one's.
    if (!(t.norm() > 1e-12))
      return point;
    t /= t.norm();
    point.on_vertex = true;
    point.tangent   = t;
    point.normal    = Tensor<1, 2>({-t[1], t[0]});
    point.gap       = (x - point.point) * point.normal;
    set_vertex_rotation(point);
    return point;
  }



  bool
  CurveSurface::project_on_kept_segment(const Point<2>    &x,
                                        const SegmentHint &keep,
                                        SurfacePoint      &point) const
  {
    if (keep.segment < 0)
      return false;
    double s = keep.s;
    if (!project_on_segment(x,
                            keep.segment,
                            s,
                            keep.held ? std::max(extension(), 0.5) :
                                        extension()))
      return false;
    point = point_at(x, keep.segment, s);
    return true;
  }



  SurfacePoint
  CurveSurface::project(const Point<2> &x, const SegmentHint &keep) const
  {
    if (SurfacePoint point; project_on_kept_segment(x, keep, point))
      return point;
    return surface_point_of(x, curve->project({{x[0], x[1]}}));
  }



  SurfacePoint
  CurveSurface::project_facing(const Point<2>    &x,
                               const SegmentHint &keep,
                               const FacingView  &view) const
  {
    if (SurfacePoint point; project_on_kept_segment(x, keep, point))
      return point;
    // A node on the chain is the slave of the part of its surface that
    // comes later along the chain, never of the part before it: two
    // stretches of one surface that face each other are then held once,
    // by the nodes of the earlier one, and not twice (each node on the
    // other's segments, the node-on-node case doubling every constraint,
    // which leaves the condensed problem singular). Nor of the segments
    // that meet its own place (the next one on each side included), whose
    // points face the same way as the node.
    const int  own        = view.master_node;
    const int  n_segments = curve->n_segments();
    const auto allowed    = [&](const unsigned int segment) {
      return own < 0 ||
             (int(segment) >= own + 2 &&
              (!chain.closed || int(segment) + 2 < own + n_segments));
    };
    const auto faces_the_node = [&](const MasterCurve::Projection &p) {
      return p.normal[0] * view.outward_normal[0] +
                 p.normal[1] * view.outward_normal[1] <
               0. &&
             p.gap >= -view.penetration_limit;
    };
    return surface_point_of(x,
                            curve->project_among({{x[0], x[1]}},
                                                 view.reach +
                                                   view.penetration_limit,
                                                 allowed,
                                                 faces_the_node));
  }



  SurfacePoint
  CurveSurface::surface_point_of(const Point<2>                &x,
                                 const MasterCurve::Projection &p) const
  {
    if (!p.valid)
      return SurfacePoint();
    SurfacePoint point = point_at(x, p.segment, p.s);
    if (p.on_vertex)
      {
        // A convex corner: the curve's own (bisecting) normal, with its gap.
        point.on_vertex = true;
        point.tangent   = Tensor<1, 2>({p.tangent[0], p.tangent[1]});
        point.normal    = Tensor<1, 2>({p.normal[0], p.normal[1]});
        point.gap       = p.gap;
        set_vertex_rotation(point);
      }
    return point;
  }
} // namespace glissade
