#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace glissade
{
  /**
   * When the Newton iteration of one increment has converged, and when it
   * diverges (doc/design.md, "Newton convergence"):
   * - converged: at least one correction, |R| <= residual tolerance times
   *   the force scale, and the last correction |du| <= the displacement
   *   tolerance times |u|, or at the round-off of the nodes' positions
   *   (100 eps size sqrt(n)): when nothing moves, |u| is itself round-off;
   * - diverges: after the second correction, |R| more than 1e8 times the
   *   larger of the first two residuals (a step driven by prescribed
   *   displacements starts from a zero residual).
   * The Simulation tells it each residual and each correction.
   *
   * It also says when the next correction only confirms the state
   * (confirms_only): the residual already meets its tolerance, and the
   * last correction was small (at most 1e-3 of |u|), so the tangent has
   * barely changed since it was factorised. A correction solved with the
   * previous factorisation then differs from the full Newton one by a
   * relative amount of the order of that last correction, and the
   * displacement test decides on it as it would on the full one.
   */
  class NewtonCriterion
  {
  public:
    /** `size`: the largest body's diameter; `n_dofs`: all bodies' dofs. */
    NewtonCriterion(const double       residual_tolerance,
                    const double       displacement_tolerance,
                    const double       size,
                    const unsigned int n_dofs)
      : residual_tolerance(residual_tolerance)
      , displacement_tolerance(displacement_tolerance)
      , round_off(100. * std::numeric_limits<double>::epsilon() * size *
                  std::sqrt(double(n_dofs)))
    {}

    /** The residual |R| at `iteration` (the number of corrections made so
     *  far) and the force scale it is measured against. */
    void
    add_residual(const unsigned int iteration,
                 const double       residual,
                 const double       scale)
    {
      this->iteration = iteration;
      this->residual  = residual;
      this->scale     = scale;
      if (iteration <= 1)
        first_residual = std::max(first_residual, residual);
    }

    /** The correction |du| just made and the displacement |u| after it. */
    void
    add_correction(const double correction, const double displacement)
    {
      last_correction   = correction;
      displacement_norm = displacement;
    }

    bool
    converged() const
    {
      return iteration > 0 && residual <= residual_tolerance * scale &&
             last_correction <=
               std::max(displacement_tolerance * displacement_norm, round_off);
    }

    bool
    confirms_only() const
    {
      return iteration > 1 && residual <= residual_tolerance * scale &&
             last_correction <= 1e-3 * displacement_norm;
    }

    bool
    diverges() const
    {
      return iteration > 2 && residual > 1e8 * std::max(first_residual, 1e-300);
    }

  private:
    const double residual_tolerance;
    const double displacement_tolerance;
    const double round_off;

    unsigned int iteration         = 0;
    double       residual          = 0.;
    double       scale             = 0.;
    double       first_residual    = 0.;
    double       last_correction   = std::numeric_limits<double>::max();
    double       displacement_norm = 0.;
  };
} // namespace glissade
