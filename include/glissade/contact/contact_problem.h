#pragma once

#include <glissade/body/body.h>
#include <glissade/contact/bipotential_solver.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/scene/scene_description.h>

#include <map>
#include <memory>
#include <vector>

namespace glissade
{
  /**
   * The contact part of a Newton iteration, on the system condensed to the
   * active contact nodes (paper eq. 8-10, shared/design/CONTACT_ALGORITHM.md):
   *
   * given each body's free step du_lib = K^-1 (F_ext - F_int), it
   * re-projects the active nodes, forms their free relative displacement
   * u_free = H du_lib (+ the gap, + the slip since the increment began), the
   * compliance W = H K^-1 H^T (from the block of K^-1 on the contact dofs
   * that the Cholesky factorisation gives, or one back-substitution per
   * contact dof when the tangent needs LU), solves the bi-potential
   * local problem for the reactions r, and returns the corrected step
   * du = du_lib + K^-1 H^T r. The contact forces H^T r are handed to the
   * bodies for their equilibrium residual.
   */
  class ContactProblem
  {
  public:
    /** `timer` receives the detection, W and local solve sections. */
    ContactProblem(const SceneDescription                   &scene,
                   const std::vector<std::unique_ptr<Body>> &bodies,
                   TimerOutput                              &timer);

    bool
    empty() const
    {
      return pairs.empty();
    }

    /** Detection at the start of an increment (alert distance). */
    void
    begin_step(const double time);

    /**
     * `increments[b]` holds body b's du_lib on entry and its corrected du on
     * exit; the bodies must be factorised. Returns false if the local
     * solver failed (the step is then cut back).
     */
    bool
    correct(std::vector<Vector<double>> &increments);

    unsigned int
    n_active() const;

    /** ContactPair::activate_penetrating_nodes over every pair. */
    unsigned int
    activate_penetrating_nodes();

    /**
     * The same at the state the free step would reach (u + du_lib): nodes
     * that it would take behind the master join the active set before the
     * step is taken, so that a small alert distance does not let a body
     * fall through its support in one iteration. The state is restored.
     */
    unsigned int
    activate_nodes_crossed_by(const std::vector<Vector<double>> &free_step);

    /** Sweeps and outcome of the last local solve. */
    const BiPotentialSolver::Result &
    last_result() const
    {
      return result;
    }

    std::vector<std::unique_ptr<ContactPair>> &
    contact_pairs()
    {
      return pairs;
    }

  private:
    /** Index of a body in the simulation's list. */
    unsigned int
    body_index(const Body *body) const;

    /**
     * K_b^-1 e_dof for a dof the contact maps touch, computed once per
     * Newton iteration however many nodes share it (one back-substitution
     * per contact dof and iteration).
     */
    const Vector<double> &
    column(const unsigned int body, const types::global_dof_index dof);

    const std::vector<std::unique_ptr<Body>> &bodies;
    TimerOutput                              &timer;
    std::vector<std::map<types::global_dof_index, Vector<double>>> columns;
    std::vector<std::unique_ptr<ContactPair>> pairs;
    BiPotentialSolver::Result                 result;
  };
} // namespace glissade
