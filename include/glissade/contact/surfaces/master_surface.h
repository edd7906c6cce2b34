#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <vector>

namespace glissade
{
  class AbradableCoating;

  /**
   * One master dof's share in the point of the master surface under a
   * slave node: component `component` of the surface point c(s) contains
   * `value` times the dof's displacement, and c'(s) contains `derivative`
   * (= d value / ds) times it. The same form hands the reaction to the
   * dofs (then value is the share of the force).
   */
  struct SurfaceWeight
  {
    dealii::types::global_dof_index dof;
    unsigned int                    component;
    double                          value;
    double                          derivative;
  };

  /**
   * Where a slave node meets a master surface, with what the consistent
   * linearisation needs (theory.md, section 4.2): the curve's first two
   * derivatives at the point and the dof weights with their derivatives
   * along the curve.
   */
  struct SurfacePoint
  {
    /** False if the node has no counterpart (beyond an open end). */
    bool valid = false;

    /**
     * Not valid, and beyond a rigid obstacle's open end: the point is then
     * the foot of x on the end's tangent line (the obstacle continued
     * straight past its end), with the end's normal and c'' = 0. Mortar
     * integrates the part of a slave face that passes the end against it,
     * so that a node at the end sees the obstacle over its whole support
     * (as node-to-segment sees it at the node); whether a node counts is
     * its own point's validity. (A node held there within the increment,
     * SegmentHint::held, gets the same point, valid.)
     */
    bool beyond_open_end = false;

    /** Segment and local coordinate s (in [0, 1], or a faceted extension). */
    int    segment = -1;
    double s       = 0.;

    /** c(s), the unit tangent t = c'/|c'| and n = e3 x t (out of the master).
     */
    dealii::Point<2>     point;
    dealii::Tensor<1, 2> tangent, normal;

    /** c'(s) and c''(s). */
    dealii::Tensor<1, 2> first_derivative, second_derivative;

    /** (x - c) . n for the slave node x. */
    double gap = 0.;

    /**
     * The point is a corner node of the master curve (a convex vertex of a
     * faceted master, see MasterCurve::Projection::on_vertex): it does not
     * slide, and the normal bisects the corner; vertex_rotation gives the
     * normal's turn, theta = sum w u (delta t = theta n, delta n = -theta t).
     */
    bool                       on_vertex = false;
    std::vector<SurfaceWeight> vertex_rotation;

    /**
     * At a vertex of a faceted master met with its mean normal (the
     * Faceted vertex rule vertex normal), the normal is set-valued: the
     * reaction may lie anywhere between the two facets' normals,
     * |r_t| <= vertex_cone r_n about the mean normal (vertex_cone = tan of
     * half the angle between the facets' normals; with Coulomb friction mu
     * on the facets the cone widens to tan(atan(vertex_cone) + atan(mu))).
     * The node then holds its place at the vertex, and its slip is its
     * tangential offset from the vertex, t . (x - c). Zero elsewhere.
     */
    double vertex_cone = 0.;

    /** The master dofs in c(s) (value) and c'(s) (derivative). */
    std::vector<SurfaceWeight> kinematics;

    /**
     * The master dofs that receive the reaction and their shares: the same
     * as kinematics, or the two nodes of the straight segment under a
     * B-spline point (the paper's hand-over), with the shares' derivatives
     * along the curve.
     */
    std::vector<SurfaceWeight> forces;

    /**
     * The displacement of the master's material point since the start of
     * the increment that no dof carries: a rigid obstacle's prescribed
     * translation (zero for a deformable master, whose motion is in its
     * dofs). The slip is measured against it.
     */
    dealii::Tensor<1, 2> motion_since_step_start;
    /**
     * Its derivative along the curve's parameter: not zero for an
     * obstacle that turns, whose material points each moved by their own
     * amount.
     */
    dealii::Tensor<1, 2> motion_derivative;
  };

  /**
   * A node's segment to keep (segment -1: none). `held`: the node has
   * already switched segments back and forth within the increment, and
   * keeps this one along its extension (up to half its length past either
   * end) until the increment ends.
   */
  struct SegmentHint
  {
    int    segment = -1;
    double s       = 0.;
    bool   held    = false;
    /**
     * The last point was a vertex with its cone (SurfacePoint::vertex_cone),
     * `segment` the one leaving it; `sticking`: and the contact law held
     * the node there (within the cone). A sticking node stays at its vertex
     * (the Newton step that pinned it there leaves it off the vertex by
     * the step's second-order remainder, which must not send it to a
     * facet); a node that slipped off is projected afresh.
     */
    bool at_vertex = false;
    bool sticking  = false;
  };

