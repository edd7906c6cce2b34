#include <glissade/material/neo_hookean.h>

#include <any>
#include <cmath>
#include <memory>

namespace glissade
{
  using namespace dealii;

  std::unique_ptr<HyperelasticLaw>
  make_neo_hookean(const double lambda, const double mu, const std::any &)
  {
    return std::make_unique<NeoHookean>(lambda, mu);
  }



  NeoHookean::NeoHookean(const double lambda, const double mu)
    : lambda(lambda)
    , mu(mu)
  {}

  void
  NeoHookean::evaluate(const SymmetricTensor<2, 3> &E,
                       SymmetricTensor<2, 3>       &S,
                       SymmetricTensor<4, 3>       &D) const
  {
    const SymmetricTensor<2, 3> I     = unit_symmetric_tensor<3>();
    const SymmetricTensor<2, 3> C     = I + 2. * E;
    const SymmetricTensor<2, 3> C_inv = invert(C);

    // det C - 1 = det(I + A) - 1 with A = 2E, written without cancellation:
    // tr A + ((tr A)^2 - tr A^2)/2 + det A; then ln J = log1p(.)/2.
    const SymmetricTensor<2, 3> A   = 2. * E;
    const double                trA = trace(A);
    const double                det_C_minus_1 =
      trA + 0.5 * (trA * trA - A * A) + determinant(A);
    const double log_J = 0.5 * std::log1p(det_C_minus_1);

    // S = mu (I - C^-1) + lambda ln J C^-1 = C^-1 (2 mu E + lambda ln J I),
    // the second form again free of cancellation.
    S = symmetrize(Tensor<2, 3>(C_inv) *
                   Tensor<2, 3>(2. * mu * E + lambda * log_J * I));

    // D = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1}, with
    // (I_{C^-1})_ijkl = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) / 2.
    const double factor = 2. * (mu - lambda * log_J);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = k; l < 3; ++l)
            D[i][j][k][l] =
              lambda * C_inv[i][j] * C_inv[k][l] +
              factor * 0.5 *
                (C_inv[i][k] * C_inv[j][l] + C_inv[i][l] * C_inv[j][k]);
  }



  double
  NeoHookean::energy(const SymmetricTensor<2, 3> &E) const
  {
    // W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 with tr C - 3 =
    // 2 tr E and ln J as in evaluate(), free of cancellation.
    const SymmetricTensor<2, 3> A   = 2. * E;
    const double                trA = trace(A);
    const double                log_J =
      0.5 * std::log1p(trA + 0.5 * (trA * trA - A * A) + determinant(A));
    return mu * trace(E) - mu * log_J + 0.5 * lambda * log_J * log_J;
  }
} // namespace glissade
