#pragma once

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /** What one variant of case 3 gives. */
  struct Case3Result
  {
    std::string         variant;
    unsigned int        dofs              = 0;
    double              wall_seconds      = 0.;
    unsigned int        newton_iterations = 0;
    unsigned int        active_nodes      = 0; // at the end
    std::vector<double> spread_percent;        // per rotation increment
    std::vector<double> node_force; // |f| of node (1.25, 0), per increment
    /**
     * Fig 28: per increment, the master curve near node (1.25, 0) as
     * (angle in degrees, radius) samples, over two elements either side.
     */
    std::vector<std::vector<std::array<double, 2>>> master_profile;
    /** Per increment, the mean, smallest and largest |f| over the active nodes.
     */
    std::vector<double> mean_force, smallest_force, largest_force;
    double              worst_spread    = 0.;
    unsigned int        worst_increment = 0;
    std::vector<double> worst_distribution; // (|f| - F_e) / F_e in %, per node
    /**
     * Spurious torque: frictionless contact between rotationally symmetric
     * rings transmits no torque, so the torque T of the contact forces on
     * the inner ring about the centre is a discretisation error. Per
     * rotation increment, T / (R sum_k |f_k|) in % (the share of the forces
     * that acts as a tangential force at the interface radius R = 1.25).
     */
    std::vector<double> torque_percent;
    double              worst_torque_percent = 0.;
    /** The work of T over the rotation (J per unit thickness). */
    double spurious_work = 0.;
    /** The work if every contact force were tangential: R sum |f| theta. */
    double tangential_work_scale = 0.;
  };

  /**
   * Case 3 of the paper (section 4.3): the concentric rings of
   * prm/case3_rings.prm, compressed and then rotated, for the variants q4
   * (faceted master), bspline (closed B-spline over the Q4 master) and
   * hermite (Hermite outer ring). Per rotation increment it measures the
   * spread of the interface contact forces around their equilibrium value
   * F_e, the mean force norm over the interface at that increment:
   * max_k | |f_k| - F_e | / F_e, in %.
   */
  class Case3Study
  {
  public:
    /** The paper's worst-increment spread (fig 26), in %. */
    static double
    paper_spread(const std::string &variant);

    /**
     * Runs one variant of the scene file with `rotation_increments`
     * increments over `rotation_degrees` after the 10 of compression, with
     * `outer_elements` around the outer ring (Hermite: that ring only, as
     * in fig 29; Q4 and B-spline: both rings, radially refined alike) and
     * the same 400 N of total load.
     */
    static Case3Result
    run_variant(const std::string &scene_file,
                const std::string &variant,
                const double       rotation_degrees,
                const unsigned int rotation_increments,
                const std::string &output_directory,
                const unsigned int outer_elements = 40);

    /**
     * Fig 28: the B-spline and Hermite master curves near node (1.25, 0) at
     * two increments of the first element of rotation, i1 (the node at
     * mid-element, where the paper's two smooth masters match) and i2 (the
     * largest difference of their forces on the node), as
     * case3_fig28.csv. Nothing without both variants.
     */
    static void
    write_fig28(const std::vector<Case3Result> &results,
                double                          rotation_degrees,
                unsigned int                    rotation_increments,
                const std::string              &directory);

    /** Reads the study's .prm, runs its variants, writes CSV and PNG. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
