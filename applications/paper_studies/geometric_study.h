#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /** One point of the geometric study along the two edges around pi/2. */
  struct GeometricSample
  {
    unsigned int edge; // 1: theta in [pi/2, pi/2 + pi/n_e], 2: the other
    double xi; // local coordinate in [-1, 1], xi = 1 at theta = pi/2 on edge 1
    double theta;
    double gap_error_percent;    // (|c| - R) / R, in % of R
    double normal_error_degrees; // angle from the circle's normal
  };

  /**
   * The geometric study of the paper's section 3.3 (figs 12-14): the outer
   * edge of a half ring of radius R with n_e elements along it, represented
   * by each discretisation, compared with the exact circle on the two edges
   * that meet at theta = pi/2.
   *
   * Each representation is built exactly as contact would build it, through
   * the MasterCurve classes from nodes on the circle: q4 a FacetedCurve, q8
   * and q12 a LagrangeEdgeCurve of degree 2 and 3 through the element edge
   * nodes, bspline an open double-vertex BSplineCurve through the Q4 nodes,
   * hermite a HermiteCurve whose node tangents come from the exact
   * parametrisation (dX/dxi = R dtheta/dxi e_theta, as the Hermite element's
   * isoparametric geometry does).
   */
  class GeometricStudy
  {
  public:
    static const std::vector<std::string> &
    methods();

    static std::vector<GeometricSample>
    evaluate(const std::string &method,
             const unsigned int n_elements,
             const unsigned int samples_per_edge);

    /** Jump of the normal angle at theta = pi/2 (degrees, edge 2 - edge 1). */
    static double
    normal_jump_degrees(const std::vector<GeometricSample> &samples);

    /** Largest |gap error| (%) over the samples. */
    static double
    max_gap_error_percent(const std::vector<GeometricSample> &samples);

    /** Largest |normal error| (degrees) over the samples. */
    static double
    max_normal_error_degrees(const std::vector<GeometricSample> &samples);

    /**
     * Least-squares slope of -log(error) against log(n_e): the measured
     * convergence order.
     */
    static double
    convergence_order(const std::vector<unsigned int> &n_elements,
                      const std::vector<double>       &errors);

    /** Reads the study's .prm, writes CSVs and pictures, prints the table. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
