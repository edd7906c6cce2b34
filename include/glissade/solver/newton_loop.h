#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <glissade/body/body.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/description/scene_description.h>
#include <glissade/io/run_report.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The Newton iterations of one step, Simulation's first job: each
   * iteration assembles the bodies (one task each), tests convergence
   * (NewtonCriterion), factorises and solves each body alone (the
   * predictor), corrects with the contact step, and updates. The load
   * program around it (steps, cut-back, checkpoint, signals, output) is
   * Simulation's; the detection and the time scheme's step are begun by the
   * caller.
   */
  class NewtonLoop
  {
  public:
    /**
     * `statistics` receives the iterations and the corrections solved with
     * a previous factorisation; `progress` prints a contact failure.
     */
    NewtonLoop(const NewtonSettings                     &settings,
               const std::vector<std::unique_ptr<Body>> &bodies,
               ContactProblem                           &contact,
               dealii::TimerOutput                      &timer,
               RunStatistics                            &statistics,
               const bool                                progress);

    /**
     * Iterates to the state of the step begun by the caller. Returns false
     * if it did not converge (failure_cause() says why); the bodies' state
     * is then the last iteration's, for the caller to restore.
     */
    bool
    solve();

    /** The scaled residuals |R| / F of the last solve's iterations. */
    const std::vector<double> &
    residuals() const
    {
      return residual_history;
    }

    /** Why the last solve failed (empty if it did not). */
    const std::string &
    failure_cause() const
    {
      return cause;
    }

    /** The iterations of the last converged solve. */
    unsigned int
    iterations() const
    {
      return last_iterations;
    }

  private:
    /**
     * Assembles every body (with its tangent, or the residual alone);
     * returns false if one was not admissible. `residual` is the norm of
     * all the residuals, `scale` the largest force scale.
     */
    bool
    assemble_bodies(double &residual, double &scale, bool with_tangent = true);

    /** What made an assembly fail (the bodies' problems, or overflow). */
    std::string
    assembly_failure() const;

    /**
     * The contact-free step of every body the contact step does not solve,
     * with a new factorisation or the previous one; false (and the cause)
     * if a tangent cannot be factorised.
     */
    bool
    predict(const bool                           previous_tangent,
            std::vector<dealii::Vector<double>> &du);

    /** Adds the corrections; the norms of the correction and of u. */
    void
    update_bodies(const std::vector<dealii::Vector<double>> &du,
                  double                                    &increment_norm,
                  double                                    &displacement_norm);

    /** The iteration's line of the debug log (GLISSADE_DEBUG >= 1). */
    void
    log_iteration(const unsigned int                         iteration,
                  const double                               scaled_residual,
                  const std::vector<dealii::Vector<double>> &du,
                  const double                               increment_norm,
                  const double displacement_norm) const;

    const NewtonSettings                     &settings;
    const std::vector<std::unique_ptr<Body>> &bodies;
    ContactProblem                           &contact;
    dealii::TimerOutput                      &timer;
    RunStatistics                            &statistics;
    const bool                                progress;
    std::vector<double>                       residual_history;
    std::string                               cause;
    unsigned int                              last_iterations = 0;
  };
} // namespace glissade
