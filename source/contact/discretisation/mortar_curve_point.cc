#include <deal.II/lac/vector.h>

#include <glissade/body/body.h>
#include <glissade/contact/discretisation/mortar_curve_point.h>
#include <glissade/contact/surfaces/curve_surface.h>

#include <algorithm>
#include <cmath>

namespace glissade::mortar
{
  namespace
  {
    /** Newton on (c(t) - x) x n = 0 in plain numbers; NaN if it leaves. */
    double
    curve_parameter(const MasterCurve &curve,
                    const unsigned int i,
                    const DualPoint   &x,
                    const DualPoint   &n,
                    const double       start)
    {
      double             t = std::min(1., std::max(0., start));
      MasterCurve::Point c0{}, c1{}, c2{};
      for (unsigned int it = 0; it < 30; ++it)
        {
          curve.evaluate(i, t, c0, c1, c2);
          const double F =
            (c0[0] - x.x.value) * n.y.value - (c0[1] - x.y.value) * n.x.value;
          const double dF   = c1[0] * n.y.value - c1[1] * n.x.value;
          const double step = F / dF;
          t -= step;
          if (!std::isfinite(t) || std::abs(step) < 1e-15)
            break;
        }
      return t;
    }
  } // namespace



  bool
  find_curve_point(
    const CurveSurface             &surface,
    const Body                     &master,
    const unsigned int              i,
    const unsigned int              variable,
    const DualPoint                &x,
    const DualPoint                &n,
    const double                    start,
    const std::array<DualPoint, 2> &segment_ends,
    const std::array<std::array<dealii::types::global_dof_index, 2>, 2>
               &segment_dofs,
    CurvePoint &point)
  {
    const MasterCurve &curve = surface.master_curve();
    const double       t     = curve_parameter(curve, i, x, n, start);
    if (!std::isfinite(t))
      return false;
    MasterCurve::Point c0{}, c1{}, c2{};
    curve.evaluate(i, t, c0, c1, c2);
    // The curve point at t, moved by its dofs: C + dC, with dC = sum_w w
    // du_w the two variables; one Newton step on the duals from t:
    // (c(eta) - x) x n = 0.
    const DualPoint  C{MortarDual::variable(c0[0], variable),
                      MortarDual::variable(c0[1], variable + 1)};
    const DualPoint  dC{MortarDual(c1[0]), MortarDual(c1[1])};
    const MortarDual eta = t - cross(C - x, n) / cross(dC, n);
    point.kinematics     = surface.kinematics_at(i, t);
    dealii::Tensor<1, 2>          m0, m1;
    const dealii::Vector<double> &u  = master.displacement();
    const dealii::Vector<double> &u0 = master.stored_displacement();
    for (const SurfaceWeight &e : point.kinematics)
      {
        const double moved = u(e.dof) - u0(e.dof);
        m0[e.component] += e.value * moved;
        m1[e.component] += e.derivative * moved;
      }
    // (the motion's change by the dofs is the point's, dC: the dofs'
    // values at the increment's start are fixed)
    const MortarDual deta = eta - t;
    point.y[0]            = C.x + c1[0] * deta;
    point.y[1]            = C.y + c1[1] * deta;
    point.motion[0]       = m0[0] + (C.x - c0[0]) + m1[0] * deta;
    point.motion[1]       = m0[1] + (C.y - c0[1]) + m1[1] * deta;

    point.forces.clear();
    if (surface.transfers_by_segment())
      {
        // The underlying segment's two nodes, by the hat functions at the
        // curve point's place along the chord (not at the curve's
        // parameter, whose speed need not be uniform: on a straight master
        // the two differ near its ends, and the patch test would fail by
        // their difference).
        const DualPoint &Yc = segment_ends[0], &Yd        = segment_ends[1];
        const DualPoint  Y{point.y[0], point.y[1]}, chord = Yd - Yc;
        const DualPoint  from_c = Y - Yc;
        const MortarDual along  = (from_c.x * chord.x + from_c.y * chord.y) /
                                 (chord.x * chord.x + chord.y * chord.y);
        for (unsigned int k = 0; k < 2; ++k)
          {
            point.forces.push_back({segment_dofs[0][k], k, 1. - along});
            point.forces.push_back({segment_dofs[1][k], k, along});
          }
      }
    else
      // The curve's own weights (the Hermite edge's, the spline's, the
      // NURBS functions): the reaction's work conjugate to the gap.
      for (const SurfaceWeight &e : surface.forces_at(i, t, point.kinematics))
        point.forces.push_back(
          {e.dof, e.component, e.value + e.derivative * deta});
    return true;
  }



  CurvePoint
  obstacle_point(const SurfacePoint &point, const DualPoint &x)
  {
    const dealii::Tensor<1, 2> &dc = point.first_derivative;
    const dealii::Tensor<1, 2>  r(
      {x.x.value - point.point[0], x.y.value - point.point[1]});
    const MortarDual ds =
      (dc[0] * (x.x - x.x.value) + dc[1] * (x.y - x.y.value)) /
      MortarDual(dc * dc - r * point.second_derivative);
    CurvePoint result;
    for (unsigned int c = 0; c < 2; ++c)
      {
        result.y[c] = point.point[c] + dc[c] * ds;
        result.motion[c] =
          point.motion_since_step_start[c] + point.motion_derivative[c] * ds;
      }
    return result;
  }



  OpenEndPlace
  open_end_place(const MasterSurface &surface, const dealii::Point<2> &x)
  {
    OpenEndPlace place;
    place.past        = !surface.project(x).valid;
    place.may_be_held = place.past && surface.project(x, {-1, 0., true}).valid;
    return place;
  }



  void
  add_curve_variables(const MortarDual                              &v,
                      const std::vector<std::vector<SurfaceWeight>> &kinematics,
                      const unsigned int first_variable,
                      Accumulated       &to)
  {
    for (unsigned int q = 0; q < kinematics.size(); ++q)
      for (const SurfaceWeight &e : kinematics[q])
        if (const double dv =
              v.derivative[first_variable + 2 * q + e.component];
            dv != 0.)
          to.gradient.push_back({1, e.dof, dv * e.value});
  }
} // namespace glissade::mortar
