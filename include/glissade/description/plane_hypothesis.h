#pragma once

namespace glissade
{
  /**
   * The hypothesis that makes a 2D body a 3D one (Material/Hypothesis):
   * a slice of a long body (plane strain), a thin plate (plane stress), or
   * a body of revolution (axisymmetric: x is the radius r >= 0, y the
   * axis, and the third direction the hoop, with F_33 = 1 + u_r / r).
   */
  enum class PlaneHypothesis
  {
    plane_strain,
    plane_stress,
    axisymmetric
  };
} // namespace glissade
