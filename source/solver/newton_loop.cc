// The Newton iterations of a step (NewtonLoop): Simulation's first job,
// the load program around it being Simulation's.

#include <deal.II/base/thread_management.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/freed_memory.h>
#include <glissade/base/memory_use.h>
#include <glissade/base/processes.h>
#include <glissade/base/timing_sections.h>
#include <glissade/solver/newton_criterion.h>
#include <glissade/solver/newton_loop.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <stdexcept>

namespace glissade
{
  using namespace dealii;

  NewtonLoop::NewtonLoop(const NewtonSettings                     &settings,
                         const std::vector<std::unique_ptr<Body>> &bodies,
                         ContactProblem                           &contact,
                         TimerOutput                              &timer,
                         RunStatistics                            &statistics,
                         const bool                                progress)
    : settings(settings)
    , bodies(bodies)
    , contact(contact)
    , timer(timer)
    , statistics(statistics)
    , progress(progress)
  {}



  bool
  NewtonLoop::solve()
  {
    residual_history.clear();
    cause.clear();
    last_iterations     = 0;
    double       size   = 0.;
    unsigned int n_dofs = 0;
    for (auto &b : bodies)
      {
        size = std::max(size, b->size());
        n_dofs += b->n_unknowns();
      }
    NewtonCriterion criterion(settings.residual_tolerance,
                              settings.displacement_tolerance,
                              size,
                              n_dofs);

    // At small strain every body's tangent is the same matrix through the
    // increment (K_e kept, the inertia's and damping's terms fixed by the
    // step, pressures on the undeformed body): a correction after the
    // first is exact with the factorisation the first made. Where each
    // body is solved alone (the condensed contact method) the iterations
    // after the first then assemble the residual alone, which tests
    // convergence and drives that correction: a quasi-static or dynamic
    // step makes one tangent instead of three (Body::residual_alone_is_
    // cheap). The tangent is assembled again where a factorisation follows
    // (a node that went behind the master).
    bool affine_bodies = true;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      affine_bodies = affine_bodies && bodies[b]->residual_alone_is_cheap() &&
                      !contact.solves_body(b);

    bool factorized_last_iteration = false;
    for (unsigned int iteration = 0; iteration <= settings.max_iterations;
         ++iteration)
      {
        double     residual = 0., scale = 0.;
        const bool with_tangent = !affine_bodies || iteration == 0;
        const bool admissible = assemble_bodies(residual, scale, with_tangent);
        log_memory_use("the assembly");
        // (on several processes: each decision below is taken alike by all
        // of them only if they hold the same numbers)
        processes::check_identical(residual, "the Newton residual");
        if (!admissible || !std::isfinite(residual))
          {
            cause = assembly_failure();
            return false;
          }
        criterion.add_residual(iteration, residual, scale);
        const double scaled = scale > 0. ? residual / scale : residual;
        residual_history.push_back(scaled);

        // At least one correction per step (NewtonCriterion): at iteration
        // 0 the prescribed displacements of the new time are not applied.
        const bool converged = criterion.converged();
        // A converged state with a slave node behind the master that was
        // not active (beyond the alert distance at the start of the
        // increment) is not a solution: iterate on with that node.
        const unsigned int newly_active =
          converged && !contact.empty() && contact.position_law() ?
            contact.activate_penetrating_nodes() :
            0;
        if (converged && newly_active == 0)
          {
            last_iterations = iteration;
            statistics.newton_iterations += iteration;
            return true;
          }
        if (newly_active > 0 && debug_log::at(1))
          debug_log::stream()
            << "  it " << iteration << ": " << newly_active
            << " slave nodes went behind the master; now active" << std::endl;
        if (iteration == settings.max_iterations)
          break;
        if (criterion.diverges())
          {
            cause = "Newton diverges: the residual grew by more than "
                    "1e8 over its first value";
            return false;
          }

        // A correction that only confirms a converged state for the
        // displacement test is solved with the last factorisation
        // (NewtonCriterion::confirms_only), once per factorisation; the
        // contact's own terms are those of the current state all the same.
        // Affine bodies keep the first iteration's factorisation through
        // the increment (exact for them).
        const bool previous_tangent =
          settings.last_correction_with_previous_tangent && newly_active == 0 &&
          ((factorized_last_iteration && criterion.confirms_only()) ||
           (affine_bodies && iteration > 0));
        factorized_last_iteration = !previous_tangent;
        if (!with_tangent && !previous_tangent)
          {
            // (the same state: the same residual, now with its tangent)
            double again = 0., again_scale = 0.;
            if (!assemble_bodies(again, again_scale, true))
              {
                cause = assembly_failure();
                return false;
              }
          }

        // Predictor: the contact-free step of every body; then the contact
        // correction on the condensed system; then the update.
        std::vector<Vector<double>> du(bodies.size());
        if (!predict(previous_tangent, du))
          return false;
        log_memory_use("the factorisations");
        if (!contact.empty() && !contact.correct(du))
          {
            cause = "the contact problem: " + contact.last_result().message;
            if (progress)
              std::cout << "    contact: " << contact.last_result().message
                        << std::endl;
            return false;
          }
        if (!contact.empty())
          log_memory_use("the contact correction");
        double last_increment = 0., displacement_norm = 0.;
        update_bodies(du, last_increment, displacement_norm);
        criterion.add_correction(last_increment, displacement_norm);
        if (!contact.empty())
          contact.update_state();
        if (debug_log::at(1))
          log_iteration(
            iteration, scaled, du, last_increment, displacement_norm);
        if (!std::isfinite(last_increment))
          {
            cause = "the Newton correction is not finite (a singular "
                    "tangent: a body or a rigid-body mode without "
                    "support?)";
            return false;
          }
      }
    statistics.newton_iterations += settings.max_iterations;
    cause = "no convergence in Newton/Maximum iterations = " +
            std::to_string(settings.max_iterations);
    return false;
  }



