// NURBS bodies of several patches (include/glissade/mesh/nurbs_multipatch.h).

#include <glissade/base/input_error.h>
#include <glissade/mesh/nurbs_multipatch.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** A side's control points (a + n_xi b, the patch's own numbering), in
     *  the order of its moving parameter, and that parameter's knots. */
    struct SideNet
    {
      std::vector<unsigned int> controls;
      std::vector<double>       knots;
    };

    SideNet
    side_net(const NurbsPatch &patch, const unsigned int side)
    {
      const unsigned int  fixed = side / 2, at_end = side % 2;
      SideNet             net;
      const BSplineBasis &along = fixed == 0 ? patch.eta : patch.xi;
      const unsigned int  row =
        at_end ? (fixed == 0 ? patch.n_xi() : patch.n_eta()) - 1 : 0;
      for (unsigned int m = 0; m < along.n_functions(); ++m)
        net.controls.push_back(fixed == 0 ? row + patch.n_xi() * m :
                                            m + patch.n_xi() * row);
      net.knots = along.knots();
      return net;
    }

    /** The knots mapped onto [0, 1], reversed if asked. */
    std::vector<double>
    normalised(const std::vector<double> &knots, const bool reversed)
    {
      std::vector<double> result;
      const double        a = knots.front(), b = knots.back();
      for (const double k : knots)
        result.push_back((k - a) / (b - a));
      if (reversed)
        {
          std::reverse(result.begin(), result.end());
          for (double &k : result)
            k = 1. - k;
        }
      return result;
    }

    unsigned int
    root(std::vector<unsigned int> &parent, unsigned int i)
    {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    }
  } // namespace



  const std::array<std::string, 4> &
  patch_side_keys()
  {
    static const std::array<std::string, 4> keys = {
      {"xi0", "xi1", "eta0", "eta1"}};
    return keys;
  }



  std::string
  describe(const PatchSide &side)
  {
    return "patch " + std::to_string(side.patch + 1) + "'s side " +
           patch_side_keys()[side.side];
  }



  NurbsMultipatch::NurbsMultipatch(NurbsPatch patch)
  {
    patches.push_back(std::move(patch));
    n_body_controls = patches.front().n_unique_controls();
  }



  void
  NurbsMultipatch::number_controls(const std::string &where)
  {
    AssertThrow(!patches.empty(), ExcMessage("a body of no patch"));
    for (unsigned int i = 0; i < patches.size(); ++i)
      if (patches[i].xi.degree() != degree() ||
          patches[i].eta.degree() != degree())
        throw InputError(where,
                         "patch " + std::to_string(i + 1) + " is of degrees " +
                           std::to_string(patches[i].xi.degree()) + ", " +
                           std::to_string(patches[i].eta.degree()) +
                           ", patch 1 of " + std::to_string(degree()) +
                           " (a body's patches are all of one degree, the "
                           "same in both directions)");
    for (auto &patch : patches)
      patch.body_numbers.clear();
    if (patches.size() == 1 && joins.empty())
      {
        n_body_controls = patches.front().n_unique_controls();
        return;
      }

    // Each patch's own numbers, one after the other, then the joined
    // sides' points made one (union-find).
    std::vector<unsigned int> first(patches.size() + 1, 0);
    for (unsigned int i = 0; i < patches.size(); ++i)
      first[i + 1] = first[i] + patches[i].n_unique_controls();
    std::vector<unsigned int> parent(first.back());
    std::iota(parent.begin(), parent.end(), 0u);

    double size = 1.;
    for (const auto &patch : patches)
      for (const auto &X : patch.points)
        size = std::max(size, X.norm());
    const double tolerance = 1e-9 * size;

    std::vector<std::array<bool, 4>> joined(patches.size(),
                                            {{false, false, false, false}});
    for (const auto &[one, other] : joins)
      {
        for (const PatchSide &s : {one, other})
          {
            AssertThrow(s.patch < patches.size() && s.side < 4,
                        ExcMessage("a join names no side of the body"));
            if (joined[s.patch][s.side])
              throw InputError(where,
                               describe(s) + " is joined twice (a side "
                                             "joins one other side)");
            joined[s.patch][s.side] = true;
          }
        const std::string what =
          "the join of " + describe(one) + " and " + describe(other) + ": ";
        const NurbsPatch &P = patches[one.patch], &Q = patches[other.patch];
        const SideNet a = side_net(P, one.side), b = side_net(Q, other.side);
        if (a.controls.size() != b.controls.size())
          throw InputError(where,
                           what + "the sides have " +
                             std::to_string(a.controls.size()) + " and " +
                             std::to_string(b.controls.size()) +
                             " control points (joined sides must be the same "
                             "curve with the same knots: the Subdivisions "
                             "of each patch along them must agree)");
        const unsigned int n = a.controls.size();
        // The same curve from the same end or from the other: its ends
        // tell which, then the knots, the points and the weights.
        const auto ends_apart = [&](const bool reversed) {
          return std::max((P.points[a.controls[0]] -
                           Q.points[b.controls[reversed ? n - 1 : 0]])
                            .norm(),
                          (P.points[a.controls[n - 1]] -
                           Q.points[b.controls[reversed ? 0 : n - 1]])
                            .norm());
        };
        const bool reversed = ends_apart(true) < ends_apart(false);
        if (ends_apart(reversed) > tolerance)
          {
            std::ostringstream message;
            message << what
                    << "the sides do not meet: their ends are apart by up to "
                    << ends_apart(reversed);
            throw InputError(where, message.str());
          }
        const auto ka = normalised(a.knots, false),
                   kb = normalised(b.knots, reversed);
        for (unsigned int k = 0; k < ka.size(); ++k)
          if (std::abs(ka[k] - kb[k]) > 1e-10)
            {
              std::ostringstream message;
              message << what << "the knots along the sides differ (knot "
                      << k + 1 << ": " << ka[k] << " against " << kb[k]
                      << " on [0, 1]; the Subdivisions and Grading of each "
                         "patch along them must agree): the sides' "
                         "functions would not be the same, and the "
                         "displacement not continuous";
              throw InputError(where, message.str());
            }
        for (unsigned int m = 0; m < n; ++m)
          {
            const double apart =
              (P.points[a.controls[m]] -
               Q.points[b.controls[reversed ? n - 1 - m : m]])
                .norm();
            if (apart > tolerance)
              {
                std::ostringstream message;
                message << what << "the sides meet at their ends but are "
                        << "not the same curve: their control points " << m + 1
                        << " are " << apart << " apart";
                throw InputError(where, message.str());
              }
          }
        const double ratio = P.weights[a.controls[0]] /
                             Q.weights[b.controls[reversed ? n - 1 : 0]];
        for (unsigned int m = 0; m < n; ++m)
          {
            const double r = P.weights[a.controls[m]] /
                             Q.weights[b.controls[reversed ? n - 1 - m : m]];
            if (std::abs(r - ratio) > 1e-10 * ratio)
              {
                std::ostringstream message;
                message << what << "the weights of control point " << m + 1
                        << " along the sides are not in the proportion of "
                           "the first's ("
                        << r << " against " << ratio
                        << "): the sides are not the same curve";
                throw InputError(where, message.str());
              }
          }
        const auto unique_of = [](const NurbsPatch  &patch,
                                  const unsigned int i) {
          return patch.unique_control(i % patch.n_xi(), i / patch.n_xi());
        };
        for (unsigned int m = 0; m < n; ++m)
          {
            const unsigned int i =
              root(parent, first[one.patch] + unique_of(P, a.controls[m]));
            const unsigned int j =
              root(parent,
                   first[other.patch] +
                     unique_of(Q, b.controls[reversed ? n - 1 - m : m]));
            parent[std::max(i, j)] = std::min(i, j);
          }
      }

    // The body's numbers: the roots in order.
    std::vector<unsigned int> number(parent.size(), 0);
    n_body_controls = 0;
    for (unsigned int i = 0; i < parent.size(); ++i)
      if (root(parent, i) == i)
        number[i] = n_body_controls++;
    for (unsigned int i = 0; i < patches.size(); ++i)
      {
        NurbsPatch               &patch = patches[i];
        std::vector<unsigned int> numbers(patch.points.size());
        for (unsigned int b = 0; b < patch.n_eta(); ++b)
          for (unsigned int a = 0; a < patch.n_xi(); ++a)
            numbers[a + patch.n_xi() * b] =
              number[root(parent, first[i] + patch.unique_control(a, b))];
        patch.body_numbers = std::move(numbers);
      }
  }



  unsigned int
  NurbsMultipatch::n_cells() const
  {
    unsigned int n = 0;
    for (const auto &patch : patches)
      n += patch.xi.n_spans() * patch.eta.n_spans();
    return n;
  }



  NurbsMultipatch::CellSpan
  NurbsMultipatch::cell_span(unsigned int cell) const
  {
    for (unsigned int i = 0; i < patches.size(); ++i)
      {
        const unsigned int n_u = patches[i].xi.n_spans();
        const unsigned int n   = n_u * patches[i].eta.n_spans();
        if (cell < n)
          return {i, {{cell % n_u, cell / n_u}}};
        cell -= n;
      }
    AssertThrow(false, ExcMessage("a cell beyond the body's patches"));
    return {};
  }



  std::vector<Point<2>>
  NurbsMultipatch::control_points() const
  {
    // (a point numbered twice, on a seam or a join, at its first place)
    std::vector<Point<2>> result(n_body_controls);
    std::vector<bool>     placed(n_body_controls, false);
    for (const auto &patch : patches)
      for (unsigned int b = 0; b < patch.n_eta(); ++b)
        for (unsigned int a = 0; a < patch.n_xi(); ++a)
          {
            const unsigned int A = patch.unique_control(a, b);
            if (!placed[A])
              result[A] = patch.points[a + patch.n_xi() * b];
            placed[A] = true;
          }
    return result;
  }
} // namespace glissade
