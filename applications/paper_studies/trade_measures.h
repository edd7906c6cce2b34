#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /**
   * One point of the speed-accuracy trade: one discretisation at one mesh
   * size, measured on one of the paper's measures of accuracy. The figures
   * are those a user pays and gets: dofs, Newton iterations, active
   * contact nodes (the most at any increment), wall time, and the value
   * the measure reads (TradeMeasures::error turns it into an error).
   */
  struct TradePoint
  {
    double dofs              = 0.;
    double newton_iterations = 0.;
    double active_nodes      = 0.;
    double wall_seconds      = 0.;
    double value             = 0.;
  };

  /**
   * The paper's measures of accuracy, each as a function of one
   * discretisation and one mesh parameter n, for the trade study:
   *
   * - "geometric_gap", "geometric_normal" (section 3.3, figs 12-14): the
   *   largest gap error (% of R) and normal error (degrees) of the half
   *   ring's outer edge with n elements along it. The cost is the dofs of
   *   the edge's nodes and the time to build the curve and sample it; no
   *   Newton iteration is involved.
   * - "table1" (Table 1): the cantilever's largest displacement with n
   *   elements along (n/15 across, the paper's aspect); the error is its
   *   distance to a reference run, in %.
   * - "case1" (section 4.1): the beam's tip displacement u_y(0, 0) on the
   *   deformable half ring, both meshed with n elements along (n/15
   *   across); the error is its distance to a reference run, in %.
   * - "case2" (section 4.2): the roughness of the square corner's contact
   *   force history over the contact phase (ContactCaseStudy::roughness),
   *   with n elements around each ring (the square refined alike).
   * - "case3" (section 4.3): the worst spread of the interface contact
   *   forces (%), n elements around the rings.
   * - "case3_torque": the same runs' largest spurious torque on the inner
   *   ring, |T| / (R sum |f|) in % (exactly 0 for frictionless round rings:
   *   an error against a closed form, not against a reference run).
   *
   * Discretisations: q4 (Q4 bodies, faceted masters), bspline and
   * bspline-spline (Q4 bodies, B-spline masters with the segment or the
   * spline force transfer), hermite; for the geometric study and Table 1
   * also q8, q9 and q12 (Lagrange and serendipity elements), and q16 for
   * Table 1's reference.
   */
  class TradeMeasures
  {
  public:
    /** Every measure the study knows, in the order it runs them. */
    static const std::vector<std::string> &
    names();

    /** What the error of a measure is, for tables and axes. */
    static std::string
    error_name(const std::string &measure);

    /** Whether a measure's error is taken against a reference run. */
    static bool
    needs_reference(const std::string &measure);

    /**
     * The error of a point: its value, or for measures that need a
     * reference, |value - reference| / |reference| in %.
     */
    static double
    error(const std::string &measure,
          const double       value,
          const double       reference);

    /** The discretisations a measure accepts. */
    static const std::vector<std::string> &
    discretisations(const std::string &measure);

    /**
     * Runs one point. `scene` is the measure's scene file (unused by the
     * geometric measures); `settings` carries measure-specific numbers
     * (case2: increments and the fraction of the scene's load program;
     * case3: the rotation angle in degrees and the increments per element
     * crossed).
     */
    static TradePoint
    run(const std::string         &measure,
        const std::string         &discretisation,
        const unsigned int         n,
        const std::string         &scene,
        const std::vector<double> &settings,
        const std::string         &output_directory);
  };
} // namespace glissade
