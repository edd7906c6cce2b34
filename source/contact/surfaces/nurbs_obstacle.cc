// A rigid obstacle bounded by a NURBS curve (Obstacle/Type = nurbs curve):
// the exact shape of a tool, a die's rounded profile, a circle or an
// ellipse, read from a curve file (doc/user_guide.md, "NURBS curve files").

#include <deal.II/base/quadrature_lib.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/contact/surfaces/rigid_obstacle.h>
#include <glissade/contact/surfaces/surface_registry.h>
#include <glissade/mesh/nurbs_patch.h>
#include <glissade/mesh/nurbs_patch_file.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** A curve of a file: its basis, control points and weights. */
    struct NurbsCurveShape
    {
      BSplineBasis          basis;
      std::vector<Point<2>> points;
      std::vector<double>   weights;
      /** Its last control point is its first: it has no ends. */
      bool closed = false;
    };

    /** C(u) on a span, C'(u) and C''(u). */
    struct CurveSample
    {
      Point<2>     point;
      Tensor<1, 2> first, second;
    };

    /** The rational curve and its derivatives: C = A / W, C' = (A' - W' C)
     *  / W, C'' = (A'' - 2 W' C' - W'' C) / W. */
    CurveSample
    curve_at(const NurbsCurveShape &curve, const unsigned int span, double u)
    {
      std::vector<double> N, dN, d2N;
      curve.basis.evaluate(span, u, N, dN, d2N);
      const unsigned int first = curve.basis.first_function(span);
      Tensor<1, 2>       A, dA, d2A;
      double             W = 0., dW = 0., d2W = 0.;
      for (unsigned int i = 0; i < N.size(); ++i)
        {
          const double       w = curve.weights[first + i];
          const Tensor<1, 2> P = curve.points[first + i];
          A += N[i] * w * P;
          dA += dN[i] * w * P;
          d2A += d2N[i] * w * P;
          W += N[i] * w;
          dW += dN[i] * w;
          d2W += d2N[i] * w;
        }
      CurveSample c;
      c.point  = Point<2>(A / W);
      c.first  = (dA - dW * Tensor<1, 2>(c.point)) / W;
      c.second = (d2A - 2. * dW * c.first - d2W * Tensor<1, 2>(c.point)) / W;
      return c;
    }

    /**
     * A curve file, checked: its lines, its knots (check_knot_vector), a
     * control point per function, positive weights, a tangent that never
     * vanishes, and no corner (the tangent's direction the same on both
     * sides of a knot repeated p times, and at a closed curve's seam): a
     * rigid obstacle's normal cannot turn through a corner.
     */
    NurbsCurveShape
    read_curve_file(const std::string &file, const std::string &where_entry)
    {
      const std::string where = where_entry + " ('" + file + "')";
      const auto lines  = meaningful_lines(file, "NURBS curve file", where);
      int        degree = 0;
      std::vector<double> knots;
      std::vector<double> x, y, w;
      for (unsigned int i = 0; i < lines.size(); ++i)
        {
          const auto &[number, text] = lines[i];
          const std::string  at = where + ", line " + std::to_string(number);
          std::istringstream words(text);
          std::string        key;
          words >> key;
          if (key == "degree")
            {
              if (!(words >> degree) || degree < 1)
                throw InputError(at, "expected 'degree p' with p >= 1");
            }
          else if (key == "knots")
            {
              knots.clear();
              for (double u; words >> u;)
                knots.push_back(u);
              if (!words.eof())
                throw InputError(at, "a knot is not a number");
            }
          else if (key == "control")
            {
              std::string points;
              int         n = 0;
              if (!(words >> points >> n) || points != "points" || n < 1)
                throw InputError(at, "expected 'control points n'");
              for (unsigned int k = 0; k < unsigned(n); ++k)
                {
                  if (++i >= lines.size())
                    throw InputError(at,
                                     "the file ends after " +
                                       std::to_string(k) + " of the " +
                                       std::to_string(n) + " control points");
                  const auto [px, py, pw] =
                    read_control_point(lines[i].second,
                                       k,
                                       where + ", line " +
                                         std::to_string(lines[i].first));
                  x.push_back(px);
                  y.push_back(py);
                  w.push_back(pw);
                }
            }
          else
            throw InputError(at,
                             "'" + key +
                               "' is not one of degree, knots, control "
                               "points");
        }
      if (degree < 1 || knots.empty() || x.empty())
        throw InputError(where,
                         "a curve needs 'degree', 'knots' and 'control "
                         "points'");
      check_knot_vector(knots, degree, "knots", where);
      const unsigned int needed = knots.size() - degree - 1;
      if (x.size() != needed)
        throw InputError(where,
                         "control points: " + std::to_string(x.size()) +
                           ", where its " + std::to_string(knots.size()) +
                           " knots and degree " + std::to_string(degree) +
                           " make " + std::to_string(needed) + " functions");

      NurbsCurveShape curve;
      curve.basis   = BSplineBasis(degree, knots);
      curve.weights = w;
      double size   = 0.;
      for (unsigned int k = 0; k < x.size(); ++k)
        {
          curve.points.emplace_back(x[k], y[k]);
          size = std::max(size, curve.points.back().norm());
        }
      size = std::max(size, 1e-300);
      curve.closed =
        (curve.points.front() - curve.points.back()).norm() <= 1e-12 * size;

      // The tangent at Gauss points of every span, and its direction at
      // each span's ends against the next span's.
      const QGauss<1>    rule(degree + 2);
      const unsigned int n_spans = curve.basis.n_spans();
      const auto         direction =
        [&](const unsigned int span, const double u, const std::string &what) {
          const Tensor<1, 2> d = curve_at(curve, span, u).first;
          if (!(d.norm() > 1e-12 * size))
            {
              std::ostringstream message;
              message << "the curve's tangent vanishes at u = " << u << " ("
                      << what << "): control points that coincide there";
              throw InputError(where, message.str());
            }
          return d / d.norm();
        };
      for (unsigned int s = 0; s < n_spans; ++s)
        {
          const auto range = curve.basis.span_range(s);
          for (unsigned int q = 0; q < rule.size(); ++q)
            direction(s,
                      range[0] + rule.point(q)[0] * (range[1] - range[0]),
                      "inside a span");
          if (s + 1 < n_spans || curve.closed)
            {
              const unsigned int next = (s + 1) % n_spans;
              const Tensor<1, 2> before =
                direction(s, range[1], "a span's end");
              const Tensor<1, 2> after =
                direction(next,
                          curve.basis.span_range(next)[0],
                          "a span's start");
              const double turn =
                std::atan2(before[0] * after[1] - before[1] * after[0],
                           before * after);
              if (std::abs(turn) > 1e-8)
                {
                  std::ostringstream message;
                  message << "the curve has a corner at u = " << range[1]
                          << (s + 1 < n_spans ? "" : " (its closing point)")
                          << ": its tangent turns by " << turn * 180. / M_PI
                          << " degrees there, which a rigid obstacle's normal "
                             "cannot turn through (round it off, or make the "
                             "control points on both sides of the knot "
                             "collinear)";
                  throw InputError(where, message.str());
                }
            }
        }
      return curve;
    }



    /**
     * The obstacle: its curve where the file has it, moved by the pair's
     * Motion and turned by its Rotation about Point. The closest point of
     * a node: each span sampled at 2p + 3 points, then Newton's method on
     * (C(u) - x) . C'(u) = 0 from the nearest sample inside the span, the
     * nearest of the spans' answers; beyond an open end, no counterpart.
     * Walking along the curve, the obstacle is on the right: n = e3 x t
     * points out of it.
     */
    class NurbsCurveObstacle : public RigidObstacle
    {
    public:
      explicit NurbsCurveObstacle(const SurfaceContext &context)
        : RigidObstacle(context.description)
        , curve(*std::any_cast<std::shared_ptr<const NurbsCurveShape>>(
            context.description.surface_settings))
        , alert_distance(context.description.alert_distance)
      {
        for (const auto &P : curve.points)
          size = std::max(size, P.norm());
      }

      SurfacePoint
      project(const Point<2> &x, const SegmentHint &keep) const override
      {
        // (in the curve's own frame, where the file has it)
        const Point<2>     X    = reference() + rotated(x - position, -angle);
        double             best = std::numeric_limits<double>::max();
        unsigned int       best_span = 0;
        double             best_u    = 0.;
        const unsigned int samples   = 2 * curve.basis.degree() + 3;
        for (unsigned int s = 0; s < curve.basis.n_spans(); ++s)
          {
            const auto range = curve.basis.span_range(s);
            double u = range[0], nearest = std::numeric_limits<double>::max();
            for (unsigned int k = 0; k <= samples; ++k)
              {
                const double v = range[0] + (range[1] - range[0]) * k / samples;
                const double d =
                  (curve_at(curve, s, v).point - X).norm_square();
                if (d < nearest)
                  {
                    nearest = d;
                    u       = v;
                  }
              }
            for (unsigned int k = 0; k < 50; ++k)
              {
                const CurveSample  c  = curve_at(curve, s, u);
                const Tensor<1, 2> r  = c.point - X;
                const double       f  = r * c.first;
                const double       df = c.first * c.first + r * c.second;
                const double       step =
                  df > 0. ? -f / df : -f / (c.first * c.first);
                const double next  = std::clamp(u + step, range[0], range[1]);
                const double moved = std::abs(next - u);
                u                  = next;
                if (moved <= 1e-15 * (range[1] - range[0]))
                  break;
              }
            const double d = (curve_at(curve, s, u).point - X).norm_square();
            if (d < best)
              {
                best      = d;
                best_span = s;
                best_u    = u;
              }
          }
        const CurveSample  c     = curve_at(curve, best_span, best_u);
        const double       speed = c.first.norm();
        const Tensor<1, 2> t     = c.first / speed;
        const Tensor<1, 2> n({-t[1], t[0]});
        // Beyond an open end the nearest point is the end, where x does not
        // lie on its normal: no counterpart there (the end's tangent line
        // continued to x's foot is what mortar may integrate against). A
        // node that slid past the end within the increment after holding
        // contact there (`held`: ContactPair::update_geometry) keeps the
        // tangent line, up to the alert distance or half the end span's
        // chord past the end, whichever is shorter, until the increment
        // ends: else a node whose equilibrium is at the end
        // (the edge of a table a block is pushed off) slides off, comes
        // back behind the obstacle and slides off again at every Newton
        // iteration. A deformable master's end segments are kept the same
        // way.
        const auto  &knots = curve.basis.knots();
        const double past  = std::abs((X - c.point) * t);
        if (!curve.closed &&
            (best_u == knots.front() || best_u == knots.back()) &&
            past > 1e-10 * std::max(size, 1.))
          {
            const Point<2> foot = c.point + ((X - c.point) * t) * t;
            SurfacePoint   p =
              point(x,
                    position + rotated(foot - reference(), angle),
                    rotated(n, angle),
                    speed,
                    Tensor<1, 2>());
            const auto   span = curve.basis.span_range(best_span);
            const double half_chord =
              0.5 * (curve_at(curve, best_span, span[1]).point -
                     curve_at(curve, best_span, span[0]).point)
                      .norm();
            p.valid = keep.held && past <= std::min(half_chord, alert_distance);
            p.beyond_open_end = !p.valid;
            p.segment         = best_span;
            p.s               = best_u;
            return p;
          }
        SurfacePoint p = point(x,
                               position + rotated(c.point - reference(), angle),
                               rotated(n, angle),
                               speed,
                               rotated(c.second, angle));
        p.segment      = best_span;
        p.s            = best_u;
        return p;
      }

      std::vector<Point<2>>
      open_ends() const override
      {
        if (curve.closed)
          return {};
        const unsigned int    last = curve.basis.n_spans() - 1;
        std::vector<Point<2>> ends;
        for (const auto &[span, u] :
             {std::make_pair(0u, curve.basis.span_range(0)[0]),
              std::make_pair(last, curve.basis.span_range(last)[1])})
          ends.push_back(
            position +
            rotated(curve_at(curve, span, u).point - reference(), angle));
        return ends;
      }

      std::vector<Point<2>>
      outline(const Point<2> &, const double) const override
      {
        std::vector<Point<2>> points;
        for (unsigned int s = 0; s < curve.basis.n_spans(); ++s)
          {
            const auto range = curve.basis.span_range(s);
            for (unsigned int k = (s == 0 ? 0 : 1); k <= 16; ++k)
              points.push_back(
                position +
                rotated(
                  curve_at(curve, s, range[0] + (range[1] - range[0]) * k / 16.)
                      .point -
                    reference(),
                  angle));
          }
        return points;
      }

    private:
      const NurbsCurveShape &curve;
      /** How far past an open end a held node keeps the end's tangent. */
      const double alert_distance;
      double       size = 0.;
    };
  } // namespace



  std::unique_ptr<MasterSurface>
  make_nurbs_curve_obstacle(const SurfaceContext &context)
  {
    return std::make_unique<NurbsCurveObstacle>(context);
  }



  void
  declare_nurbs_curve_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Curve file",
                      "",
                      Patterns::Anything(),
                      "nurbs curve: the obstacle's boundary, a NURBS curve "
                      "file (doc/user_guide.md, 'NURBS curve files'; a "
                      "relative path is beside this .prm), where it is at "
                      "t = 0, the obstacle on its right.");
  }



  std::any
  parse_nurbs_curve_parameters(const ParameterHandler &prm,
                               const std::string      &where,
                               const std::string      &prm_file)
  {
    const std::string file = text::trim(prm.get("Curve file"));
    if (file.empty())
      throw InputError(where + "/Curve file",
                       "a 'nurbs curve' obstacle needs its curve file");
    return std::shared_ptr<const NurbsCurveShape>(
      std::make_shared<NurbsCurveShape>(read_curve_file(
        text::path_beside(prm_file, file), where + "/Curve file")));
  }
} // namespace glissade
