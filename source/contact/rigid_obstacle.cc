#include <glissade/contact/rigid_obstacle.h>

#include <cmath>

namespace glissade
{
  RigidObstacle::RigidObstacle(const ContactDescription &d)
    : type(d.obstacle)
    , point(d.obstacle_point)
    , normal(d.obstacle_normal / std::max(d.obstacle_normal.norm(), 1e-300))
    , radius(d.obstacle_radius)
    , motion(std::make_shared<FunctionParser<2>>(2))
  {
    motion->initialize("x,y,t", d.obstacle_motion, {{"pi", numbers::PI}}, true);
  }



  Tensor<1, 2>
  RigidObstacle::translation(const double time) const
  {
    motion->set_time(time);
    return Tensor<1, 2>({motion->value(Point<2>(), 0),
                         motion->value(Point<2>(), 1)});
  }



  RigidObstacle::Projection
  RigidObstacle::project(const Point<2> &x, const double time) const
  {
    const Point<2> p = point + translation(time);
    Projection     result;
    if (type == "line")
      {
        result.normal  = normal;
        result.gap     = (x - p) * normal;
        result.point   = x - result.gap * normal;
      }
    else
      {
        // Disk: n points away from the centre; hole: towards it. At the
        // centre itself any direction is as good: take +y, never NaN.
        Tensor<1, 2> d      = x - p;
        const double length = d.norm();
        d = length > 0. ? d / length : Tensor<1, 2>({0., 1.});
        result.normal = (type == "disk") ? d : -d;
        result.gap    = (type == "disk") ? length - radius : radius - length;
        result.point  = p + radius * d;
      }
    // t such that n = e3 x t, as for the master curves.
    result.tangent = Tensor<1, 2>({result.normal[1], -result.normal[0]});
    return result;
  }
} // namespace glissade
