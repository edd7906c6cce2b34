#pragma once

#include <glissade/body/body.h>
#include <glissade/contact/step/contact_problem.h>
#include <glissade/description/scene_description.h>
#include <glissade/io/history_writer.h>
#include <glissade/io/run_report.h>
#include <glissade/io/scene_output.h>
#include <glissade/solver/newton_loop.h>
#include <glissade/solver/time_integrator.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * Runs a scene: the load program, increment by increment, each solved by
   * Newton-Raphson on the total Lagrangian equilibrium of every body.
   *
   * An increment whose Newton iteration does not converge (too many
   * iterations, a growing or non-finite residual, an inverted element) is
   * bisected, recursively, up to the load program's cut-back depth; if that
   * is not enough the run stops with a ConvergenceFailure that names the
   * increment and gives the residual history of the last attempt. Output
   * written until then stays valid.
   */
  class Simulation
  {
  public:
    explicit Simulation(const SceneDescription &description);

    /**
     * The whole load program, with output and the checkpoints the scene
     * asks for. With restart, continue from the checkpoint in the output
     * directory (InputError if it is missing, unreadable or of another
     * scene). Returns false if the run stopped at Checkpoint/Stop after
     * increment, true if it reached the end.
     */
    bool
    run(const bool restart = false);

    /** Called after every converged increment of run(): (increment, t). */
    std::function<void(unsigned int, double)> on_increment;

    /**
     * One step from the current state to time t (with cut-backs); returns
     * the number of Newton iterations. Throws ConvergenceFailure.
     */
    unsigned int
    advance_to(const double t, const std::string &label);

    Body &
    body(const std::string &name);

    const std::vector<std::unique_ptr<Body>> &
    bodies() const
    {
      return all_bodies;
    }

    /** The unknowns of every body. */
    unsigned int
    n_dofs() const;

    ContactProblem &
    contact()
    {
      return *contact_problem;
    }

    const ContactProblem &
    contact() const
    {
      return *contact_problem;
    }

    /** The energies of a dynamic scheme so far; nullptr if quasi-static. */
    const EnergyAccount *
    energies() const
    {
      return integrator->energies();
    }

    /** Scaled residuals |R|/scale of the Newton iterations of the last step. */
    const std::vector<double> &
    last_residuals() const
    {
      return newton_loop->residuals();
    }

    const HistoryWriter &
    history_writer() const
    {
      return *history;
    }

    /**
     * Counters and times so far: those restored from a checkpoint plus
     * this process's TimerOutput sections.
     */
    RunStatistics
    statistics() const;

    /** "N increments, M Newton iterations, ... s wall" */
    std::string
    summary() const;

    /**
     * Where the wall time went: assembly, factorization, predictor solve,
     * contact detection, master surface build, compliance matrix, local
     * solve, output, checkpoints and the rest, in seconds, in percent and
     * per increment (from the TimerOutput sections).
     */
    std::string
    timing_table() const;

  private:
    /** One Newton solve from the stored state (at t_start) to t, by the
     *  NewtonLoop; false if it failed. */
    bool
    newton(const double t_start, const double t);

    bool
    advance(const double t_start, const double t_end, const unsigned int depth);

    /**
     * Before a stop (an increment that failed, an input error found while
     * iterating): the VTU and contact tables of the last converged state
     * (SceneOutput), where they are, and the pictures.
     */
    void
    write_last_converged_state(const unsigned int increment);

    /**
     * Linear solver/Factors out of core: MUMPS's factors in files on
     * several processes; a note on one process, whose factorisations keep
     * them in memory.
     */
    void
    keep_factors_where_asked() const;

    /**
     * The state a run starts from: the initial state (recorded and
     * written), or with `restart` the checkpoint's; returns the increment
     * it is the state after.
     */
    unsigned int
    begin_run(const bool restart);

    /** An increment's progress line; `remaining`: the time left. */
    void
    report_increment(const unsigned int increment,
                     const unsigned int n_total,
                     const double       t,
                     const unsigned int iterations,
                     const std::string &remaining) const;

    /** Whether Checkpoint/Interval asks for a checkpoint after increment. */
    bool
    checkpoint_due(const unsigned int increment) const;

    /**
     * A stop on SIGINT or SIGTERM after increment (of n_total, at t): its
     * checkpoint, its output and summary, then RunInterrupted.
     */
    [[noreturn]] void
    stop_on_signal(const int          signal,
                   const unsigned int increment,
                   const unsigned int n_total,
                   const double       t,
                   const bool         last);

    /** summary.txt: the summary line, the timing table, and `ending`. */
    void
    write_summary_file(const std::string &ending) const;

    /** Progress lines: asked for, and this process prints them. */
    bool
    shows_progress() const
    {
      return scene.output.progress && writes_files;
    }

    /** <Output directory>/checkpoint.bin */
    std::string
    checkpoint_file() const;

    /** The state after the increment, written atomically. */
    void
    write_checkpoint(const unsigned int increment);

    /** Restores the state; returns the increment it was written after. */
    unsigned int
    read_checkpoint();

    /** Both directions of the checkpoint (source/solver/checkpoint.cc). */
    template <class Archive>
    void
    serialize_state(Archive &archive);

    const SceneDescription scene;
    /** Every timed part of the run (never printed by itself). */
    dealii::TimerOutput                timer;
    std::vector<std::unique_ptr<Body>> all_bodies;
    std::unique_ptr<ContactProblem>    contact_problem;
    /** Quasi-static or dynamic (Time integration/Scheme). */
    std::unique_ptr<TimeIntegrator> integrator;
    std::unique_ptr<HistoryWriter>  history;
    /** The VTU, PVD and contact files written as the run goes. */
    std::unique_ptr<SceneOutput> output;
    /** The Newton iterations of a step (its residuals, why it failed). */
    std::unique_ptr<NewtonLoop> newton_loop;
    /** Counters; times restored from a checkpoint (0 in a fresh run). */
    RunStatistics stats;
    /**
     * True on the process that writes the files (process 0 of a run on
     * several: every process holds the whole state, doc/parallel.md).
     */
    const bool   writes_files;
    unsigned int iterations_of_step = 0;
    double       current_time       = 0.;
  };
} // namespace glissade