  /**
   * What self-contact (a pair whose master is its slave's own body) asks
   * of a projection, so that a node finds the part of the surface that
   * faces it rather than its own segments, or the body's back: the
   * master point's normal against the node's current outward normal
   * (n_master . n_slave < 0), no farther than `reach` and no deeper behind
   * than `penetration_limit` (a node that deep would see through the
   * body). A node on the master (its place `master_node` on the chain,
   * else -1) takes only the segments past the next one after its place:
   * two stretches of one surface that face each other are held once, by
   * the earlier one's nodes (CurveSurface::project_facing).
   */
  struct FacingView
  {
    dealii::Tensor<1, 2> outward_normal;
    int                  master_node       = -1;
    double               reach             = 0.;
    double               penetration_limit = 0.;
  };

  /**
   * A master surface of a contact pair: a deformable body's boundary seen
   * through a smoothing (faceted, B-spline, Hermite edges) or a rigid
   * analytic obstacle. One class per kind, registered in
   * SurfaceRegistry (surface_registry.cc); doc/adding_a_surface.md.
   *
   * A surface owns its data (the chain of master nodes and their dofs, the
   * curve) and knows how its points depend on the master dofs. What is the
   * same for every surface (gap, slip, their derivatives, the contact
   * tangent) is written once, in contact_linearization.cc.
   */
  class MasterSurface
  {
  public:
    virtual ~MasterSurface() = default;

    /**
     * The surface at the current state: rebuilt from the master body's
     * current displacement, or moved to the obstacle's position at `time`.
     * `step_start_time` is the time of the increment's starting state.
     */
    virtual void
    update(double step_start_time, double time) = 0;

    /**
     * The counterpart of the point x. With a `keep` hint (the segment and
     * s of the node's last projection in this increment), the node keeps
     * that segment while it still has an orthogonal projection there (for a
     * faceted master: on the segment's extension, up to half its length
     * past either end), so that the contact constraint does not jump
     * between two equally close segments from one Newton iteration to the
     * next.
     */
    virtual SurfacePoint
    project(const dealii::Point<2> &x, const SegmentHint &keep = {}) const = 0;

    /**
     * Self-contact's counterpart of x (FacingView): with a `keep` hint as
     * project(), else the closest point that faces x. Surfaces on a body's
     * boundary answer it; the default (a rigid obstacle, never its own
     * slave) has none.
     */
    /**
     * The mesh vertices along the surface, in its order (a body's boundary
     * chain); empty for a rigid obstacle.
     */
    virtual std::vector<unsigned int>
    vertices() const
    {
      return {};
    }

    virtual SurfacePoint
    project_facing(const dealii::Point<2> & /*x*/,
                   const SegmentHint & /*keep*/,
                   const FacingView & /*view*/) const
    {
      return SurfacePoint();
    }

    /**
     * Every master dof that a point's weights can ever contain (empty for
     * a rigid obstacle): the body eliminates them last.
     */
    virtual std::vector<dealii::types::global_dof_index>
    dofs() const = 0;

    /** True for an obstacle without dofs. */
    virtual bool
    is_rigid() const = 0;

    /**
     * The velocity at time t of the obstacle's material at x (a rigid
     * obstacle's prescribed motion); zero for a deformable master, whose
     * velocity is its dofs'.
     */
    virtual dealii::Tensor<1, 2>
    velocity_at(const dealii::Point<2> & /*x*/, const double /*t*/) const
    {
      return {};
    }

    /**
     * A rigid obstacle's curve as a polyline, for pictures: the part that
     * a box of half-diagonal `reach` about `centre` sees. Empty for a
     * deformable master, whose body draws itself.
     */
    virtual std::vector<dealii::Point<2>>
    outline(const dealii::Point<2> & /*centre*/, const double /*reach*/) const
    {
      return {};
    }

    /**
     * A rigid obstacle's convex corners as they stand now: the ends of an
     * open curve. A slave face can wrap around one, which neither
     * discretisation sees (they hold the slave's points off the obstacle,
     * not the obstacle's corners off the slave's faces):
     * ContactPair::measure_corners() says how far one went in.
     */
    virtual std::vector<dealii::Point<2>>
    open_ends() const
    {
      return {};
    }

    /** The surface's abradable coating, if it has one (a casing's). */
    virtual AbradableCoating *
    coating()
    {
      return nullptr;
    }
    virtual const AbradableCoating *
    coating() const
    {
      return nullptr;
    }

    /**
     * After a converged step: wears the coating along the path of a point
     * that yielded on it, from x_start at the step's start to x_end at its
     * end (the surface as it stood at each). Nothing without a coating.
     */
    virtual void
    wear_along(const dealii::Point<2> & /*x_start*/,
               const dealii::Point<2> & /*x_end*/)
    {}

    /** A rigid obstacle's turn now (Obstacle/Rotation); zero otherwise. */
    virtual double
    rotation() const
    {
      return 0.;
    }

    /** The coating's removed area (zero without one). */
    virtual double
    removed_area() const
    {
      return 0.;
    }
  };
} // namespace glissade
