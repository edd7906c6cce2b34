#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <string>

namespace glissade
{
  /**
   * A three-dimensional hyperelastic law written in the reference
   * configuration: given the Green-Lagrange strain E = (C - I)/2 it returns
   * the second Piola-Kirchhoff stress S and the material tangent dS/dE.
   *
   * The input is E and not C on purpose: E computed from the displacement
   * gradient H as (H + H^T + H^T H)/2 carries no cancellation, while C - I
   * loses all digits of a strain of 1e-8. Laws keep that accuracy (for
   * instance with log1p), so small-strain problems converge to the same
   * relative residual as large-strain ones.
   *
   * Laws are written in 3D on purpose: the planar hypotheses (plane strain,
   * plane stress) are then one generic reduction in Material, instead of a
   * hand-derived 2D formula per law.
   */
  class HyperelasticLaw
  {
  public:
    virtual ~HyperelasticLaw() = default;

    virtual void
    evaluate(const dealii::SymmetricTensor<2, 3> &green_lagrange_strain,
             dealii::SymmetricTensor<2, 3>       &second_piola_kirchhoff,
             dealii::SymmetricTensor<4, 3>       &tangent) const = 0;

    /**
     * The stored energy W(E) per unit reference volume (the strain energy
     * of a dynamic run's energy balance).
     */
    virtual double
    energy(
      const dealii::SymmetricTensor<2, 3> &green_lagrange_strain) const = 0;

    virtual std::string
    name() const = 0;
  };
} // namespace glissade
