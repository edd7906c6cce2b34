#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * What one run of a contact case (one scene, one discretisation) gives:
   * per-increment measures and the final vertex displacements of every
   * body. Which measures are filled depends on what the scene contains:
   * - a rigid disk master (case 1, rigid ring): the signed distance of the
   *   slave nodes to the exact circle (negative: penetration);
   * - bodies "left ring" and "right ring" and pairs "left" and "right"
   *   (case 2): the mirror symmetry about x = 0 of the displacements and
   *   of the contact forces, the crowns' vertical displacements (fig 19),
   *   and the history of the square's lower left corner (figs 20-23).
   */
  struct ContactCaseResult
  {
    std::string  scene;   // the scene file's stem, e.g. "case2_sliding"
    std::string  variant; // q4 | bspline | hermite
    unsigned int dofs              = 0;
    unsigned int increments        = 0;
    unsigned int newton_iterations = 0;
    unsigned int cut_backs         = 0;
    double       wall_seconds      = 0.;

    /** Per increment (index 0: the first converged increment). */
    std::vector<double> min_obstacle_distance;
    /** Largest |distance| of a node that carries a force (all increments). */
    double              max_active_distance = 0.;
    std::vector<double> symmetry_displacement;   // max |u - mirror| / max |u|
    std::vector<double> symmetry_force;          // max |f - mirror| / max |f|
    std::vector<std::array<double, 2>> crown_uy; // left, right crown
    std::vector<double>                corner_ux, corner_force;
    std::vector<unsigned int>          active_nodes;

    /**
     * Final state: per body, reference vertices, their displacement, and
     * the cells as four vertex indices in counter-clockwise order (for
     * pictures); the forces on the slave nodes that carry one.
     */
    std::vector<std::string>                              body_names;
    std::vector<std::vector<dealii::Point<2>>>            vertices;
    std::vector<std::vector<dealii::Tensor<1, 2>>>        final_displacement;
    std::vector<std::vector<std::array<unsigned int, 4>>> cells;
    std::vector<std::pair<dealii::Point<2>, dealii::Tensor<1, 2>>>
      contact_forces;
  };

  /**
   * Cases 1 and 2 of the paper (sections 4.1, 4.2): runs scenes for the
   * discretisations q4 (faceted masters), bspline (Q4 bodies, B-spline
   * masters; bspline-spline with the spline's own force transfer) and
   * hermite (every body Hermite, Hermite masters), measures what the paper
   * claims, and writes CSV, PNG and the runs' VTU.
   */
  class ContactCaseStudy
  {
  public:
    /**
     * Runs one scene with one discretisation. increments = 0 keeps the
     * scene's load program; otherwise its single stage is cut to
     * `load_fraction` of its end time in `increments` increments.
     * `extra_overrides` ("Section/Entry=value") change the scene first,
     * e.g. its meshes (the trade study).
     */
    static ContactCaseResult
    run_variant(const std::string              &scene_file,
                const std::string              &variant,
                const unsigned int              increments,
                const double                    load_fraction,
                const std::string              &output_directory,
                const bool                      progress        = false,
                const std::vector<std::string> &extra_overrides = {});

    /**
     * max over vertices of |u_a - u_b| / max |u_a|: how far two runs of
     * the same scene are apart at the end (they must share the meshes).
     */
    static double
    final_difference(const ContactCaseResult &a, const ContactCaseResult &b);

    /**
     * Smoothness of a history f_i: the largest jump of its first
     * difference, max_i |f_{i+1} - 2 f_i + f_{i-1}|, over max_i |f_i|,
     * taken over [first, last). Given the number of loaded nodes per
     * increment, increments within two of a change of that number are left
     * out: another node closing or opening is a physical event that bends
     * every discretisation's history alike, while the jumps that smoothing
     * removes happen as the node crosses a master vertex, with the same
     * nodes loaded.
     */
    static double
    roughness(const std::vector<double>       &history,
              const unsigned int               first,
              const unsigned int               last,
              const std::vector<unsigned int> &loaded_nodes = {});

    /**
     * The increments [first, last) of the first stretch in which the
     * corner node of a case-2 run carries a force.
     */
    static std::pair<unsigned int, unsigned int>
    contact_phase(const ContactCaseResult &result);

    /**
     * How piecewise linear a history is: the share of the total
     * |second difference| carried by the largest 10 % of the increments.
     * About 0.1-0.3 for a smooth curve, close to 1 when the curve is
     * straight between a few kinks.
     */
    static double
    kink_concentration(const std::vector<double> &history,
                       const unsigned int         first,
                       const unsigned int         last);

    /** Reads the study's .prm (Study = case1 or case2) and runs it. */
    static void
    run(const std::string &prm_file, const std::vector<std::string> &overrides);
  };
} // namespace glissade
