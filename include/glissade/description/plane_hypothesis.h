#pragma once

namespace glissade
{
  /** The planar hypothesis of a 2D body (Material/Hypothesis). */
  enum class PlaneHypothesis
  {
    plane_strain,
    plane_stress
  };
} // namespace glissade
