#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <glissade/scene/scene_description.h>

#include <memory>

namespace glissade
{
  using namespace dealii;

  /**
   * An analytic rigid master with a prescribed translation: the half-plane
   * behind a line, a solid disk, or the outside of a circular hole. It has
   * no dofs, so it adds nothing to the compliance matrix: the condensed
   * problem only sees the slave body.
   */
  class RigidObstacle
  {
  public:
    explicit RigidObstacle(const ContactDescription &description);

    struct Projection
    {
      Point<2>     point;
      Tensor<1, 2> tangent;
      Tensor<1, 2> normal; // out of the obstacle
      double       gap;
    };

    /** Closest point of the obstacle's surface at time t. */
    Projection
    project(const Point<2> &x, const double time) const;

  private:
    Tensor<1, 2>
    translation(const double time) const;

    const std::string                  type;
    const Point<2>                     point;
    const Tensor<1, 2>                 normal;
    const double                       radius;
    std::shared_ptr<FunctionParser<2>> motion;
  };
} // namespace glissade
