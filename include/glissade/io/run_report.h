#pragma once

#include <glissade/body/energy_account.h>

#include <string>

namespace glissade
{
  /**
   * Counters and timings of a run, for the summary line, the timing table
   * and benchmarks. The times are the sections of the run's deal.II
   * TimerOutput (base/timing_sections.h); detection includes the surface
   * build.
   */
  struct RunStatistics
  {
    unsigned int increments            = 0;
    unsigned int newton_iterations     = 0;
    unsigned int cut_backs             = 0;
    double       assembly_seconds      = 0.;
    double       factorization_seconds = 0.;
    double       solve_seconds         = 0.;
    double       detection_seconds     = 0.;
    double       surface_build_seconds = 0.;
    double       compliance_seconds    = 0.;
    double       local_solve_seconds   = 0.;
    double       output_seconds        = 0.;
    double       checkpoint_seconds    = 0.;
    double       wall_seconds          = 0.;
    /** Factorisations of the bodies' tangents by each method (LU: the
     * tangent was not positive definite, or not symmetric). */
    unsigned int n_cholesky = 0, n_lu = 0;
    /** Last corrections solved with the previous factorisation
     *  (Newton/Last correction with previous tangent). */
    unsigned int n_reused_factorizations = 0;
    /** Tangents equal to the one last factorised, kept (a linear body at
     *  a constant time step). */
    unsigned int n_unchanged_tangents = 0;
  };

  /** "N increments, M Newton iterations, ... s wall (assembly ...)";
   *  `with_contact`: the contact parts too. */
  std::string
  run_summary(const RunStatistics &statistics,
              const unsigned int   n_dofs,
              const bool           with_contact);

  /**
   * A dynamic run's energies in one line: what the contact (its normal part
   * and friction), the damping and the scheme dissipated, and the balance;
   * then, if any step's contact did positive work beyond round-off, a
   * warning that names those steps by their end times.
   */
  std::string
  energy_report(const EnergyAccount &energies);

  /**
   * Where the wall time went: assembly, factorization, predictor solve,
   * contact detection, master surface build, compliance matrix, local
   * solve, output, checkpoints and the rest, in seconds, in percent and
   * per increment, and the count of each factorisation.
   */
  std::string
  timing_table(const RunStatistics &statistics, const bool with_contact);
} // namespace glissade
