// What a Simulation reports of its run: the progress line of an increment,
// the counters and times (statistics, summary, timing table), summary.txt,
// and the last converged state written before a stop.

#include <deal.II/base/timer.h>

#include <glissade/base/timing_sections.h>
#include <glissade/io/atomic_file.h>
#include <glissade/solver/simulation.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <string>

namespace glissade
{
  using namespace dealii;

  void
  Simulation::write_last_converged_state(const unsigned int increment)
  {
    try
      {
        // (every process: each writes its piece of the bodies' VTU)
        output->write_last_converged_state(increment, current_time);
        if (!writes_files)
          return;
        std::cerr << "glissade: the last converged state (increment "
                  << increment << ", t = " << current_time << ") is in "
                  << scene.output.directory << std::endl;
        output->draw_pictures();
      }
    catch (const std::exception &e)
      {
        std::cerr << "glissade: the last converged state could not be "
                     "written: "
                  << e.what() << std::endl;
      }
  }



  void
  Simulation::write_summary_file(const std::string &ending) const
  {
    if (!writes_files)
      return;
    AtomicFile file(scene.output.directory + "/summary.txt");
    file.stream() << summary() << '\n' << timing_table() << ending;
    file.commit();
  }



  void
  Simulation::report_increment(const unsigned int increment,
                               const unsigned int n_total,
                               const double       t,
                               const unsigned int iterations,
                               const std::string &remaining) const
  {
    std::cout << "increment " << std::setw(5) << increment << "/" << n_total
              << "  t = " << std::setw(10) << t << "  Newton iterations "
              << std::setw(2) << iterations << "  |R|/F = " << std::scientific
              << std::setprecision(2) << newton_loop->residuals().back()
              << std::defaultfloat << std::setprecision(6)
              << (contact_problem->empty() ?
                    std::string() :
                    "  active contact nodes " +
                      std::to_string(contact_problem->n_active()))
              << "  " << remaining << std::endl;
  }



  RunStatistics
  Simulation::statistics() const
  {
    RunStatistics                       total = stats;
    const std::map<std::string, double> sections =
      timer.get_summary_data(TimerOutput::total_wall_time);
    const auto seconds = [&](const char *section) {
      const auto found = sections.find(section);
      return found == sections.end() ? 0. : found->second;
    };
    total.assembly_seconds += seconds(timing::assembly);
    total.factorization_seconds += seconds(timing::factorization);
    total.solve_seconds += seconds(timing::predictor);
    total.detection_seconds += seconds(timing::detection);
    total.surface_build_seconds += seconds(timing::surface);
    total.compliance_seconds += seconds(timing::compliance);
    total.local_solve_seconds += seconds(timing::local_solve);
    total.output_seconds += seconds(timing::output);
    total.checkpoint_seconds += seconds(timing::checkpoints);
    for (const auto &body : all_bodies)
      {
        total.n_cholesky += body->system().direct_solver().n_cholesky;
        total.n_lu += body->system().direct_solver().n_lu;
        total.n_unchanged_tangents += body->system().direct_solver().n_reused;
      }
    return total;
  }



  unsigned int
  Simulation::n_dofs() const
  {
    unsigned int n = 0;
    for (const auto &b : all_bodies)
      n += b->n_unknowns();
    return n;
  }



  std::string
  Simulation::summary() const
  {
    std::string text =
      run_summary(statistics(), n_dofs(), !contact_problem->empty());
    if (const EnergyAccount *energies = integrator->energies())
      text += "\n" + energy_report(*energies);
    for (const auto &pair : contact_problem->contact_pairs())
      if (const std::string corners = pair->corner_report(); !corners.empty())
        text += "\n" + corners;
    return text;
  }



  std::string
  Simulation::timing_table() const
  {
    return glissade::timing_table(statistics(), !contact_problem->empty());
  }
} // namespace glissade
