#pragma once

#include <array>
#include <functional>
#include <vector>

namespace glissade
{
  /**
   * An abradable coating on a casing (Contact <pair>/Obstacle/Coating
   * ...): a layer of thickness e on the casing's inside, modelled as
   * Legrand, Batailly and Pierre (2012) model it in 2D, a profile along
   * the casing's angle psi (in the casing's own frame, which turns with
   * it) of the depth w(psi) worn off, 0 <= w <= e. The layer is rigid and
   * perfectly plastic: a node presses on it with at most the yield
   * pressure times its tributary area (BiPotentialSolver's cap), and
   * where it presses that hard it cuts in: after each converged step the
   * layer is removed wherever a yielding node went beyond its surface
   * (wear_along()).
   *
   * The profile is kept at `cells` equal angles and read between them by
   * a periodic Catmull-Rom cubic, so that the surface's normal does not
   * jump from cell to cell.
   */
  class AbradableCoating
  {
  public:
    AbradableCoating(double       thickness,
                     double       yield_pressure,
                     unsigned int cells);

    double
    thickness() const
    {
      return layer_thickness;
    }

    double
    yield_pressure() const
    {
      return pressure;
    }

    /** w, dw/dpsi and d2w/dpsi2 at psi. */
    std::array<double, 3>
    worn(double psi) const;

    /**
     * Wears the layer along the path of a point that went, in the casing's
     * frame, from angle psi_0 at radius rho_0 to psi_1 at rho_1 (the
     * shorter way round), its radius taken linearly in the angle between:
     * every cell whose surface the path went beyond is cut down to it, no
     * deeper than the layer. `casing_radius` is r_c(psi), the casing's
     * own curve in its frame.
     */
    void
    wear_along(double                               psi_0,
               double                               rho_0,
               double                               psi_1,
               double                               rho_1,
               const std::function<double(double)> &casing_radius);

    /**
     * The area removed, int 1/2 ((r_c - e + w)^2 - (r_c - e)^2) dpsi
     * (per unit thickness), by the trapezoidal rule over the cells.
     */
    double
    removed_area(const std::function<double(double)> &casing_radius) const;

    /** The worn depth at each cell's angle, 2 pi k / cells. */
    const std::vector<double> &
    profile() const
    {
      return depth;
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &depth;
    }

  private:
    double              layer_thickness, pressure;
    std::vector<double> depth;
  };
} // namespace glissade
