// NURBS patch files (include/glissade/mesh/nurbs_patch_file.h).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>

#include <glissade/base/input_error.h>
#include <glissade/mesh/graded_intervals.h>
#include <glissade/mesh/nurbs_patch_file.h>

#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    const std::array<std::string, 4> &side_keys = patch_side_keys();

  } // namespace



  std::vector<std::pair<unsigned int, std::string>>
  meaningful_lines(const std::string &file,
                   const std::string &kind,
                   const std::string &where)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError(where, "cannot open the " + kind + " '" + file + "'");
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



  void
  check_knot_vector(const std::vector<double> &knots,
                    const unsigned int         degree,
                    const std::string         &label,
                    const std::string         &where)
  {
    const std::string what = label + ": ";
    if (knots.size() < 2 * degree + 2)
      throw InputError(where,
                       what + std::to_string(knots.size()) + " knots; degree " +
                         std::to_string(degree) + " needs at least " +
                         std::to_string(2 * degree + 2));
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
            message << what << "the inner knot " << knots[k] << " is repeated "
                    << run
                    << " times, more than the degree: the patch would not "
                       "be continuous there";
            throw InputError(where, message.str());
          }
      }
  }



  std::array<double, 3>
  read_control_point(const std::string &line,
                     const unsigned int k,
                     const std::string &where)
  {
    std::istringstream point(line);
    double             x, y, w;
    std::string        extra;
    if (!(point >> x >> y >> w) || (point >> extra))
      throw InputError(where,
                       "control point " + std::to_string(k + 1) +
                         ": expected 'x y w'");
    if (!(w > 0.) || !std::isfinite(w) || !std::isfinite(x) ||
        !std::isfinite(y))
      throw InputError(where,
                       "control point " + std::to_string(k + 1) +
                         ": the weight must be positive and the numbers "
                         "finite");
    return {{x, y, w}};
  }



  namespace
  {
    /** One patch's lines as read, before its checks. */
    struct PatchLines
    {
      std::array<unsigned int, 2>        degrees{{0, 0}};
      bool                               have_degrees = false;
      std::array<std::vector<double>, 2> knots;
      std::array<unsigned int, 2>        counts{{0, 0}};
      std::vector<std::array<double, 3>> control;
    };

    /** The side named by `key` (xi0, xi1, eta0, eta1). */
    unsigned int
    side_of(const std::string &key, const std::string &at)
    {
      for (unsigned int s = 0; s < 4; ++s)
        if (side_keys[s] == key)
          return s;
      throw InputError(at,
                       "side '" + key + "' is none of xi0, xi1, eta0, eta1");
    }

    /** A patch number of a multi-patch line, from 1. */
    unsigned int
    patch_of(const std::string &word,
             const unsigned int n_patches,
             const std::string &at)
    {
      std::size_t  end = 0;
      unsigned int k   = 0;
      try
        {
          k = std::stoul(word, &end);
        }
      catch (const std::exception &)
        {
          end = 0;
        }
      if (end != word.size() || k < 1 || k > n_patches)
        throw InputError(at,
                         "'" + word + "' is not a patch of the file (1 to " +
                           std::to_string(n_patches) + ")");
      return k - 1;
    }

    /** The patch of `lines`, checked; `where` names it in the messages. */
    NurbsPatch
    checked_patch(const PatchLines &lines, const std::string &where)
    {
      const auto &[degrees, have_degrees, knots, counts, control] = lines;
      if (!have_degrees || knots[0].empty() || knots[1].empty() ||
          control.empty())
        throw InputError(where,
                         "a patch needs 'degrees', 'knots xi', 'knots eta' "
                         "and 'control points'");
      for (unsigned int d = 0; d < 2; ++d)
        {
          const std::string direction = d == 0 ? "xi" : "eta";
          check_knot_vector(knots[d], degrees[d], "knots " + direction, where);
          const unsigned int needed = knots[d].size() - degrees[d] - 1;
          if (counts[d] != needed)
            throw InputError(where,
                             "control points: " + std::to_string(counts[d]) +
                               " along " + direction + ", where its " +
                               std::to_string(knots[d].size()) +
                               " knots and degree " +
                               std::to_string(degrees[d]) + " make " +
                               std::to_string(needed) + " functions");
        }
      NurbsPatch patch =
        NurbsPatch::from_homogeneous(BSplineBasis(degrees[0], knots[0]),
                                     BSplineBasis(degrees[1], knots[1]),
                                     control);

      // The Jacobian at every element's Gauss points: positive, or the
      // patch is inverted (clockwise) or folded there.
      const QGauss<1>        rule(std::max(degrees[0], degrees[1]) + 2);
      NurbsPatch::Evaluation e;
      for (unsigned int b = 0; b < patch.eta.n_spans(); ++b)
        for (unsigned int a = 0; a < patch.xi.n_spans(); ++a)
          {
            const auto u = patch.xi.span_range(a);
            const auto v = patch.eta.span_range(b);
            for (unsigned int j = 0; j < rule.size(); ++j)
              for (unsigned int i = 0; i < rule.size(); ++i)
                {
                  const double s = u[0] + rule.point(i)[0] * (u[1] - u[0]);
                  const double t = v[0] + rule.point(j)[0] * (v[1] - v[0]);
                  patch.evaluate(a, b, s, t, e);
                  const double J = determinant(e.jacobian);
                  if (!(J > 0.))
                    {
                      std::ostringstream message;
                      message << "the patch is inverted or folded in its "
                                 "element ("
                              << a << ", " << b
                              << ") (xi and eta spans from 0): det J = " << J
                              << " at (xi, eta) = (" << s << ", " << t
                              << "); (xi, eta) must turn counterclockwise, "
                                 "as (x, y) do";
                      throw InputError(where, message.str());
                    }
                }
          }
      return patch;
    }
  } // namespace



  NurbsPatchFile
  NurbsPatchFile::read(const std::string &file, const std::string &entry)
  {
    NurbsPatchFile result;
    result.where     = entry + " ('" + file + "')";
    const auto lines = meaningful_lines(file, "NURBS patch file", result.where);
    std::vector<PatchLines> patches(1);
    // (boundary and join lines are read once the patches are known)
    std::vector<std::pair<std::string, std::vector<std::string>>> boundaries,
      joins;
    bool begun = false;
    for (unsigned int i = 0; i < lines.size(); ++i)
      {
        const auto &[number, text] = lines[i];
        const std::string at =
          result.where + ", line " + std::to_string(number);
        std::istringstream words(text);
        std::string        key;
        words >> key;
        std::vector<std::string> rest;
        PatchLines              &patch = patches.back();
        if (key == "patch")
          {
            // (the first patch of a file may go without its line)
            if (begun)
              patches.emplace_back();
            begun = true;
          }
        else if (key == "degrees")
          {
            int p = 0, q = 0;
            if (!(words >> p >> q) || p < 1 || q < 1)
              throw InputError(at, "expected 'degrees p q' with p, q >= 1");
            patch.degrees      = {{unsigned(p), unsigned(q)}};
            patch.have_degrees = true;
            begun              = true;
          }
        else if (key == "knots")
          {
            std::string direction;
            words >> direction;
            if (direction != "xi" && direction != "eta")
              throw InputError(at,
                               "expected 'knots xi ...' or 'knots eta ...'");
            auto &k = patch.knots[direction == "xi" ? 0 : 1];
            k.clear();
            for (double u; words >> u;)
              k.push_back(u);
            if (!words.eof())
              throw InputError(at, "a knot is not a number");
            begun = true;
          }
        else if (key == "control")
          {
            std::string points;
            int         n_xi = 0, n_eta = 0;
            if (!(words >> points >> n_xi >> n_eta) || points != "points" ||
                n_xi < 1 || n_eta < 1)
              throw InputError(at, "expected 'control points n_xi n_eta'");
            patch.counts = {{unsigned(n_xi), unsigned(n_eta)}};
            patch.control.clear();
            for (unsigned int k = 0; k < patch.counts[0] * patch.counts[1]; ++k)
              {
                if (i + 1 >= lines.size())
                  throw InputError(at,
                                   "the file ends after " + std::to_string(k) +
                                     " of the " +
                                     std::to_string(patch.counts[0] *
                                                    patch.counts[1]) +
                                     " control points");
                ++i;
                const auto [x, y, w] =
                  read_control_point(lines[i].second,
                                     k,
                                     result.where + ", line " +
                                       std::to_string(lines[i].first));
                patch.control.push_back({{w * x, w * y, w}});
              }
            begun = true;
          }
        else if (key == "boundary" || key == "join")
          {
            for (std::string word; words >> word;)
              rest.push_back(word);
            (key == "boundary" ? boundaries : joins).emplace_back(at, rest);
          }
        else
          throw InputError(at,
                           "'" + key +
                             "' is not one of patch, degrees, knots, control "
                             "points, boundary, join");
      }

    const unsigned int n = patches.size();
    for (unsigned int k = 0; k < n; ++k)
      result.geometry.patches.push_back(
        checked_patch(patches[k],
                      n == 1 ?
                        result.where :
                        result.where + ", patch " + std::to_string(k + 1)));
    result.side_names.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int s = 0; s < 4; ++s)
        result.side_names[k][s] =
          n == 1 ? side_keys[s] :
                   "patch" + std::to_string(k + 1) + "." + side_keys[s];

    for (const auto &[at, words] : joins)
      {
        if (words.size() != 4)
          throw InputError(at,
                           "expected 'join <patch> <side> <patch> <side>' "
                           "(as 'join 1 xi1 2 xi0')");
        std::array<PatchSide, 2> join;
        for (unsigned int m = 0; m < 2; ++m)
          join[m] = {patch_of(words[2 * m], n, at),
                     side_of(words[2 * m + 1], at)};
        result.geometry.joins.push_back(join);
        for (const PatchSide &side : join)
          result.side_names[side.patch][side.side].clear();
      }
    // The joins on the file's own patches, before any refinement: a
    // mistake is told against the file's knots.
    result.geometry.number_controls(result.where);
    for (const auto &[at, words] : boundaries)
      {
        std::vector<PatchSide> sides;
        if (n == 1 && words.size() == 2)
          sides.push_back({0, side_of(words[1], at)});
        else if (words.size() >= 3 && words.size() % 2 == 1)
          for (unsigned int m = 1; m < words.size(); m += 2)
            sides.push_back(
              {patch_of(words[m], n, at), side_of(words[m + 1], at)});
        else
          throw InputError(at,
                           n == 1 ? "expected 'boundary <name> <side>'" :
                                    "expected 'boundary <name> <patch> <side> "
                                    "...' (as 'boundary outer 1 eta1 2 "
                                    "eta1'): a file of several patches names "
                                    "the patch of each side");
        for (const PatchSide &side : sides)
          {
            if (result.side_names[side.patch][side.side].empty())
              throw InputError(at,
                               describe(side) +
                                 " is joined to another patch: it is inside "
                                 "the body, not on its boundary");
            result.side_names[side.patch][side.side] = words[0];
          }
      }
    return result;
  }



  void
  NurbsPatchFile::refine(const std::array<unsigned int, 2> &subdivisions,
                         const std::array<double, 2>       &grading)
  {
    for (NurbsPatch &patch : geometry.patches)
      {
        patch.body_numbers.clear();
        for (unsigned int d = 0; d < 2; ++d)
          {
            const BSplineBasis        basis = d == 0 ? patch.xi : patch.eta;
            const std::vector<double> ends =
              graded_interval_ends(subdivisions[d], grading[d]);
            for (unsigned int s = 0; s < basis.n_spans(); ++s)
              {
                const auto range = basis.span_range(s);
                for (unsigned int k = 1; k < subdivisions[d]; ++k)
                  patch.insert_knot(d,
                                    range[0] + (range[1] - range[0]) * ends[k]);
              }
          }
      }
    geometry.number_controls(where + " with Mesh/Subdivisions and Grading");
  }



  BoundaryNames
  NurbsPatchFile::create_mesh(Triangulation<2> &mesh) const
  {
    // Each patch's knot points, patch after patch; a point of a joined
    // side (or where patches touch) kept once.
    std::vector<Point<2>>    vertices;
    std::vector<CellData<2>> cells;
    double                   size = 1.;
    for (const NurbsPatch &patch : geometry.patches)
      {
        const unsigned int n_u = patch.xi.n_spans(), n_v = patch.eta.n_spans();
        const unsigned int first = vertices.size();
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
              size = std::max(size, vertices.back().norm());
            }
        for (unsigned int b = 0; b < n_v; ++b)
          for (unsigned int a = 0; a < n_u; ++a)
            {
              CellData<2> cell;
              const auto  vertex = [&](const unsigned int i,
                                      const unsigned int j) {
                return first + (b + j) * (n_u + 1) + (a + i);
              };
              cell.vertices = {vertex(0, 0),
                               vertex(1, 0),
                               vertex(0, 1),
                               vertex(1, 1)};
              cells.push_back(cell);
            }
      }
    if (geometry.patches.size() > 1)
      {
        SubCellData               no_subcells;
        std::vector<unsigned int> all(vertices.size());
        std::iota(all.begin(), all.end(), 0u);
        GridTools::delete_duplicated_vertices(
          vertices, cells, no_subcells, all, 1e-9 * size);
      }
    mesh.create_triangulation(vertices, cells, SubCellData());

    // Names to ids, in the order of the patches' sides.
    BoundaryNames names;
    if (geometry.patches.size() == 1)
      for (unsigned int s = 0; s < 4; ++s)
        {
          if (names.count(side_names[0][s]))
            throw InputError(where,
                             "two sides of the patch are named '" +
                               side_names[0][s] + "'");
          names[side_names[0][s]] = s;
        }
    else
      for (const auto &sides : side_names)
        for (const std::string &name : sides)
          if (!name.empty() && !names.count(name))
            {
              const types::boundary_id id = names.size();
              names[name]                 = id;
            }

    // deal.II's faces 0 to 3 are x = 0, x = 1, y = 0, y = 1 of the unit
    // cell: on a patch's element, the sides xi0, xi1, eta0, eta1 where the
    // element is at them. Two patches meet only where a join says so.
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const unsigned int patch =
          geometry.cell_span(cell->active_cell_index()).patch;
        for (const unsigned int f : cell->face_indices())
          {
            const std::string &name = side_names[patch][f];
            if (cell->face(f)->at_boundary())
              {
                if (name.empty())
                  throw InputError(where,
                                   describe(PatchSide{patch, f}) +
                                     " is joined, but an element of it is on "
                                     "the boundary of the body");
                cell->face(f)->set_boundary_id(names.at(name));
              }
            else if (geometry.cell_span(cell->neighbor(f)->active_cell_index())
                         .patch != patch &&
                     !name.empty())
              throw InputError(
                where,
                describe(PatchSide{patch, f}) + " touches patch " +
                  std::to_string(
                    geometry.cell_span(cell->neighbor(f)->active_cell_index())
                      .patch +
                    1) +
                  " where no 'join' line joins them: their "
                  "control points there would be two, and "
                  "the displacement not continuous");
          }
      }
    return names;
  }
} // namespace glissade
