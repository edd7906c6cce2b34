#pragma once

#include <deal.II/base/point.h>

#include <glissade/description/plane_hypothesis.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace glissade
{
  /**
   * What makes the 2D body a 3D one (Material/Hypothesis), as the one
   * object that everything integrating over the body or reading its third
   * direction asks: the cell integration, the loads, the mass, the
   * measures, the outputs, the contact's tributary areas, the law's
   * reduction to the plane (Material). Which hypothesis a body has is
   * decided here, and nowhere else: the others ask what it does.
   *
   * - plane strain: a slice of a long body, E_33 = 0, a reference area dA
   *   standing for the volume Thickness dA;
   * - plane stress: a thin plate, S_33 = 0 (E_33 solved at each point);
   * - axisymmetric: a body of revolution, x the radius r >= 0 and y the
   *   axis, the third direction the hoop, which strains with the radial
   *   motion (F_33 = 1 + u_r / r), and dA the ring 2 pi r dA.
   */
  class Hypothesis
  {
  public:
    /** What the third direction does, which the law's reduction needs. */
    enum class ThirdDirection
    {
      /** E_33 = 0 */
      held,
      /** S_33 = 0, E_33 solved */
      free_of_stress,
      /** E_33 from u_r / r */
      hoop
    };

    Hypothesis(const PlaneHypothesis kind, const double thickness)
      : third(kind == PlaneHypothesis::plane_strain ?
                ThirdDirection::held :
              kind == PlaneHypothesis::plane_stress ?
                ThirdDirection::free_of_stress :
                ThirdDirection::hoop)
      , thickness(thickness)
    {}

    /** The names a .prm gives (Material/Hypothesis), with their kinds. */
    static const std::array<std::pair<const char *, PlaneHypothesis>, 3> &
    names()
    {
      static const std::array<std::pair<const char *, PlaneHypothesis>, 3>
        table = {{{"plane strain", PlaneHypothesis::plane_strain},
                  {"plane stress", PlaneHypothesis::plane_stress},
                  {"axisymmetric", PlaneHypothesis::axisymmetric}}};
      return table;
    }

    ThirdDirection
    third_direction() const
    {
      return third;
    }

    /**
     * True for a body of revolution: its third direction is the hoop, which
     * strains with the radial motion; its rigid motions are the translation
     * along the axis alone, and its radial dofs on the axis are held.
     */
    bool
    strains_the_hoop() const
    {
      return third == ThirdDirection::hoop;
    }

    /**
     * What a reference area dA at X stands for, per unit dA: the thickness,
     * or the ring's 2 pi r (r = X[0]). The same for a length of boundary
     * ds, whose area it gives.
     */
    double
    out_of_plane_measure(const dealii::Point<2> &X) const
    {
      return strains_the_hoop() ? 2. * M_PI * X[0] : thickness;
    }

    /** The same for a body of size L: the thickness, or the ring 2 pi L. */
    double
    out_of_plane_size(const double L) const
    {
      return strains_the_hoop() ? 2. * M_PI * L : thickness;
    }

    /** u_r / r at X, the hoop's strain ratio; 0 without a hoop. */
    double
    hoop_ratio(const double u_r, const dealii::Point<2> &X) const
    {
      return strains_the_hoop() ? u_r / X[0] : 0.;
    }

    /**
     * The share of node k of the area of a straight boundary segment from
     * x_k to x_other, of the given length: half of length times the
     * thickness, or the integral of 2 pi r N_k along it, 2 pi length (2
     * r_k + r_other) / 6.
     */
    double
    node_share_of_segment(const dealii::Point<2> &x_k,
                          const dealii::Point<2> &x_other,
                          const double            length) const
    {
      return strains_the_hoop() ?
               2. * M_PI * length * (2. * x_k[0] + x_other[0]) / 6. :
               0.5 * length * thickness;
    }

  private:
    ThirdDirection third;
    double         thickness;
  };
} // namespace glissade
