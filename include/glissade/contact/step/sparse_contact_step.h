#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <glissade/contact/local_solvers/bipotential_solver.h>
#include <glissade/contact/step/condensed_problem.h>
#include <glissade/contact/step/contact_step.h>
#include <glissade/lac/direct_solver.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  class Body;

  /**
   * The Newton step of the bodies in contact solved as one sparse system,
   * without the dense compliance W (Contact solver/Method = sparse;
   * theory.md, section 4.7).
   *
   * The condensed method needs the block of each body's K^-1 on its contact
   * dofs and W = H K^-1 H^T, dense in the active nodes: at 20,000 active
   * nodes each is 40,000 x 40,000 (13 GB). Here the step of the bodies in
   * contact and the reactions of the active nodes are the unknowns of one
   * saddle-point system,
   *
   *   [ K - U V   -F ] [du]   [ rhs ]
   *   [   G        D ] [r ] = [ -g0 ],
   *
   * K the bodies' tangents (block-diagonal), U V the contact tangent's
   * rank-one terms (sparse: each couples a node's few dofs), F the forces of
   * unit reactions, and per node two rows chosen by its status: a closed
   * node's linearised gap g0 + G du = 0 (else r_n = 0); a sticking node's
   * linearised slip = 0, a slipping node's r_t = s mu r_n (friction against
   * the slip), an open or frictionless node's r_t = 0. The statuses follow a
   * primal-dual active-set iteration (Hueber and Wohlmuth): solve, then
   * open the nodes that pull, close those that penetrate, let slip those
   * beyond Coulomb's bound and stick those that would slip against their
   * friction, until nothing changes. Its answer is the contact law's, the
   * same as the bi-potential solver's on W; each pass costs one sparse LU
   * (UMFPACK) of the bodies' size.
   *
   * Constrained dofs take part through their constraints (u_c = sum w_j u_j
   * + b_c): a row on u_c acts on the u_j, a force on u_c is handed to the
   * u_j, and b_c moves to the right-hand side; fixed dofs drop out.
   */
  class SparseContactStep : public ContactStep
  {
  public:
    using Vector2    = ComplianceMatrix::Vector2;
    using NodeStatus = BiPotentialSolver::NodeStatus;

    /**
     * The bodies of the contact pairs (ContactStepContext::bodies_in_contact)
     * are those whose step this solves. Refuses (InputError) a body that
     * only contact holds.
     */
    explicit SparseContactStep(const ContactStepContext &context);

    bool
    correct(ContactProblem                      &problem,
            std::vector<dealii::Vector<double>> &increments) override;

    bool
    solves_body(const unsigned int b) const override
    {
      return std::find(in_contact.begin(), in_contact.end(), b) !=
             in_contact.end();
    }

    /**
     * One Newton correction. `status` and `r` hold the last ones on entry
     * (the warm start) and the new ones on exit; `increments[b]` receives
     * du of each body in contact. False, with `message`, if the statuses
     * do not settle or the system is singular.
     */
    bool
    solve(const ActiveNodes                   &nodes,
          std::vector<NodeStatus>             &status,
          std::vector<Vector2>                &r,
          std::vector<dealii::Vector<double>> &increments,
          std::string                         &message);

    /** Active-set passes (sparse LU factorisations) of the last solve. */
    unsigned int
    passes() const
    {
      return last_passes;
    }

  private:
    /** A global unknown and its weight: a dof's share after its constraint. */
    struct Share
    {
      unsigned int column;
      double       weight;
    };

    /**
     * The unknowns a dof of body `b` stands for, with its constant part
     * (the inhomogeneity of this iteration) in `constant`.
     */
    void
    expand(unsigned int        b,
           unsigned int        dof,
           std::vector<Share> &shares,
           double             &constant) const;

    /** A pair vector over global unknowns, and its constant part. */
    void
    expand(const PairVector   &v,
           std::vector<Share> &shares,
           double             &constant) const;

    /** Builds the pattern if the couplings changed (keeps the analysis). */
    void
    set_up_pattern(const ActiveNodes &nodes);

    /** The matrix and right-hand side for the given statuses. */
    void
    assemble(const ActiveNodes             &nodes,
             const std::vector<NodeStatus> &status,
             const std::vector<double>     &slip_sign);

    /**
     * The scale of the multiplier rows and columns: sets alpha to the
     * bodies' mean diagonal stiffness, and returns each body unknown's
     * |K_ii| (by global unknown).
     */
    std::vector<double>
    scale_reactions();

    /**
     * Each node's stiffness c_k for the status tests: trial_stiffness over
     * the estimate of its normal compliance from the diagonals.
     */
    std::vector<double>
    status_stiffness(const ActiveNodes         &nodes,
                     const std::vector<double> &diagonal) const;

    /**
     * Factorises and solves the assembled system into x; false, with
     * `message`, if it is singular.
     */
    bool
    solve_system(dealii::Vector<double> &x, std::string &message);

    /** The bodies' increments and the reactions r = alpha x from x. */
    void
    read_solution(const dealii::Vector<double>        &x,
                  std::vector<Vector2>                &r,
                  std::vector<dealii::Vector<double>> &increments) const;

    /**
     * The statuses (and slip signs) that the solution of a pass implies;
     * true if any changed.
     */
    bool
    update_statuses(const ActiveNodes                         &nodes,
                    const std::vector<Vector2>                &r,
                    const std::vector<dealii::Vector<double>> &increments,
                    const std::vector<double>                 &stiffness,
                    std::vector<NodeStatus>                   &status,
                    std::vector<double>                       &slip_sign) const;

    const std::vector<std::unique_ptr<Body>> &bodies;
    const std::vector<unsigned int>           in_contact;
    dealii::TimerOutput                      &timer;
    /** First global unknown of each body (invalid if not in contact). */
    std::vector<unsigned int>           offset;
    unsigned int                        n_body_unknowns = 0;
    std::vector<dealii::Vector<double>> inhomogeneity;
    /** The scale of the reaction unknowns and the multiplier rows. */
    double alpha = 1.;

    /**
     * A new pattern is a new object whenever the couplings change (the
     * factorisation keeps its analysis while the pattern is the same
     * object).
     */
    std::unique_ptr<dealii::SparsityPattern> pattern;
    dealii::SparseMatrix<double>             matrix;
    dealii::Vector<double>                   rhs;
    DirectSolver                             lu;
    unsigned int                             last_passes = 0;
  };
} // namespace glissade
