#pragma once

#include <glissade/material/hyperelastic_law.h>

#include <Sacado.hpp>

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace glissade
{
  /**
   * The number a strain energy is evaluated on: forward automatic
   * differentiation (Trilinos's Sacado, as deal.II's step-71/72 use it)
   * nested twice over the six components of E, so that one evaluation of W
   * gives its value, its gradient (the stress S) and its Hessian (the
   * tangent D). Fixed size: no allocation per operation.
   */
  using EnergyNumber = Sacado::Fad::SFad<Sacado::Fad::SFad<double, 6>, 6>;

  /**
   * What a strain energy may be written in, at one strain: the invariants
   * of C = I + 2E, J = sqrt(I3) and ln J (formed from E without
   * cancellation, as the hand-written laws do), and C's components.
   */
  struct StrainMeasures
  {
    EnergyNumber I1, I2, I3, J, ln_J;
    /** C_11, C_22, C_33, C_12, C_13, C_23. */
    std::array<EnergyNumber, 6> C;
  };

  /** A strain energy W per unit reference volume. */
  using StrainEnergy = std::function<EnergyNumber(const StrainMeasures &)>;

  /**
   * A hyperelastic law given by its strain energy alone: S = dW/dE and D =
   * d2W/dE2 by automatic differentiation. `Law = energy` takes W as a
   * formula of the .prm (energy_law.cc); a law in C++ is one function:
   *
   *   make_energy_law("my law",
   *                   [=](const StrainMeasures &s) -> EnergyNumber {
   *                     return mu / 2 * (s.I1 - 3) - mu * s.ln_J +
   *                            lambda / 2 * s.ln_J * s.ln_J;
   *                   });
   *
   * and one line in law_registry.cc (doc/adding_a_material.md). The return
   * type must be written: Sacado's sums and products are expression
   * templates that refer to the function's temporaries, and a lambda left
   * to deduce it returns one of them, dangling.
   */
  std::unique_ptr<HyperelasticLaw>
  make_energy_law(const std::string &name, StrainEnergy energy);
} // namespace glissade
