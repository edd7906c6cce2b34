#pragma once

#include <glissade/contact/step/condensed_problem.h>
#include <glissade/contact/step/contact_step.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  struct ContactNode;

  /**
   * The paper's contact step (Contact solver/Method = condensed; eq. 8-10,
   * theory.md sections 4.3-4.5): each body factorised alone, the Newton
   * matrix condensed on the active nodes (CondensedProblem: W and the free
   * relative displacement), the bi-potential local problem solved on it
   * (with the active-set polish and the augmentation of the closed
   * directions where the tangent alone is indefinite), and the
   * corrector.
   */
  class CondensedStep : public ContactStep
  {
  public:
    explicit CondensedStep(const ContactStepContext &context);

    /** The touching dofs go last in the bodies' factorisations. */
    void
    begin_step(ContactProblem &problem) override;

    bool
    correct(ContactProblem                      &problem,
            std::vector<dealii::Vector<double>> &increments) override;

  private:
    /**
     * The reactions r of the active nodes (warm start on entry), and the
     * condensed problem whose Newton step goes with them; nullptr if the
     * local problem could not be solved.
     */
    std::unique_ptr<CondensedProblem>
    solve_local_problem(ContactProblem                            &problem,
                        const std::vector<ContactNode *>          &active,
                        const ActiveNodes                         &nodes,
                        const std::vector<dealii::Vector<double>> &predictor,
                        std::vector<BiPotentialSolver::Vector2>   &r);

    /**
     * The contact law on one condensed problem, from the reactions
     * `start` into r and `result`: Gauss-Seidel, then the active-set
     * iteration where W is not positive on the directions in play and
     * the statuses left those `held`. False if neither solved it (or the
     * problem is singular).
     */
    bool
    solve_contact_law(const CondensedProblem                        &condensed,
                      const ActiveNodes                             &nodes,
                      const std::vector<BiPotentialSolver::Vector2> &start,
                      const std::vector<std::array<bool, 2>>        &held,
                      const Augmentation                      &augmentation,
                      std::vector<BiPotentialSolver::Vector2> &r);

    /**
     * The message of `result` once every augmentation has failed: a body
     * that its contact does not hold, or a node where the bodies are
     * unstable (not_positive_at()).
     */
    void
    explain_failure(ContactProblem                   &problem,
                    const std::vector<ContactNode *> &active,
                    const CondensedProblem           &condensed);

    /**
     * Why the local problem failed, for a user, where a node's own
     * compliance in W is not positive (the first such node, its pair, its
     * bodies, what to change); empty if there is none.
     */
    std::string
    not_positive_at(ContactProblem                   &problem,
                    const std::vector<ContactNode *> &active,
                    const CondensedProblem           &condensed) const;

    /**
     * Each body's contact dofs to eliminate last in its Cholesky factor:
     * those the active nodes touch at the start of the increment
     * (BodyLinearSystem::set_contact_dofs, called when they change).
     */
    void
    eliminate_touching_dofs_last(ContactProblem &problem);

    const std::vector<std::unique_ptr<Body>>                 &bodies;
    const std::vector<unsigned int>                           bodies_in_contact;
    const BiPotentialSolver::Settings                         settings;
    dealii::TimerOutput                                      &timer;
    std::vector<std::vector<dealii::types::global_dof_index>> eliminated_last;
  };
} // namespace glissade
