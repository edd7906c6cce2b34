#pragma once

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /** One run of the friction study: a master and a friction coefficient. */
  struct FrictionRun
  {
    std::string  variant; // q4 | bspline | hermite
    double       friction          = 0.;
    unsigned int dofs              = 0;
    double       wall_seconds      = 0.;
    unsigned int newton_iterations = 0;
    unsigned int cut_backs         = 0;

    /** Per increment, over every pair's slave nodes. */
    std::vector<double>       time;
    std::vector<double>       normal_force;     // sum of r_n
    std::vector<double>       tangential_force; // sum of |r_t|
    std::vector<unsigned int> sticking, slipping, open;
    /**
     * The spread of the contact forces' norms around their mean over the
     * closed nodes, max_k | |f_k| - mean | / mean in % (case 3's measure).
     */
    std::vector<double> spread_percent;
    /**
     * Per increment, per slave node (pairs one after the other, nodes in
     * the order of their slave boundary): 0 open, 1 stick, 2 slip.
     */
    std::vector<std::vector<unsigned char>> status;
    /** The slave nodes' reference positions, in the order of `status`. */
    std::vector<std::array<double, 2>> node_positions;
    std::vector<std::string>           node_pairs; // each node's pair
    /**
     * Coulomb's law at every closed node, |r_t| - mu r_n <= 0: the largest
     * excess over the run, relative to the increment's largest r_n.
     */
    double worst_cone_excess = 0.;
    /** The time the first stage ends (case 3: the compression). */
    double first_stage_end = 0.;
  };

  /**
   * Friction studies of a scene (issue 22: cases 2 and 3 with mu = 0.1,
   * 0.3): every master variant with every friction coefficient, the
   * histories of the normal and tangential contact forces, the numbers of
   * sticking and slipping nodes, the spread of the force norms, and each
   * node's status at every increment (the stick-slip pattern), as CSV and
   * PNG. Driver files: prm/case2_friction.prm, prm/case3_friction.prm.
   */
  class FrictionStudy
  {
  public:
    /**
     * Runs `scene_file` with its masters turned into `variant` (hermite:
     * the master bodies' elements too) and `friction` on every pair, plus
     * the given overrides.
     */
    static FrictionRun
    run_variant(const std::string              &scene_file,
                const std::string              &variant,
                double                          friction,
                const std::string              &output_directory,
                const std::vector<std::string> &overrides = {});

    /** Reads the study's .prm, runs it, writes CSV and PNG. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