  bool
  NewtonLoop::assemble_bodies(double    &residual,
                              double    &scale,
                              const bool with_tangent)
  {
    TimerOutput::Scope scope(timer, timing::assembly);
    // (the last iteration's contact algebra and factorisations' workspace
    // are free: their pages go back before the new tangent is made)
    return_freed_memory();
    // The bodies are independent until the contact correction: one task
    // each, on both cores (the same arithmetic as one after the other). The
    // factorisations stay in sequence: they call the threaded BLAS, and two
    // at once took 1.7 times as long (doc/performance.md).
    // What a body's assembly throws (a boundary datum that is not finite:
    // an input error naming it) is rethrown here, the first body's first,
    // as the sequential loop would have.
    std::vector<char>               assembled(bodies.size());
    std::vector<std::exception_ptr> thrown(bodies.size());
    Threads::TaskGroup<void>        tasks;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      tasks += Threads::new_task([&, b]() {
        try
          {
            assembled[b] = bodies[b]->assemble(with_tangent);
          }
        catch (...)
          {
            thrown[b] = std::current_exception();
          }
      });
    tasks.join_all();
    for (const std::exception_ptr &e : thrown)
      if (e)
        std::rethrow_exception(e);
    bool   admissible       = true;
    double residual_squared = 0.;
    scale                   = 0.;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        admissible = assembled[b] && admissible;
        residual_squared += std::pow(bodies[b]->residual_norm(), 2);
        scale = std::max(scale, bodies[b]->force_scale());
      }
    residual = std::sqrt(residual_squared);
    return admissible;
  }



  std::string
  NewtonLoop::assembly_failure() const
  {
    std::string cause;
    for (auto &b : bodies)
      if (!b->assembly_problem().empty())
        cause += (cause.empty() ? "" : "; ") + b->assembly_problem();
    if (cause.empty())
      cause = "the residual overflows double precision (loads or prescribed "
              "displacements too large for the bodies' stiffness?)";
    return cause;
  }



  bool
  NewtonLoop::predict(const bool                   previous_tangent,
                      std::vector<Vector<double>> &du)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        // (with the sparse contact method, the contact step solves the
        // bodies in contact together)
        if (contact.solves_body(b))
          continue;
        try
          {
            TimerOutput::Scope scope(timer, timing::factorization);
            if (previous_tangent)
              ++statistics.n_reused_factorizations;
            else
              bodies[b]->system().factorize();
            // (the condensed method and a body out of contact read the
            // factor alone until the next assembly, which makes the tangent
            // again: with the previous factor too)
            bodies[b]->system().release_tangent();
          }
        catch (const std::runtime_error &e)
          {
            // A singular tangent: a structural limit point (free rigid-body
            // motions are refused before computing, or regularised where
            // contact holds them).
            cause = "the tangent of body '" + bodies[b]->name() +
                    "' cannot be factorised: " + e.what();
            return false;
          }
        TimerOutput::Scope scope(timer, timing::predictor);
        bodies[b]->system().solve(bodies[b]->system().right_hand_side(), du[b]);
      }
    // (the factorisations' workspace, before the contact algebra's blocks)
    return_freed_memory();
    return true;
  }



  void
  NewtonLoop::update_bodies(const std::vector<Vector<double>> &du,
                            double                            &increment_norm,
                            double &displacement_norm)
  {
    double increment_squared = 0., displacement_squared = 0.;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        bodies[b]->update(du[b]);
        increment_squared += du[b].norm_sqr();
        displacement_squared += bodies[b]->displacement().norm_sqr();
      }
    increment_norm    = std::sqrt(increment_squared);
    displacement_norm = std::sqrt(displacement_squared);
  }



  void
  NewtonLoop::log_iteration(const unsigned int                 iteration,
                            const double                       scaled_residual,
                            const std::vector<Vector<double>> &du,
                            const double                       increment_norm,
                            const double displacement_norm) const
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      debug_log::stream() << "    body " << b << " |du| " << du[b].l2_norm()
                          << " max " << du[b].linfty_norm() << " |u| "
                          << bodies[b]->displacement().l2_norm() << std::endl;
    debug_log::stream() << "  it " << iteration << " |R|/F " << scaled_residual
                        << " |du| " << increment_norm << " |u| "
                        << displacement_norm << " active " << contact.n_active()
                        << " sweeps " << contact.last_result().sweeps
                        << std::endl;
  }
} // namespace glissade
