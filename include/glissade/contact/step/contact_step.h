#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <glissade/contact/local_solvers/bipotential_solver.h>
#include <glissade/description/scene_description.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  class Body;
  class ContactProblem;

  /** What a contact step is built from. */
  struct ContactStepContext
  {
    const std::vector<std::unique_ptr<Body>> &bodies;
    /** The bodies of the contact pairs (indices into `bodies`). */
    const std::vector<unsigned int> &bodies_in_contact;
    /** The local solver's settings (section Contact solver). */
    const BiPotentialSolver::Settings &local_solver;
    dealii::TimerOutput               &timer;
    /** The scene's file, for messages. */
    const std::string &source;
  };

  /**
   * How a Newton iteration's step of the bodies in contact is found from
   * the active nodes (Contact solver/Method): one class per method, chosen
   * from the table of contact_step.cc. ContactProblem detects, projects
   * and linearises the nodes (whatever the discretisation); the step
   * solves.
   *
   * - condensed (condensed_step.cc): the paper's method, each body
   *   factorised alone and the problem condensed on the active nodes
   *   (W = H K^-1 H^T), the bi-potential local solver on it;
   * - sparse (sparse_contact_step.cc): the bodies in contact and the
   *   reactions in one sparse saddle-point system, an active-set
   *   iteration on it.
   */
  class ContactStep
  {
  public:
    virtual ~ContactStep() = default;

    /** After the increment's detection (the active set is known). */
    virtual void
    begin_step(ContactProblem & /*problem*/)
    {}

    /**
     * `increments[b]` holds body b's du_lib on entry and its Newton step
     * on exit; false if the step cannot be found (last_result() says why).
     */
    virtual bool
    correct(ContactProblem                      &problem,
            std::vector<dealii::Vector<double>> &increments) = 0;

    /**
     * True if this step computes body b's whole Newton step, so that the
     * Newton loop neither factorises nor solves it alone.
     */
    virtual bool
    solves_body(unsigned int /*b*/) const
    {
      return false;
    }

    /** Sweeps (or passes), outcome and statuses of the last solve. */
    const BiPotentialSolver::Result &
    last_result() const
    {
      return result;
    }

    /** The step of `method`. */
    static std::unique_ptr<ContactStep>
    create(ContactSolverSettings::Method method,
           const ContactStepContext     &context);

  protected:
    BiPotentialSolver::Result result;
  };
} // namespace glissade
