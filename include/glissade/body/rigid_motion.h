#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * An infinitesimal rigid motion of the plane,
   * v(X) = translation + rotation e3 x (X - center).
   * Used to find which motions of a body its supports leave free, and
   * which of those its contacts hold (doc/contact.md, "Bodies held by
   * contact").
   */
  struct RigidMotion
  {
    dealii::Tensor<1, 2> translation;
    double               rotation = 0.;
    dealii::Point<2>     center;

    dealii::Tensor<1, 2>
    at(const dealii::Point<2> &X) const
    {
      return translation + rotation * dealii::Tensor<1, 2>({-(X[1] - center[1]),
                                                            X[0] - center[0]});
    }

    /**
     * "a translation along (0.6, 0.8)" or "a rotation about (2, 0)", for
     * messages; `length` is the size of the body (what counts as no
     * rotation at all).
     */
    std::string
    describe(const double length) const;
  };

  /**
   * The translations along x and y and the rotation about `center` at the
   * rate 1 / `length`: each moves a body of that size by about 1, so that
   * combinations of them compare.
   */
  std::array<RigidMotion, 3>
  rigid_motion_basis(const dealii::Point<2> &center, const double length);

  /** sum_j coefficients[j] basis[j]. */
  RigidMotion
  combine(const std::vector<RigidMotion> &basis,
          const std::vector<double>      &coefficients);

  /**
   * An orthonormal basis of the vectors x of length n with rows . x = 0
   * (each row of length n): the eigenvectors of the rows' Gram matrix
   * whose eigenvalue is below 1e-12 of its trace, all n if there is no
   * row. Small problems only (n is three per body).
   */
  std::vector<std::vector<double>>
  null_space(const std::vector<std::vector<double>> &rows,
             const unsigned int                      n);
} // namespace glissade
