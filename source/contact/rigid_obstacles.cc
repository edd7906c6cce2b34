#include <glissade/base/user_function.h>
#include <glissade/contact/master_surface.h>
#include <glissade/contact/surface_registry.h>
#include <glissade/description/scene_description.h>

#include <cmath>
#include <memory>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * What the rigid obstacles share: no dofs, and a prescribed
     * translation m(t) (`Obstacle/Motion`), whose change over the increment
     * is the motion of the obstacle's material point that the slip is
     * measured against.
     */
    class RigidObstacle : public MasterSurface
    {
    public:
      RigidObstacle(const ContactDescription &d)
        : reference_point(d.obstacle_point)
        , motion(d.obstacle_motion, d.entry + "/Obstacle/Motion")
      {}

      void
      update(const double step_start_time, const double time) override
      {
        position    = reference_point + translation(time);
        step_motion = translation(time) - translation(step_start_time);
      }

      std::vector<types::global_dof_index>
      dofs() const override
      {
        return {};
      }

      bool
      is_rigid() const override
      {
        return true;
      }

    protected:
      /**
       * The point of a curve with the given closest point, normal and
       * curvature vector c'' (the curve parametrised by arc length times
       * `speed`): what the linearisation of the slave's sliding needs.
       */
      SurfacePoint
      point(const Point<2>     &x,
            const Point<2>     &closest,
            const Tensor<1, 2> &normal,
            const double        speed,
            const Tensor<1, 2> &second_derivative) const
      {
        SurfacePoint p;
        p.valid  = true;
        p.point  = closest;
        p.normal = normal;
        // t such that n = e3 x t, as for the master curves.
        p.tangent                 = Tensor<1, 2>({normal[1], -normal[0]});
        p.first_derivative        = speed * p.tangent;
        p.second_derivative       = second_derivative;
        p.gap                     = (x - closest) * normal;
        p.motion_since_step_start = step_motion;
        return p;
      }

      Point<2> position;

    private:
      Tensor<1, 2>
      translation(const double time) const
      {
        motion.set_time(time);
        return Tensor<1, 2>(
          {motion.value(Point<2>(), 0), motion.value(Point<2>(), 1)});
      }

      const Point<2> reference_point;
      /** m(t), its values checked finite (UserFunction). */
      mutable UserFunction motion;
      Tensor<1, 2>         step_motion;
    };



    /** The half-plane behind a line (`Obstacle/Point`, `Obstacle/Normal`). */
    class LineObstacle : public RigidObstacle
    {
    public:
      LineObstacle(const SurfaceContext &context)
        : RigidObstacle(context.description)
        , normal(context.description.obstacle_normal /
                 std::max(context.description.obstacle_normal.norm(), 1e-300))
      {}

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &) const override
      {
        const double gap = (x - position) * normal;
        return point(x, x - gap * normal, normal, 1., Tensor<1, 2>());
      }

    private:
      const Tensor<1, 2> normal;
    };



    /**
     * A solid disk (n away from the centre) or the outside of a circular
     * hole (n towards it), of `Obstacle/Radius` R about `Obstacle/Point`.
     * Parametrised with speed R, c'' = -R n for the disk and R n for the
     * hole: the curvature that turns the normal as a node slides.
     */
    class CircleObstacle : public RigidObstacle
    {
    public:
      CircleObstacle(const SurfaceContext &context, const bool hole)
        : RigidObstacle(context.description)
        , radius(context.description.obstacle_radius)
        , hole(hole)
      {}

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &) const override
      {
        // At the centre itself any direction is as good: take +y, never NaN.
        Tensor<1, 2> d      = x - position;
        const double length = d.norm();
        d                   = length > 0. ? d / length : Tensor<1, 2>({0., 1.});
        const Tensor<1, 2> normal = hole ? -d : d;
        return point(x,
                     position + radius * d,
                     normal,
                     radius,
                     (hole ? radius : -radius) * normal);
      }

    private:
      const double radius;
      const bool   hole;
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_line_obstacle(const SurfaceContext &context)
  {
    return std::make_unique<LineObstacle>(context);
  }



  std::unique_ptr<MasterSurface>
  make_disk_obstacle(const SurfaceContext &context)
  {
    return std::make_unique<CircleObstacle>(context, false);
  }



  std::unique_ptr<MasterSurface>
  make_hole_obstacle(const SurfaceContext &context)
  {
    return std::make_unique<CircleObstacle>(context, true);
  }
} // namespace glissade
