#pragma once

namespace glissade
{
  /**
   * How a body strains (Material/Kinematics): large strain (total
   * Lagrangian, the Green-Lagrange strain and the hyperelastic law, the
   * default) or small strain (linear elasticity: epsilon = sym(grad u),
   * sigma = D_0 : epsilon with D_0 the law's tangent at rest, equilibrium
   * and loads on the reference configuration). Contact is detected on the
   * current configuration either way.
   */
  enum class Kinematics
  {
    large_strain,
    small_strain
  };
} // namespace glissade
