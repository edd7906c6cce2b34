// The compressible Mooney-Rivlin law: the neo-Hookean law with a second
// invariant term, for rubber, whose response in shear at moderate strains
// the neo-Hookean one underestimates. Its third constant is the share of
// the shear modulus the second invariant carries (doc/adding_a_material.md
// takes this file as its example).

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/material/hyperelastic_law.h>

#include <any>
#include <cmath>
#include <memory>
#include <string>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     *   W(C) = c1 (I1 - 3) + c2 (I2 - 3) - (2 c1 + 4 c2) ln J
     *          + lambda_w / 2 (ln J)^2,
     * with c1 + c2 = mu / 2, c2 = ratio mu / 2 and lambda_w = lambda - 4 c2,
     * so that at small strain it is Hooke's law with the Lame constants of
     * Young modulus and Poisson ratio (ratio 0: the neo-Hookean law).
     *
     *   S = 2 (2 c1 + 4 c2) C^-1 E + 4 c2 (tr E I - E) + lambda_w ln J C^-1,
     *   D = 4 c2 (I x I - II) + 2 (2 c1 + 4 c2 - lambda_w ln J) C^-1 o C^-1
     *       + lambda_w C^-1 x C^-1,
     * written with E, not C - I, so that a small strain keeps its digits
     * (HyperelasticLaw).
     */
    class MooneyRivlin : public HyperelasticLaw
    {
    public:
      MooneyRivlin(const double lambda, const double mu, const double ratio)
        : c1(0.5 * (1. - ratio) * mu)
        , c2(0.5 * ratio * mu)
        , lambda_w(lambda - 4. * c2)
      {}

      void
      evaluate(const SymmetricTensor<2, 3> &E,
               SymmetricTensor<2, 3>       &S,
               SymmetricTensor<4, 3>       &D) const override
      {
        const SymmetricTensor<2, 3> I     = unit_symmetric_tensor<3>();
        const SymmetricTensor<2, 3> C_inv = invert(I + 2. * E);
        const double                log_J = log_of_J(E);
        const double                a     = 2. * c1 + 4. * c2;
        S = 2. * a * symmetrize(Tensor<2, 3>(C_inv) * Tensor<2, 3>(E)) +
            4. * c2 * (trace(E) * I - E) + lambda_w * log_J * C_inv;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int l = k; l < 3; ++l)
                D[i][j][k][l] =
                  4. * c2 *
                    ((i == j && k == l ? 1. : 0.) -
                     0.5 * ((i == k && j == l ? 1. : 0.) +
                            (i == l && j == k ? 1. : 0.))) +
                  (a - lambda_w * log_J) *
                    (C_inv[i][k] * C_inv[j][l] + C_inv[i][l] * C_inv[j][k]) +
                  lambda_w * C_inv[i][j] * C_inv[k][l];
      }

      double
      energy(const SymmetricTensor<2, 3> &E) const override
      {
        const double tr_E  = trace(E);
        const double log_J = log_of_J(E);
        return 2. * c1 * tr_E + c2 * (4. * tr_E + 2. * (tr_E * tr_E - E * E)) -
               (2. * c1 + 4. * c2) * log_J + 0.5 * lambda_w * log_J * log_J;
      }

      std::string
      name() const override
      {
        return "Mooney-Rivlin";
      }

    private:
      /** ln J = ln(det C) / 2, det C - 1 formed without cancellation. */
      static double
      log_of_J(const SymmetricTensor<2, 3> &E)
      {
        const SymmetricTensor<2, 3> A   = 2. * E;
        const double                trA = trace(A);
        return 0.5 *
               std::log1p(trA + 0.5 * (trA * trA - A * A) + determinant(A));
      }

      const double c1, c2, lambda_w;
    };
  } // namespace



  void
  declare_mooney_rivlin_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Mooney-Rivlin ratio",
                      "0",
                      Patterns::Double(),
                      "Law = Mooney-Rivlin: c2 / (c1 + c2), the share of the "
                      "shear modulus that the second invariant carries, in "
                      "[0, 1) (0: the neo-Hookean law; about 0.1-0.3 for "
                      "filled rubbers).");
  }



  std::any
  parse_mooney_rivlin_parameters(const ParameterHandler &prm,
                                 const std::string      &where)
  {
    const double ratio = prm.get_double("Mooney-Rivlin ratio");
    if (!(ratio >= 0. && ratio < 1.))
      throw InputError(where + "/Mooney-Rivlin ratio", "must lie in [0, 1)");
    return ratio;
  }



  std::unique_ptr<HyperelasticLaw>
  make_mooney_rivlin(const double    lambda,
                     const double    mu,
                     const std::any &ratio)
  {
    return std::make_unique<MooneyRivlin>(
      lambda, mu, ratio.has_value() ? std::any_cast<double>(ratio) : 0.);
  }
} // namespace glissade
