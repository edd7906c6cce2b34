#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/base/user_function.h>
#include <glissade/contact/surfaces/abradable_coating.h>
#include <glissade/contact/surfaces/master_surface.h>
#include <glissade/contact/surfaces/rigid_obstacle.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/description/scene_description.h>

#include <any>
#include <array>
#include <cmath>
#include <memory>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** A casing's shape (`Obstacle/Radius`, `Lobes`, `Lobe depth`) and
     *  its abradable coating (`Coating thickness`, ...; none if 0). */
    struct CasingShape
    {
      double       radius            = 1.;
      unsigned int lobes             = 2;
      double       depth             = 0.;
      double       coating_thickness = 0., coating_yield_pressure = 0.;
      unsigned int coating_cells = 1440;
    };

    /** The half-plane behind a line (`Obstacle/Point`, `Obstacle/Normal`). */
    class LineObstacle : public RigidObstacle
    {
    public:
      LineObstacle(const SurfaceContext &context)
        : RigidObstacle(context.description)
        , normal(
            std::any_cast<Tensor<1, 2>>(context.description.surface_settings))
      {}

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &) const override
      {
        const Tensor<1, 2> n   = rotated(normal, angle);
        const double       gap = (x - position) * n;
        return point(x, x - gap * n, n, 1., Tensor<1, 2>());
      }

      std::vector<Point<2>>
      outline(const Point<2> &centre, const double reach) const override
      {
        const Tensor<1, 2> n    = rotated(normal, angle);
        const Point<2>     foot = centre - ((centre - position) * n) * n;
        const Tensor<1, 2> t({n[1], -n[0]});
        return {foot - reach * t, foot + reach * t};
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
        , radius(std::any_cast<double>(context.description.surface_settings))
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

      std::vector<Point<2>>
      outline(const Point<2> &, const double) const override
      {
        std::vector<Point<2>> points;
        for (unsigned int k = 0; k <= 360; ++k)
          {
            const double phi = 2. * M_PI * k / 360.;
            points.push_back(
              position + radius * Tensor<1, 2>({std::cos(phi), std::sin(phi)}));
          }
        return points;
      }

    private:
      const double radius;
      const bool   hole;
    };


    /**
     * The inside of a casing ovalised into n lobes (`Obstacle/Lobes`) of
     * depth delta (`Obstacle/Lobe depth`) about a circle of radius R:
     *   r(phi) = R - delta cos(n (phi - alpha)),
     * in polar coordinates about `Obstacle/Point`, the lobes (where the
     * casing comes in furthest) at phi = alpha + 2 pi k / n, alpha the
     * obstacle's rotation. A blade seen from its own turning frame sees
     * the casing turn backwards: Rotation = -Omega t. The curve stays
     * convex (delta < R / (1 + n^2), checked on reading), so that the
     * closest point is the one Newton's method finds from the node's polar
     * angle. Parametrised by phi:
     *   c' = r' e_r + r e_phi,  c'' = (r'' - r) e_r + 2 r' e_phi.
     */
    class CasingObstacle : public RigidObstacle
    {
    public:
      CasingObstacle(const SurfaceContext &context)
        : RigidObstacle(context.description)
        , shape(
            std::any_cast<CasingShape>(context.description.surface_settings))
      {
        if (shape.coating_thickness > 0.)
          layer =
            std::make_unique<AbradableCoating>(shape.coating_thickness,
                                               shape.coating_yield_pressure,
                                               shape.coating_cells);
      }

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &) const override
      {
        const Tensor<1, 2> d   = x - position;
        double             phi = d.norm() > 0. ? std::atan2(d[1], d[0]) : 0.;
        // (c - x) . c' = 0 by Newton's method: from the node's own angle
        // it converges in a few steps, the curve being nearly a circle.
        for (unsigned int k = 0; k < 50; ++k)
          {
            const Curve        c  = at(phi);
            const Tensor<1, 2> r  = c.point - x;
            const double       f  = r * c.first;
            const double       df = c.first * c.first + r * c.second;
            const double step = df > 0. ? -f / df : -f / (c.first * c.first);
            phi += std::max(-0.1, std::min(0.1, step));
            if (std::abs(step) < 1e-15)
              break;
          }
        const Curve        c     = at(phi);
        const double       speed = c.first.norm();
        const Tensor<1, 2> normal({-c.first[1] / speed, c.first[0] / speed});
        return point(x, c.point, normal, speed, c.second);
      }

      std::vector<Point<2>>
      outline(const Point<2> &, const double) const override
      {
        std::vector<Point<2>> points;
        for (unsigned int k = 0; k <= 720; ++k)
          points.push_back(at(2. * M_PI * k / 720.).point);
        return points;
      }

      AbradableCoating *
      coating() override
      {
        return layer.get();
      }
      const AbradableCoating *
      coating() const override
      {
        return layer.get();
      }

      void
      wear_along(const Point<2> &x_start, const Point<2> &x_end) override
      {
        if (!layer)
          return;
        // Each end in the casing's frame, as the casing stood then.
        const auto frame_coordinates =
          [](const Point<2> &x, const Point<2> &centre, const double turn) {
            const Tensor<1, 2> d = x - centre;
            return std::array<double, 2>{
              {std::atan2(d[1], d[0]) - turn, d.norm()}};
          };
        const auto start =
          frame_coordinates(x_start, start_position, angle - turn_in_step);
        const auto end = frame_coordinates(x_end, position, angle);
        layer->wear_along(start[0], start[1], end[0], end[1], [&](double psi) {
          return casing_radius(psi);
        });
      }

      double
      removed_area() const override
      {
        return layer ? layer->removed_area(
                         [&](double psi) { return casing_radius(psi); }) :
                       0.;
      }

    private:
      struct Curve
      {
        Point<2>     point;
        Tensor<1, 2> first, second;
      };

      /** The casing's own curve r_c(psi) in its frame (under a coating). */
      double
      casing_radius(const double psi) const
      {
        return shape.radius - shape.depth * std::cos(shape.lobes * psi);
      }

      /**
       * The contact surface at the polar angle phi: the casing's curve, or
       * the coating's worn surface inside it, r = r_c(psi) - e + w(psi),
       * psi = phi - rotation.
       */
      Curve
      at(const double phi) const
      {
        const double n   = shape.lobes;
        const double psi = phi - angle;
        const double s   = n * psi;
        double       r   = casing_radius(psi);
        double       dr  = shape.depth * n * std::sin(s);
        double       ddr = shape.depth * n * n * std::cos(s);
        if (layer)
          {
            const auto w = layer->worn(psi);
            r += w[0] - layer->thickness();
            dr += w[1];
            ddr += w[2];
          }
        const Tensor<1, 2> e_r({std::cos(phi), std::sin(phi)});
        const Tensor<1, 2> e_phi({-std::sin(phi), std::cos(phi)});
        return {position + r * e_r,
                dr * e_r + r * e_phi,
                (ddr - r) * e_r + 2. * dr * e_phi};
      }

      const CasingShape                 shape;
      std::unique_ptr<AbradableCoating> layer;
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



  std::unique_ptr<MasterSurface>
  make_casing_obstacle(const SurfaceContext &context)
  {
    return std::make_unique<CasingObstacle>(context);
  }



  // The obstacles' own entries: each kind declares and reads the entries of
  // its shape (SurfaceRegistry); Point, Motion and Rotation, the pose of
  // every obstacle, are the pair's. An entry that several kinds read
  // (Radius) is declared by each with the same text.

  namespace
  {
    void
    declare_radius(ParameterHandler &prm)
    {
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "disk, hole: the radius; casing: the mean radius R.");
    }

    double
    parse_radius(const ParameterHandler &prm,
                 const std::string      &where,
                 const std::string      &kind)
    {
      const double radius = prm.get_double("Radius");
      if (!(radius <= 1e100))
        throw InputError(where + "/Radius",
                         "must be finite and below 1e100 (squared distances "
                         "would overflow)");
      // A disk of radius 0 is a point and a hole of radius 0 has no inside:
      // no slave node would ever touch either, and the run would end with
      // no contact and exit 0.
      if (!(radius > 0.))
        throw InputError(where + "/Radius",
                         "must be > 0 for a " + kind +
                           " (a radius of 0 makes it a point that no slave "
                           "node ever touches)");
      return radius;
    }
  } // namespace



  void
  declare_line_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Normal",
                      "0, 1",
                      Patterns::Anything(),
                      "line: the normal pointing out of the obstacle.");
  }



  std::any
  parse_line_parameters(const ParameterHandler &prm,
                        const std::string      &where,
                        const std::string &)
  {
    const auto n = text::coordinates(prm.get("Normal"), where + "/Normal");
    const Tensor<1, 2> normal({n[0], n[1]});
    if (normal.norm() == 0.)
      throw InputError(where + "/Normal", "must not be zero");
    return Tensor<1, 2>(normal / normal.norm());
  }



  void
  declare_circle_parameters(ParameterHandler &prm)
  {
    declare_radius(prm);
  }



  std::any
  parse_disk_parameters(const ParameterHandler &prm,
                        const std::string      &where,
                        const std::string &)
  {
    return parse_radius(prm, where, "disk");
  }



  std::any
  parse_hole_parameters(const ParameterHandler &prm,
                        const std::string      &where,
                        const std::string &)
  {
    return parse_radius(prm, where, "hole");
  }



  void
  declare_casing_parameters(ParameterHandler &prm)
  {
    declare_radius(prm);
    prm.declare_entry("Lobes",
                      "2",
                      Patterns::Integer(1),
                      "casing: the number n of lobes, r(phi) = R - "
                      "depth cos(n (phi - rotation)).");
    prm.declare_entry("Lobe depth",
                      "0",
                      Patterns::Double(0.),
                      "casing: how far the lobes come in from the circle "
                      "of radius R (below R / (1 + n^2), so that the "
                      "casing stays convex).");
    prm.declare_entry(
      "Coating thickness",
      "0",
      Patterns::Double(0.),
      "casing: an abradable coating of this thickness on the casing's "
      "inside, the contact surface (0: none). It is rigid and perfectly "
      "plastic: a slave node presses on it with at most Coating yield "
      "pressure times its tributary area, and where it presses that hard "
      "it cuts in, the coating removed along its path (Legrand, Batailly & "
      "Pierre 2012). The worn profile is written per revolution "
      "(coating-<pair>.csv and .png) and the removed area is the history "
      "item wear(<pair>).");
    prm.declare_entry("Coating yield pressure",
                      "0",
                      Patterns::Double(0.),
                      "casing: the pressure at which the coating gives "
                      "way (force per unit area; with a coating, > 0).");
    prm.declare_entry("Coating cells",
                      "1440",
                      Patterns::Integer(16),
                      "casing: the worn profile's equal angles round the "
                      "casing (1440: a quarter of a degree).");
  }



  std::any
  parse_casing_parameters(const ParameterHandler &prm,
                          const std::string      &where,
                          const std::string &)
  {
    CasingShape shape;
    shape.radius                 = prm.get_double("Radius");
    shape.lobes                  = prm.get_integer("Lobes");
    shape.depth                  = prm.get_double("Lobe depth");
    shape.coating_thickness      = prm.get_double("Coating thickness");
    shape.coating_yield_pressure = prm.get_double("Coating yield pressure");
    shape.coating_cells          = prm.get_integer("Coating cells");
    if (shape.coating_thickness > 0. && !(shape.coating_yield_pressure > 0.))
      throw InputError(where + "/Coating yield pressure",
                       "must be > 0 with a coating (Coating thickness = " +
                         std::to_string(shape.coating_thickness) + ")");
    if (!(shape.coating_thickness < 0.5 * shape.radius))
      throw InputError(where + "/Coating thickness",
                       "must be below half the Radius");
    if (!(shape.radius <= 1e100))
      throw InputError(where + "/Radius",
                       "must be finite and below 1e100 (squared distances "
                       "would overflow)");
    if (!(shape.radius > 0. &&
          shape.depth * (1. + shape.lobes * shape.lobes) < shape.radius))
      throw InputError(where + "/Lobe depth",
                       "must be below Radius / (1 + Lobes^2) = " +
                         std::to_string(shape.radius /
                                        (1. + shape.lobes * shape.lobes)) +
                         ", and the Radius above 0: a deeper lobe makes the "
                         "casing concave, where a node has two closest "
                         "points");
    return shape;
  }
} // namespace glissade
