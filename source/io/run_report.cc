#include <glissade/base/timing_sections.h>
#include <glissade/io/run_report.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace glissade
{
  std::string
  run_summary(const RunStatistics &s,
              const unsigned int   n_dofs,
              const bool           with_contact)
  {
    std::ostringstream out;
    out << std::setprecision(3) << "glissade: " << s.increments
        << " increments, " << s.newton_iterations << " Newton iterations, "
        << s.cut_backs << " cut-backs, " << n_dofs << " dofs, "
        << s.wall_seconds << " s wall (assembly " << s.assembly_seconds
        << " s, factorization " << s.factorization_seconds << " s";
    if (with_contact)
      out << ", contact detection " << s.detection_seconds << " s, compliance "
          << s.compliance_seconds << " s, local solve " << s.local_solve_seconds
          << " s";
    out << ")";
    return out.str();
  }


  std::string
  energy_report(const EnergyAccount &e)
  {
    std::ostringstream out;
    out << std::setprecision(4) << "energies: kinetic " << e.kinetic
        << ", stored " << e.strain << ", work of the loads " << e.work_of_loads
        << "; dissipated by the contact " << e.contact_dissipation()
        << ", by friction " << e.friction_dissipation << ", by the damping "
        << e.damping_dissipation << ", by the scheme " << e.scheme_dissipation
        << "; balance " << e.balance();
    if (e.contact_creating_steps > 0)
      {
        out << "\nwarning: the contact created energy in "
            << e.contact_creating_steps << " step"
            << (e.contact_creating_steps > 1 ? "s" : "") << " ("
            << e.contact_created << " in all; the largest, "
            << e.largest_created
            << ", in the step ending at t = " << e.largest_created_at
            << "); steps ending at t =";
        for (unsigned int k = 0; k < e.contact_creating_times.size(); ++k)
          out << (k > 0 ? ", " : " ") << e.contact_creating_times[k];
        if (e.contact_creating_steps > e.contact_creating_times.size())
          out << ", ...";
        out << ". The contact laws make each step's work <= 0; it is not "
               "where a node starts behind the master (pushed out, it gets "
               "r_n times its penetration) or where a curved master's gap, "
               "linearised over the step, bends away under a long slide "
               "(smaller steps shrink what that creates; doc/theory.md, "
               "'Energy')";
      }
    return out.str();
  }



  std::string
  timing_table(const RunStatistics &s, const bool with_contact)
  {
    std::vector<std::pair<std::string, double>> rows = {
      {timing::assembly, s.assembly_seconds},
      {timing::factorization, s.factorization_seconds},
      {timing::predictor, s.solve_seconds}};
    if (with_contact)
      {
        // The detection section contains the surface build: shown apart.
        rows.emplace_back(timing::detection,
                          s.detection_seconds - s.surface_build_seconds);
        rows.emplace_back(timing::surface, s.surface_build_seconds);
        rows.emplace_back(timing::compliance, s.compliance_seconds);
        rows.emplace_back(timing::local_solve, s.local_solve_seconds);
      }
    rows.emplace_back(timing::output, s.output_seconds);
    if (s.checkpoint_seconds > 0.)
      rows.emplace_back(timing::checkpoints, s.checkpoint_seconds);
    double accounted = 0.;
    for (const auto &row : rows)
      accounted += row.second;
    rows.emplace_back("other (corrector, bookkeeping)",
                      std::max(0., s.wall_seconds - accounted));

    std::ostringstream table;
    const double       total = std::max(s.wall_seconds, 1e-300);
    const double       per   = 1000. / std::max(1u, s.increments);
    table << std::fixed << "  " << std::left << std::setw(36)
          << "part of the run (deal.II TimerOutput)" << std::right
          << std::setw(11) << "wall (s)" << std::setw(8) << "%" << std::setw(20)
          << "per increment (ms)" << '\n';
    for (const auto &[name, seconds] : rows)
      table << "  " << std::left << std::setw(36) << name << std::right
            << std::setw(11) << std::setprecision(3) << seconds << std::setw(8)
            << std::setprecision(1) << 100. * seconds / total << std::setw(20)
            << std::setprecision(2) << seconds * per << '\n';
    table << "  " << std::left << std::setw(36) << "total" << std::right
          << std::setw(11) << std::setprecision(3) << s.wall_seconds
          << std::setw(8) << "100.0" << std::setw(20) << std::setprecision(2)
          << s.wall_seconds * per << '\n';
    table << "  factorisations: " << s.n_cholesky << " Cholesky, " << s.n_lu
          << " LU (a tangent that is not positive definite, or not "
             "symmetric); "
          << s.n_reused_factorizations
          << " last corrections with the previous one; "
          << s.n_unchanged_tangents << " tangents unchanged (kept)\n";
    return table.str();
  }
} // namespace glissade
