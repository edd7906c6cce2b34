#include <deal.II/base/data_out_base.h>
#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/freed_memory.h>
#include <glissade/base/input_error.h>
#include <glissade/base/interruption.h>
#include <glissade/base/processes.h>
#include <glissade/base/progress_text.h>
#include <glissade/base/timing_sections.h>
#include <glissade/contact/folding_corner.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/directory_lock.h>
#include <glissade/io/plotting.h>
#include <glissade/io/pvd_index.h>
#include <glissade/lac/mumps_factorization.h>
#include <glissade/solver/newton_loop.h>
#include <glissade/solver/simulation.h>
#include <glissade/solver/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  using progress_text::duration;
  using progress_text::time_left;

  namespace
  {
    /**
     * Runs `check`, which may refuse the scene (InputError) on some
     * processes only (a directory only one can make or write): the first
     * refusal is every process's, or the others would wait for the one
     * that stopped.
     */
    void
    refuse_on_every_process(const std::function<void()> &check)
    {
      std::string refused;
      try
        {
          check();
        }
      catch (const InputError &e)
        {
          refused = e.what();
        }
      refused = processes::first_message(refused);
      if (!refused.empty())
        throw InputError("", refused);
    }
  } // namespace



  // (the body reads the member scene, the description's copy: what it
  // hands on by reference must live as long as the Simulation, and a
  // description given as a temporary does not)
  Simulation::Simulation(const SceneDescription &description)
    : scene(description)
    , timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
    , writes_files(processes::writes_files())
  {
    // Every body is built, and its boundary names checked against its mesh,
    // before the first mistake is reported: all of them in one message.
    InputErrorList mistakes;
    Timer          setup;
    for (const auto &description : scene.bodies)
      mistakes.collect([&]() {
        all_bodies.push_back(std::make_unique<Body>(description, scene.source));
        // A large mesh takes a while to set up: say what is happening.
        // (on several processes, whether its mesh is shared out: process
        // 0's count of the cells it holds)
        const Body &body = *all_bodies.back();
        if (shows_progress())
          std::cout
            << "body '" << description.name << "': " << body.n_cells()
            << " cells, " << body.n_unknowns() << " dofs"
            << processes::mesh_held_here(body.mesh_is_distributed(),
                                         body.triangulation().n_active_cells())
            << " (set up, elapsed " << duration(setup.wall_time()) << ")"
            << std::endl;
      });
    mistakes.throw_if_any();
    // (a dynamic scheme's inertia holds the rigid motions that no support
    // does, which the contact problem checks: the scheme first)
    integrator = TimeIntegrator::create(scene, all_bodies);
    contact_problem =
      std::make_unique<ContactProblem>(scene, all_bodies, timer);
    integrator->attach(*contact_problem);
    // Slave nodes behind their master at the start, deeper than the
    // alert distance but not so deep as to refuse the scene: said before
    // anything is computed (an interference fit's load, or a mistake).
    if (writes_files)
      for (const auto &pair : contact_problem->contact_pairs())
        if (!pair->initial_overlap().empty())
          std::cout << "warning: contact pair '" << pair->name()
                    << "': " << pair->initial_overlap() << std::endl;
    newton_loop = std::make_unique<NewtonLoop>(scene.newton,
                                               all_bodies,
                                               *contact_problem,
                                               timer,
                                               stats,
                                               shows_progress());
    output      = std::make_unique<SceneOutput>(scene.output,
                                           all_bodies,
                                           *contact_problem,
                                           timer);
    history =
      std::make_unique<HistoryWriter>(scene.output.history,
                                      all_bodies,
                                      *contact_problem,
                                      scene.output.directory + "/history.csv",
                                      scene.source,
                                      integrator->energies());
    // The curves to plot name history columns: known only now.
    const auto &columns = history->column_names();
    for (const auto &[x, y] : scene.output.plot_curves)
      for (const std::string &name : {x, y})
        if (name != "time" &&
            std::find(columns.begin(), columns.end(), name) == columns.end())
          {
            std::string known = "time";
            for (const std::string &c : columns)
              if (c != "increment" && c != "time")
                known += ", " + c;
            throw InputError(scene.source + ": Output/Plot curves",
                             "'" + name + "' is not a column of history.csv (" +
                               known + ")");
          }
  }



  Body &
  Simulation::body(const std::string &name)
  {
    for (auto &b : all_bodies)
      if (b->name() == name)
        return *b;
    throw InputError(scene.source, "there is no body '" + name + "'");
  }



  bool
  Simulation::newton(const double t_start, const double t)
  {
    for (auto &b : all_bodies)
      b->set_time(t);
    // Detection at the start of the load step, from the current state.
    contact_problem->begin_step(t_start, t);
    integrator->begin_step(t_start, t);
    if (!newton_loop->solve())
      return false;
    iterations_of_step += newton_loop->iterations();
    return true;
  }



  bool
  Simulation::advance(const double       t_start,
                      const double       t_end,
                      const unsigned int depth)
  {
    for (auto &b : all_bodies)
      b->store_state();
    contact_problem->store_state();
    try
      {
        if (newton(t_start, t_end))
          {
            integrator->accept_step(t_end);
            contact_problem->accept_step();
            return true;
          }
      }
    catch (...)
      {
        // An input error found while iterating (an expression that is not
        // finite at this time): the state goes back to the last converged
        // one, which the caller may still write.
        for (auto &b : all_bodies)
          b->restore_state();
        contact_problem->restore_state();
        throw;
      }
    for (auto &b : all_bodies)
      b->restore_state();
    contact_problem->restore_state();
    if (depth >= scene.load_program.max_cut_back_depth)
      return false;

    ++stats.cut_backs;
    if (shows_progress())
      std::cout << "    cut-back: t = " << t_start << " -> " << t_end
                << " bisected" << std::endl;
    const double t_mid = 0.5 * (t_start + t_end);
    return advance(t_start, t_mid, depth + 1) &&
           advance(t_mid, t_end, depth + 1);
  }



  unsigned int
  Simulation::advance_to(const double t, const std::string &label)
  {
    iterations_of_step   = 0;
    const double t_start = current_time;
    if (!advance(t_start, t, 0))
      {
        std::ostringstream message;
        message << label << " (t = " << t_start << " -> " << t
                << ") did not converge after "
                << scene.load_program.max_cut_back_depth
                << " cut-backs. Scaled residuals |R|/max(|F_int|, |F_ext|) "
                   "of the last attempt:";
        for (const double r : newton_loop->residuals())
          message << ' ' << std::setprecision(3) << r;
        if (newton_loop->residuals().empty())
          message << " none (its first assembly failed)";
        if (!newton_loop->failure_cause().empty())
          message << ". Cause of the last attempt's failure: "
                  << newton_loop->failure_cause();
        // (the state is the last converged one again: what it shows)
        for (const auto &pair : contact_problem->contact_pairs())
          if (const std::string fold = describe_folding_corner(*pair);
              !fold.empty())
            {
              message << ". What happened: " << fold;
              break;
            }
        throw ConvergenceFailure(message.str());
      }
    current_time = t;
    return iterations_of_step;
  }



  void
  Simulation::keep_factors_where_asked() const
  {
    const LinearSolverSettings &settings = scene.linear_solver;
    if (!settings.factors_out_of_core)
      return;
    if (!processes::shared_out())
      {
        std::cout << "note: " << scene.source
                  << ": Linear solver/Factors out of core applies to runs on "
                     "several processes (MUMPS); one process keeps its "
                     "factors in memory (CHOLMOD, UMFPACK)"
                  << std::endl;
        return;
      }
    // (every process writes its own files)
    refuse_on_every_process([&]() {
      MumpsFactorization::keep_factors_out_of_core(
        settings.out_of_core_directory,
        scene.source + ": Linear solver/Out-of-core directory");
    });
  }



  bool
  Simulation::run(const bool restart)
  {
    Timer wall;
    // One run per output directory at a time (held until run() returns),
    // held by the process that writes the files.
    std::optional<DirectoryLock> output_lock;
    refuse_on_every_process([&]() {
      if (writes_files)
        output_lock.emplace(scene.output.directory,
                            scene.source + ": Output/Directory");
    });
    keep_factors_where_asked();

    const LoadProgram &program = scene.load_program;
    unsigned int       n_total = 0;
    for (const unsigned int n : program.stage_increments)
      n_total += n;

    const unsigned int restart_increment = begin_run(restart);
    const double       wall_before       = stats.wall_seconds;

    unsigned int increment = 0;
    double       t_begin   = 0.;
    bool         completed = true;
    for (unsigned int stage = 0;
         stage < program.stage_end_times.size() && completed;
         ++stage)
      {
        const double       t_end = program.stage_end_times[stage];
        const unsigned int n     = program.stage_increments[stage];
        for (unsigned int k = 1; k <= n; ++k)
          {
            ++increment;
            // The same formula for t as the uninterrupted run: the same bits.
            const double t = t_begin + (t_end - t_begin) * double(k) / n;
            if (increment <= restart_increment)
              continue;
            unsigned int iterations = 0;
            try
              {
                iterations =
                  advance_to(t, "increment " + std::to_string(increment));
              }
            catch (...)
              {
                history->write();
                write_last_converged_state(increment - 1);
                throw;
              }
            ++stats.increments;
            for (auto &pair : contact_problem->contact_pairs())
              pair->measure_corners(t);
            if (shows_progress())
              report_increment(increment,
                               n_total,
                               t,
                               iterations,
                               time_left(wall.wall_time(),
                                         increment - restart_increment,
                                         n_total - increment));
            history->record(increment, t, iterations);
            if (on_increment)
              on_increment(increment, t);
            const bool last = (increment == n_total);
            output->write_increment(increment, t, last);

            const bool stop = (increment == scene.checkpoint.stop_after);
            if (stop || checkpoint_due(increment))
              {
                stats.wall_seconds = wall_before + wall.wall_time();
                history->write();
                write_checkpoint(increment);
                if (shows_progress())
                  std::cout << "checkpoint after increment " << increment
                            << ": " << checkpoint_file() << std::endl;
              }
            if (stop)
              {
                completed = false;
                break;
              }
            // (every process stops after the same increment: the largest signal
            // number any of them received)
            if (const int signal =
                  processes::maximum(interruption::signal_received()))
              {
                history->write();
                stats.wall_seconds = wall_before + wall.wall_time();
                stop_on_signal(signal, increment, n_total, t, last);
              }
          }
        t_begin = t_end;
      }
    history->write();
    stats.wall_seconds = wall_before + wall.wall_time();

    write_summary_file(
      completed ? std::string() :
                  "stopped after increment " + std::to_string(increment) +
                    " of " + std::to_string(n_total) +
                    " (Checkpoint/Stop after increment); continue with "
                    "--restart\n");
    if (writes_files)
      output->draw_pictures();
    return completed;
  }



  unsigned int
  Simulation::begin_run(const bool restart)
  {
    if (!restart)
      {
        integrator->initialize();
        history->record(0, 0., 0);
        output->write_initial_state();
        return 0;
      }
    const unsigned int restart_increment = read_checkpoint();
    if (shows_progress())
      std::cout << "restart after increment " << restart_increment
                << " (t = " << current_time << ") from " << checkpoint_file()
                << std::endl;
    return restart_increment;
  }
} // namespace glissade
