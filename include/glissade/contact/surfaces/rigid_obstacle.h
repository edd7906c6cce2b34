#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <glissade/base/user_function.h>
#include <glissade/contact/surfaces/master_surface.h>
#include <glissade/description/scene_description.h>

#include <cmath>
#include <vector>

namespace glissade
{
  /**
   * What the rigid obstacles share: no dofs, a prescribed translation
   * m(t) of their reference point (`Obstacle/Motion`) and a rotation
   * alpha(t) about it (`Obstacle/Rotation`, counterclockwise). The
   * material point of the obstacle under a contact point moved, over the
   * increment, from p_0 + R(alpha_0 - alpha)(x_c - p) to x_c: the motion
   * the slip is measured against (a turning drum or casing rubs a node
   * that stands still).
   */
  class RigidObstacle : public MasterSurface
  {
  public:
    RigidObstacle(const ContactDescription &d)
      : reference_point(d.obstacle_point)
      , motion(d.obstacle_motion, d.entry + "/Obstacle/Motion")
      , rotation_function({d.obstacle_rotation}, d.entry + "/Obstacle/Rotation")
    {}

    void
    update(const double step_start_time, const double time) override
    {
      position       = reference_point + translation(time);
      start_position = reference_point + translation(step_start_time);
      angle          = rotation_angle(time);
      turn_in_step   = angle - rotation_angle(step_start_time);
    }

    std::vector<dealii::types::global_dof_index>
    dofs() const override
    {
      return {};
    }

    bool
    is_rigid() const override
    {
      return true;
    }

    double
    rotation() const override
    {
      return angle;
    }

    /**
     * m'(t) + alpha'(t) e3 x (x - p(t)), the derivatives of the user's
     * expressions by central differences (step 1e-6 of the time scale).
     */
    dealii::Tensor<1, 2>
    velocity_at(const dealii::Point<2> &x, const double t) const override
    {
      const double               h = 1e-6 * std::max(1., std::abs(t));
      const dealii::Tensor<1, 2> translation_rate =
        (translation(t + h) - translation(t - h)) / (2. * h);
      const double turn_rate =
        (rotation_angle(t + h) - rotation_angle(t - h)) / (2. * h);
      const dealii::Tensor<1, 2> r = x - (reference_point + translation(t));
      return translation_rate + turn_rate * dealii::Tensor<1, 2>({-r[1], r[0]});
    }

  protected:
    /**
     * The point of a curve with the given closest point, normal and
     * derivatives: c' = `first_derivative` (along t, n = e3 x t) and
     * c'' = `second_derivative`, what the linearisation of the slave's
     * sliding needs.
     */
    SurfacePoint
    point(const dealii::Point<2>     &x,
          const dealii::Point<2>     &closest,
          const dealii::Tensor<1, 2> &normal,
          const double                speed,
          const dealii::Tensor<1, 2> &second_derivative) const
    {
      SurfacePoint p;
      p.valid  = true;
      p.point  = closest;
      p.normal = normal;
      // t such that n = e3 x t, as for the master curves.
      p.tangent                 = dealii::Tensor<1, 2>({normal[1], -normal[0]});
      p.first_derivative        = speed * p.tangent;
      p.second_derivative       = second_derivative;
      p.gap                     = (x - closest) * normal;
      p.motion_since_step_start = material_motion(closest);
      // d/ds of c - p_0 - R(-turn) (c - p): c' - R(-turn) c'.
      p.motion_derivative =
        p.first_derivative - rotated(p.first_derivative, -turn_in_step);
      return p;
    }

    /** x rotated by the angle a about the origin. */
    static dealii::Tensor<1, 2>
    rotated(const dealii::Tensor<1, 2> &x, const double a)
    {
      return dealii::Tensor<1, 2>({std::cos(a) * x[0] - std::sin(a) * x[1],
                                   std::sin(a) * x[0] + std::cos(a) * x[1]});
    }

    /** The reference point where the pair's entries put it (Point). */
    const dealii::Point<2> &
    reference() const
    {
      return reference_point;
    }

    /** The reference point now, and the rotation angle now. */
    dealii::Point<2> position;
    double           angle = 0.;
    /** The reference point and the turn at the step's start... */
    dealii::Point<2> start_position;
    /** ...and the turn since. */
    double turn_in_step = 0.;

  private:
    dealii::Tensor<1, 2>
    material_motion(const dealii::Point<2> &closest) const
    {
      const dealii::Point<2> before =
        start_position + rotated(closest - position, -turn_in_step);
      return closest - before;
    }

    dealii::Tensor<1, 2>
    translation(const double time) const
    {
      motion.set_time(time);
      return dealii::Tensor<1, 2>({motion.value(dealii::Point<2>(), 0),
                                   motion.value(dealii::Point<2>(), 1)});
    }

    double
    rotation_angle(const double time) const
    {
      rotation_function.set_time(time);
      return rotation_function.value(dealii::Point<2>(), 0);
    }

    const dealii::Point<2> reference_point;
    /** m(t) and alpha(t), their values checked finite (UserFunction). */
    mutable UserFunction motion;
    mutable UserFunction rotation_function;
  };
} // namespace glissade
