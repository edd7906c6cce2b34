#include <glissade/body/rigid_motion.h>
#include <glissade/lac/lapack.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  std::string
  RigidMotion::describe(const double length) const
  {
    // Numbers rounded for reading; a direction to 3 digits.
    const auto rounded = [](const double x) {
      return std::abs(x) < 5e-4 ? 0. : std::round(x * 1e3) / 1e3;
    };
    std::ostringstream text;
    if (std::abs(rotation) * length <= 1e-6 * translation.norm())
      {
        const Tensor<1, 2> d = translation / translation.norm();
        text << "a translation along (" << rounded(d[0]) << ", "
             << rounded(d[1]) << ")";
      }
    else
      {
        // The point that does not move: translation + rotation e3 x (p - c) =
        // 0.
        const Point<2> p(center[0] - translation[1] / rotation,
                         center[1] + translation[0] / rotation);
        const auto     clean = [length](const double x) {
          return std::abs(x) < 1e-9 * length ? 0. : x;
        };
        text << std::setprecision(4) << "a rotation about (" << clean(p[0])
             << ", " << clean(p[1]) << ")";
      }
    return text.str();
  }



  std::array<RigidMotion, 3>
  rigid_motion_basis(const Point<2> &center, const double length)
  {
    std::array<RigidMotion, 3> basis;
    basis[0].translation = Tensor<1, 2>({1., 0.});
    basis[1].translation = Tensor<1, 2>({0., 1.});
    basis[2].rotation    = 1. / length;
    for (auto &m : basis)
      m.center = center;
    return basis;
  }



  RigidMotion
  combine(const std::vector<RigidMotion> &basis,
          const std::vector<double>      &coefficients)
  {
    // Every motion is written about the first one's centre.
    RigidMotion sum;
    if (basis.empty())
      return sum;
    sum.center = basis[0].center;
    for (unsigned int j = 0; j < basis.size(); ++j)
      {
        sum.translation += coefficients[j] * basis[j].at(sum.center);
        sum.rotation += coefficients[j] * basis[j].rotation;
      }
    return sum;
  }



  std::vector<std::vector<double>>
  null_space(const std::vector<std::vector<double>> &rows, const unsigned int n)
  {
    std::vector<std::vector<double>> basis;
    if (n == 0)
      return basis;
    std::vector<double> gram(n * n, 0.);
    double              trace = 0.;
    for (const auto &row : rows)
      for (unsigned int i = 0; i < n; ++i)
        {
          trace += row[i] * row[i];
          for (unsigned int j = 0; j < n; ++j)
            gram[i + j * n] += row[i] * row[j];
        }
    if (!(trace > 0.))
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            basis.emplace_back(n, 0.);
            basis.back()[i] = 1.;
          }
        return basis;
      }
    const int           size = n, lwork = 8 * n + 8;
    std::vector<double> eigenvalues(n), work(lwork);
    int                 info = 0;
    dsyev_("V",
           "L",
           &size,
           gram.data(),
           &size,
           eigenvalues.data(),
           work.data(),
           &lwork,
           &info);
    if (info != 0)
      return basis;
    for (unsigned int k = 0; k < n; ++k)
      if (eigenvalues[k] <= 1e-12 * trace)
        basis.emplace_back(gram.begin() + k * n, gram.begin() + (k + 1) * n);
    return basis;
  }
} // namespace glissade
