// NURBS patch files (include/glissade/mesh/nurbs_patch_file.h).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/mesh/graded_intervals.h>
#include <glissade/mesh/nurbs_patch_file.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    const std::array<std::string, 4> side_keys = {
      {"xi0", "xi1", "eta0", "eta1"}};

    /** The lines of a file without comments and blank lines, numbered. */
    std::vector<std::pair<unsigned int, std::string>>
    meaningful_lines(const std::string &file, const std::string &where)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(where,
                         "cannot open the NURBS patch file '" + file + "'");
      std::vector<std::pair<unsigned int, std::string>> lines;
      std::string                                       line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          line = line.substr(0, line.find('#'));
          if (line.find_first_not_of(" \t\r") != std::string::npos)
            lines.emplace_back(number, line);
        }
      return lines;
    }

    /** A knot vector's checks: non-decreasing, open, long enough. */
    void
    check_knots(const std::vector<double> &knots,
                const unsigned int         degree,
                const std::string         &direction,
                const std::string         &where)
    {
      const std::string what = "knots " + direction + ": ";
      if (knots.size() < 2 * degree + 2)
        throw InputError(where,
                         what + std::to_string(knots.size()) +
                           " knots; degree " + std::to_string(degree) +
                           " needs at least " + std::to_string(2 * degree + 2));
      for (unsigned int k = 1; k < knots.size(); ++k)
        if (!(knots[k] >= knots[k - 1]))
          throw InputError(where,
                           what + "knot " + std::to_string(k + 1) +
                             " is below the one before it (knots must not "
                             "decrease)");
      for (unsigned int k = 1; k <= degree; ++k)
        if (knots[k] != knots[0] || knots[knots.size() - 1 - k] != knots.back())
          throw InputError(where,
                           what +
                             "the first and last knots must each be "
                             "repeated degree + 1 = " +
                             std::to_string(degree + 1) +
                             " times (an open knot vector)");
      if (!(knots.back() > knots.front()))
        throw InputError(where, what + "the knots span no parameter range");
      // (a knot repeated more than p times inside would cut the patch in
      // two: its functions would not be continuous)
      for (unsigned int k = degree + 1, run = 1; k + degree + 1 < knots.size();
           ++k)
        {
          if (knots[k] == knots.front() || knots[k] == knots.back())
            throw InputError(where,
                             what +
                               "an end knot is repeated more than "
                               "degree + 1 = " +
                               std::to_string(degree + 1) + " times");
          run = knots[k] == knots[k - 1] ? run + 1 : 1;
          if (run > degree)
            {
              std::ostringstream message;
              message << what << "the inner knot " << knots[k]
                      << " is repeated " << run
                      << " times, more than the degree: the patch would not "
                         "be continuous there";
              throw InputError(where, message.str());
            }
        }
    }
  } // namespace



  NurbsPatchFile
  NurbsPatchFile::read(const std::string &file, const std::string &entry)
  {
    const std::string                  where = entry + " ('" + file + "')";
    const auto                         lines = meaningful_lines(file, where);
    NurbsPatchFile                     result;
    std::array<unsigned int, 2>        degrees{{0, 0}};
    std::array<std::vector<double>, 2> knots;
    std::array<unsigned int, 2>        counts{{0, 0}};
    std::vector<std::array<double, 3>> control;
    bool                               have_degrees = false;
    for (unsigned int i = 0; i < lines.size(); ++i)
      {
        const auto &[number, text] = lines[i];
        const std::string  at      = where + ", line " + std::to_string(number);
        std::istringstream words(text);
        std::string        key;
        words >> key;
        if (key == "degrees")
          {
            int p = 0, q = 0;
            if (!(words >> p >> q) || p < 1 || q < 1)
              throw InputError(at, "expected 'degrees p q' with p, q >= 1");
            degrees      = {{unsigned(p), unsigned(q)}};
            have_degrees = true;
          }
        else if (key == "knots")
          {
            std::string direction;
            words >> direction;
            if (direction != "xi" && direction != "eta")
              throw InputError(at,
                               "expected 'knots xi ...' or 'knots eta ...'");
            auto &k = knots[direction == "xi" ? 0 : 1];
            k.clear();
            for (double u; words >> u;)
              k.push_back(u);
            if (!words.eof())
              throw InputError(at, "a knot is not a number");
          }
        else if (key == "control")
          {
            std::string points;
            int         n_xi = 0, n_eta = 0;
            if (!(words >> points >> n_xi >> n_eta) || points != "points" ||
                n_xi < 1 || n_eta < 1)
              throw InputError(at, "expected 'control points n_xi n_eta'");
            counts = {{unsigned(n_xi), unsigned(n_eta)}};
            for (unsigned int k = 0; k < counts[0] * counts[1]; ++k)
              {
                if (i + 1 >= lines.size())
                  throw InputError(at,
                                   "the file ends after " + std::to_string(k) +
                                     " of the " +
                                     std::to_string(counts[0] * counts[1]) +
                                     " control points");
                ++i;
                std::istringstream point(lines[i].second);
                double             x, y, w;
                std::string        rest;
                const std::string  line_at =
                  where + ", line " + std::to_string(lines[i].first);
                if (!(point >> x >> y >> w) || (point >> rest))
                  throw InputError(line_at,
                                   "control point " + std::to_string(k + 1) +
                                     ": expected 'x y w'");
                if (!(w > 0.) || !std::isfinite(w) || !std::isfinite(x) ||
                    !std::isfinite(y))
                  throw InputError(line_at,
                                   "control point " + std::to_string(k + 1) +
                                     ": the weight must be positive and the "
                                     "numbers finite");
                control.push_back({{w * x, w * y, w}});
              }
          }
        else if (key == "boundary")
          {
            std::string name, side;
            if (!(words >> name >> side))
              throw InputError(at, "expected 'boundary <name> <side>'");
            unsigned int s = 0;
            while (s < 4 && side_keys[s] != side)
              ++s;
            if (s == 4)
              throw InputError(at,
                               "side '" + side +
                                 "' is none of xi0, xi1, eta0, eta1");
            result.side_names[s] = name;
          }
        else
          throw InputError(at,
                           "'" + key +
                             "' is not one of degrees, knots, control points, "
                             "boundary");
      }
    if (!have_degrees || knots[0].empty() || knots[1].empty() ||
        control.empty())
      throw InputError(where,
                       "a patch needs 'degrees', 'knots xi', 'knots eta' and "
                       "'control points'");
    for (unsigned int d = 0; d < 2; ++d)
      {
        const std::string direction = d == 0 ? "xi" : "eta";
        check_knots(knots[d], degrees[d], direction, where);
        const unsigned int needed = knots[d].size() - degrees[d] - 1;
        if (counts[d] != needed)
          throw InputError(where,
                           "control points: " + std::to_string(counts[d]) +
                             " along " + direction + ", where its " +
                             std::to_string(knots[d].size()) +
                             " knots and degree " + std::to_string(degrees[d]) +
                             " make " + std::to_string(needed) + " functions");
      }
    result.patch =
      NurbsPatch::from_homogeneous(BSplineBasis(degrees[0], knots[0]),
                                   BSplineBasis(degrees[1], knots[1]),
                                   control);

    // The Jacobian at every element's Gauss points: positive, or the patch
    // is inverted (clockwise) or folded there.
    const QGauss<1>        rule(std::max(degrees[0], degrees[1]) + 2);
    NurbsPatch::Evaluation e;
    for (unsigned int b = 0; b < result.patch.eta.n_spans(); ++b)
      for (unsigned int a = 0; a < result.patch.xi.n_spans(); ++a)
        {
          const auto u = result.patch.xi.span_range(a);
          const auto v = result.patch.eta.span_range(b);
          for (unsigned int j = 0; j < rule.size(); ++j)
            for (unsigned int i = 0; i < rule.size(); ++i)
              {
                const double s = u[0] + rule.point(i)[0] * (u[1] - u[0]);
                const double t = v[0] + rule.point(j)[0] * (v[1] - v[0]);
                result.patch.evaluate(a, b, s, t, e);
                const double J = determinant(e.jacobian);
                if (!(J > 0.))
                  {
                    std::ostringstream message;
                    message
                      << "the patch is inverted or folded in its element (" << a
                      << ", " << b << ") (xi and eta spans from 0): "
                      << "det J = " << J << " at (xi, eta) = (" << s << ", "
                      << t
                      << "); (xi, eta) must turn counterclockwise, as "
                         "(x, y) do";
                    throw InputError(where, message.str());
                  }
              }
        }
    return result;
  }



  void
  NurbsPatchFile::refine(const std::array<unsigned int, 2> &subdivisions,
                         const std::array<double, 2>       &grading)
  {
    for (unsigned int d = 0; d < 2; ++d)
      {
        const BSplineBasis        basis = d == 0 ? patch.xi : patch.eta;
        const std::vector<double> ends =
          graded_interval_ends(subdivisions[d], grading[d]);
        for (unsigned int s = 0; s < basis.n_spans(); ++s)
          {
            const auto range = basis.span_range(s);
            for (unsigned int k = 1; k < subdivisions[d]; ++k)
              patch.insert_knot(d, range[0] + (range[1] - range[0]) * ends[k]);
          }
      }
  }



  BoundaryNames
  NurbsPatchFile::create_mesh(Triangulation<2> &mesh) const
  {
    const unsigned int    n_u = patch.xi.n_spans(), n_v = patch.eta.n_spans();
    std::vector<Point<2>> vertices;
    for (unsigned int b = 0; b <= n_v; ++b)
      for (unsigned int a = 0; a <= n_u; ++a)
        {
          const unsigned int span_a = std::min(a, n_u - 1),
                             span_b = std::min(b, n_v - 1);
          vertices.push_back(
            patch.point(span_a,
                        span_b,
                        patch.xi.span_range(span_a)[a == n_u ? 1 : 0],
                        patch.eta.span_range(span_b)[b == n_v ? 1 : 0]));
        }
    std::vector<CellData<2>> cells;
    for (unsigned int b = 0; b < n_v; ++b)
      for (unsigned int a = 0; a < n_u; ++a)
        {
          CellData<2> cell;
          const auto  vertex = [&](const unsigned int i, const unsigned int j) {
            return (b + j) * (n_u + 1) + (a + i);
          };
          cell.vertices = {vertex(0, 0),
                           vertex(1, 0),
                           vertex(0, 1),
                           vertex(1, 1)};
          cells.push_back(cell);
        }
    mesh.create_triangulation(vertices, cells, SubCellData());
    // deal.II's faces 0 to 3 are x = 0, x = 1, y = 0, y = 1 of the unit
    // cell: the sides xi0, xi1, eta0, eta1 where they are on the boundary.
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(f);
    BoundaryNames names;
    for (unsigned int s = 0; s < 4; ++s)
      {
        if (names.count(side_names[s]))
          throw InputError("",
                           "two sides of the patch are named '" +
                             side_names[s] + "'");
        names[side_names[s]] = s;
      }
    return names;
  }
} // namespace glissade
