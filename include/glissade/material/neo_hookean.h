#pragma once

#include <glissade/material/hyperelastic_law.h>

namespace glissade
{
  /**
   * Compressible neo-Hookean solid,
   *   W(C) = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
   * which reduces to Hooke's law with the same Lame constants for small
   * strains, so E and nu keep their usual meaning.
   */
  class NeoHookean : public HyperelasticLaw
  {
  public:
    NeoHookean(const double lambda, const double mu);

    void
    evaluate(const dealii::SymmetricTensor<2, 3> &green_lagrange_strain,
             dealii::SymmetricTensor<2, 3>       &second_piola_kirchhoff,
             dealii::SymmetricTensor<4, 3>       &tangent) const override;

    double
    energy(const dealii::SymmetricTensor<2, 3> &green_lagrange_strain)
      const override;

    std::string
    name() const override
    {
      return "neo-Hookean";
    }

  private:
    const double lambda;
    const double mu;
  };
} // namespace glissade
