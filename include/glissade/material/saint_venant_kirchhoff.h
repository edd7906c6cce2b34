#pragma once

#include <glissade/material/hyperelastic_law.h>

namespace glissade
{
  /**
   * Saint Venant-Kirchhoff solid: S = lambda tr(E) I + 2 mu E. Linear in the
   * Green-Lagrange strain, so its tangent is constant; it is the natural
   * large-rotation, small-strain model and softens without bound in strong
   * compression, which users should know before choosing it.
   */
  class SaintVenantKirchhoff : public HyperelasticLaw
  {
  public:
    SaintVenantKirchhoff(const double lambda, const double mu);

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
      return "Saint Venant-Kirchhoff";
    }

  private:
    const double                  lambda;
    const double                  mu;
    dealii::SymmetricTensor<4, 3> elasticity;
  };
} // namespace glissade
