// Helpers of the master curve test program surface_tests: a check printer,
// a deterministic random generator, a dense solver used as an independent
// reference, the point sets the tests use and the kinds of curve they run
// over.
#pragma once

#include <glissade/contact/curves/bspline_curve.h>
#include <glissade/contact/curves/faceted_curve.h>
#include <glissade/contact/curves/hermite_curve.h>

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "../harness.h"

namespace surface_test_tools
{
  using namespace glissade;
  using Point = MasterCurve::Point;

  inline const double pi = std::acos(-1.);

  // ---------------------------------------------------------------- helpers
  // Print the figure being checked as a line of the table
  // (glissade_tests::expect: counted, the test goes on).
  inline void
  check(const bool ok, const char *format, ...)
  {
    char    text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof(text), format, args);
    va_end(args);
    glissade_tests::expect(ok, text);
  }

  // A deterministic generator (splitmix64), so the point sets are the same
  // with every standard library.
  struct Random
  {
    std::uint64_t state;
    explicit Random(std::uint64_t seed)
      : state(seed)
    {}
    double
    uniform(double a = 0., double b = 1.)
    {
      std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
      z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      z ^= z >> 31;
      return a + (b - a) * double(z >> 11) * 0x1.0p-53;
    }
  };

  inline double
  distance(const Point &a, const Point &b)
  {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
  }

  inline bool
  finite(const MasterCurve::Projection &p)
  {
    for (double v : {p.s,
                     p.point[0],
                     p.point[1],
                     p.tangent[0],
                     p.tangent[1],
                     p.normal[0],
                     p.normal[1],
                     p.gap,
                     p.distance})
      if (!std::isfinite(v))
        return false;
    return true;
  }

  // Dense Gaussian elimination with partial pivoting: solves M X = B for
  // several right hand sides (the columns of B), in place.
  inline void
  dense_solve(std::vector<std::vector<double>>  M,
              std::vector<std::vector<double>> &B)
  {
    const unsigned int n = M.size(), m = B[0].size();
    for (unsigned int c = 0; c < n; ++c)
      {
        unsigned int pivot = c;
        for (unsigned int r = c + 1; r < n; ++r)
          if (std::abs(M[r][c]) > std::abs(M[pivot][c]))
            pivot = r;
        std::swap(M[c], M[pivot]);
        std::swap(B[c], B[pivot]);
        for (unsigned int r = c + 1; r < n; ++r)
          {
            const double f = M[r][c] / M[c][c];
            if (f == 0.)
              continue;
            for (unsigned int k = c; k < n; ++k)
              M[r][k] -= f * M[c][k];
            for (unsigned int k = 0; k < m; ++k)
              B[r][k] -= f * B[c][k];
          }
      }
    for (unsigned int c = n; c-- > 0;)
      for (unsigned int k = 0; k < m; ++k)
        {
          double v = B[c][k];
          for (unsigned int j = c + 1; j < n; ++j)
            v -= M[c][j] * B[j][k];
          B[c][k] = v / M[c][c];
        }
  }

  // ------------------------------------------------------------ point sets
  // Random-ish smooth closed point set, clockwise (so the normal points out).
  inline std::vector<Point>
  closed_points(const unsigned int n, Random &random)
  {
    std::vector<Point> p(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = -2. * pi * (i + 0.3 * random.uniform(-1, 1)) / n;
        const double r =
          1. + 0.2 * std::sin(3. * t) + 0.02 * random.uniform(-1, 1);
        p[i] = {{r * std::cos(t) + 0.3, r * std::sin(t) - 0.1}};
      }
    return p;
  }

  // Random-ish smooth open point set (a wave from left to right).
  inline std::vector<Point>
  open_points(const unsigned int n, Random &random)
  {
    std::vector<Point> p(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double x = 2. * (i + 0.3 * random.uniform(-1, 1)) / (n - 1);
        p[i] = {{x, 0.3 * std::sin(3. * x) + 0.01 * random.uniform(-1, 1)}};
      }
    return p;
  }

  // Nodes on a circle of radius R, clockwise: the normal n = e3 x t points
  // out of the disc.
  inline std::vector<Point>
  circle_points(const unsigned int n, const double R)
  {
    std::vector<Point> p(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = -2. * pi * i / n;
        p[i]           = {{R * std::cos(t), R * std::sin(t)}};
      }
    return p;
  }

  // Exact circle tangents dx/ds for clockwise nodes spaced by h = 2 pi / n:
  // x(s) = R e(theta_i - h s), dx/ds = R h (sin theta, -cos theta).
  inline std::vector<Point>
  circle_tangents(const unsigned int n, const double R)
  {
    std::vector<Point> d(n);
    const double       h = 2. * pi / n;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = -2. * pi * i / n;
        d[i]           = {{R * h * std::sin(t), -R * h * std::cos(t)}};
      }
    return d;
  }

  // Hermite tangents for an arbitrary point set: centred differences
  // (one-sided at open ends); any tangents make a valid Hermite curve.
  inline std::vector<Point>
  difference_tangents(const std::vector<Point> &p, const bool closed)
  {
    const unsigned int n = p.size();
    std::vector<Point> d(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        unsigned int a = (i == 0 ? (closed ? n - 1 : 0) : i - 1);
        unsigned int b = (i == n - 1 ? (closed ? 0 : n - 1) : i + 1);
        const double f = (a == i || b == i) ? 1. : 0.5;
        d[i]           = {{f * (p[b][0] - p[a][0]), f * (p[b][1] - p[a][1])}};
      }
    return d;
  }

  // The kinds of master curve that the shared groups run over, in the order
  // they print: per kind its name, its interpolation order p (faceted 2,
  // cubic 4: the projection on a circle converges like h^p) and how it is
  // built over a point set (a Hermite curve takes the given tangents, or
  // else differences of the points). A new kind of curve is one row here.
  struct CurveKind
  {
    std::string  name;
    unsigned int order;
    std::unique_ptr<MasterCurve> (*make)(bool                      closed,
                                         const std::vector<Point> &p,
                                         const std::vector<Point> *tangents);
  };

  inline const std::vector<CurveKind> curve_kinds = {
    {"faceted",
     2,
     [](const bool                closed,
        const std::vector<Point> &p,
        const std::vector<Point> *) -> std::unique_ptr<MasterCurve> {
       auto c = std::make_unique<FacetedCurve>(closed);
       c->update(p);
       return c;
     }},
    {"bspline",
     4,
     [](const bool                closed,
        const std::vector<Point> &p,
        const std::vector<Point> *) -> std::unique_ptr<MasterCurve> {
       auto c = std::make_unique<BSplineCurve>(
         closed ? BSplineCurve::EndCondition::periodic :
                  BSplineCurve::EndCondition::double_vertex);
       c->update(p);
       return c;
     }},
    {"hermite",
     4,
     [](const bool                closed,
        const std::vector<Point> &p,
        const std::vector<Point> *tangents) -> std::unique_ptr<MasterCurve> {
       auto c = std::make_unique<HermiteCurve>(closed);
       c->update(p);
       c->set_node_tangents(tangents ? *tangents :
                                       difference_tangents(p, closed));
       return c;
     }}};

  // A curve of the given kind over a point set.
  inline std::unique_ptr<MasterCurve>
  make_curve(const CurveKind          &kind,
             const bool                closed,
             const std::vector<Point> &p,
             const std::vector<Point> *tangents = nullptr)
  {
    return kind.make(closed, p, tangents);
  }

  // The same, the kind by its name in curve_kinds.
  inline std::unique_ptr<MasterCurve>
  make_curve(const std::string        &kind,
             const bool                closed,
             const std::vector<Point> &p,
             const std::vector<Point> *tangents = nullptr)
  {
    for (const CurveKind &row : curve_kinds)
      if (row.name == kind)
        return make_curve(row, closed, p, tangents);
    throw std::invalid_argument("make_curve: no curve kind '" + kind + "'");
  }

  inline const char *
  kind_name(const bool closed)
  {
    return closed ? "closed" : "open";
  }
} // namespace surface_test_tools
