#pragma once

#include <deal.II/base/types.h>

#include <glissade/contact/discretisation/mortar_variables.h>
#include <glissade/contact/surfaces/master_surface.h>

#include <array>
#include <vector>

namespace glissade
{
  class Body;
  class CurveSurface;
} // namespace glissade

/**
 * The master point of a mortar Gauss point on a smooth master curve (the
 * B-spline, the Hermite edge, a NURBS boundary, or the faceted chain as
 * a curve): where the slave normal through the Gauss point meets the
 * curve, with what it depends on as dual numbers. Shared by the mortar
 * of Q1 slave faces (mortar.cc) and of NURBS slave spans
 * (nurbs_slave_mortar.cc); doc/contact.md, "Mortar".
 */
namespace glissade::mortar
{
  /** A force weight of the curve point: the reaction's share on a dof. */
  struct CurveForceWeight
  {
    dealii::types::global_dof_index dof;
    unsigned int                    component;
    MortarDual                      weight;
  };

  /** The curve point of one Gauss point. */
  struct CurvePoint
  {
    /** The point y and its material's motion since the increment began. */
    MortarDual y[2], motion[2];
    /**
     * The curve point's dof weights at its parameter: the change of the
     * point, sum_w w.value du(w.dof), is carried by the two dual
     * variables given to find_curve_point() (mapped to these dofs when
     * the integrals are summed, add_curve_variables()).
     */
    std::vector<SurfaceWeight> kinematics;
    /** Where a unit force at the point goes, by dof and component. */
    std::vector<CurveForceWeight> forces;
  };

  /**
   * The master curve of `surface` (the master body `master`) met by the
   * line through x along n on segment i: Newton in plain numbers from the
   * parameter `start`, then one Newton step on the duals. The point's own
   * change is the dual variables `variable` and `variable + 1`;
   * `segment_ends` are the segment's end nodes as duals and
   * `segment_dofs` their value dofs, which the reaction goes to when the
   * surface transfers by segment. False if Newton leaves (no point: the
   * normal runs along the curve).
   */
  bool
  find_curve_point(
    const CurveSurface             &surface,
    const Body                     &master,
    unsigned int                    i,
    unsigned int                    variable,
    const DualPoint                &x,
    const DualPoint                &n,
    double                          start,
    const std::array<DualPoint, 2> &segment_ends,
    const std::array<std::array<dealii::types::global_dof_index, 2>, 2>
               &segment_dofs,
    CurvePoint &point);

  /**
   * A rigid obstacle's point closest to the slave point x (`point`, from
   * MasterSurface::project), moved with x as duals: by c' ds, ds = c' . dx
   * / (c' . c' - (x - c) . c''), and its material's motion by m' ds. The
   * y and motion of a CurvePoint (no kinematics, no force weights).
   */
  CurvePoint
  obstacle_point(const SurfacePoint &point, const DualPoint &x);

  /**
   * Where a slave point next to a rigid obstacle's open end stands: past
   * the end (no counterpart there), and if so whether near enough to be
   * held there (MasterSurface::project with SegmentHint::held).
   */
  struct OpenEndPlace
  {
    bool past        = false;
    bool may_be_held = false;

    /**
     * The point counts if it is not past the end, or if it held contact
     * there within the increment and is kept until the increment ends, as
     * node-to-segment keeps it (ContactPair::update_geometry).
     */
    bool
    counts(const bool         keep_segment,
           const bool         active,
           const unsigned int segment_switches) const
    {
      return !past ||
             (may_be_held && keep_segment && active && segment_switches >= 2);
    }
  };

  OpenEndPlace
  open_end_place(const MasterSurface &surface, const dealii::Point<2> &x);

  /**
   * The derivatives of v in the curve points' variables (`first_variable`
   * + 2q + component for the Gauss point q whose kinematics are
   * kinematics[q]) as master dofs, appended to `to`'s gradient.
   */
  void
  add_curve_variables(const MortarDual                              &v,
                      const std::vector<std::vector<SurfaceWeight>> &kinematics,
                      unsigned int first_variable,
                      Accumulated &to);
} // namespace glissade::mortar
