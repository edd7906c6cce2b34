#pragma once

#include <glissade/body/body.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/local_solvers/bipotential_solver.h>
#include <glissade/contact/step/broad_phase.h>
#include <glissade/contact/step/condensed_problem.h>
#include <glissade/contact/step/contact_step.h>
#include <glissade/description/scene_description.h>

#include <algorithm>
#include <deque>
#include <memory>
#include <vector>

namespace glissade
{
  /**
   * The contact part of a Newton iteration: the pairs' detection and
   * active sets, the active nodes as the steps see them (their rows,
   * forces and contact tangent terms, whatever the pairs'
   * discretisation), and the step that solves them (ContactStep, chosen by
   * Contact solver/Method: condensed on the active nodes, the paper's
   * eq. 8-10, or sparse). The contact forces H^T r are handed to the
   * bodies for their equilibrium residual.
   */
  class ContactProblem
  {
  public:
    /** `timer` receives the detection, W and local solve sections. */
    ContactProblem(const SceneDescription                   &scene,
                   const std::vector<std::unique_ptr<Body>> &bodies,
                   dealii::TimerOutput                      &timer);

    /** No pair, and none to be made (automatic contact makes its pairs
     *  when bodies come within reach). */
    bool
    empty() const
    {
      return pairs.empty() && automatic.empty();
    }

    /** Detection for the increment from step_start_time to time. */
    void
    begin_step(const double step_start_time, const double time);

    /**
     * `increments[b]` holds body b's du_lib on entry and its Newton step on
     * exit; the bodies must be factorised. Returns false if the local
     * solver failed or the consistent tangent is singular (the step is
     * then cut back). With Contact solver/Method = sparse, the bodies in
     * contact are neither factorised nor solved alone (solves_body()):
     * their step comes from one sparse system with the active nodes'
     * reactions (SparseContactStep), and the other bodies' increments are
     * left as they are.
     */
    bool
    correct(std::vector<dealii::Vector<double>> &increments);

    /**
     * True if the contact step computes body b's whole Newton step (the
     * sparse method, a body of a contact pair): the Newton loop then does
     * not factorise it.
     */
    bool
    solves_body(const unsigned int b) const
    {
      return step->solves_body(b);
    }

    /**
     * After the bodies took the Newton step: re-projects and linearises
     * the active nodes at the new state (the contact tangent at the new
     * reactions) and hands the bodies the forces of the reactions there.
     */
    void
    update_state();

    /**
     * After a converged step: what the step leaves behind besides the
     * bodies' state, an abradable coating's wear (ContactPair::
     * wear_coating()).
     */
    void
    accept_step();

    /** Saves and restores the nodes' state (for cut-backs). */
    void
    store_state();
    void
    restore_state();

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
    activate_nodes_crossed_by(
      const std::vector<dealii::Vector<double>> &free_step);

    /**
     * The active nodes of every pair as the condensed problem sees them
     * (their rows, loads and contact tangent terms, which stay valid until
     * the nodes are projected again), and pointers to them in `active`.
     */
    ActiveNodes
    active_nodes(std::vector<ContactNode *> &active);

    /** Sweeps and outcome of the last local solve. */
    const BiPotentialSolver::Result &
    last_result() const
    {
      return step->last_result();
    }

    /** Every pair made so far: written, a body on itself, and the
     *  couples' of automatic contact in the order they were made. */
    std::vector<std::unique_ptr<ContactPair>> &
    contact_pairs()
    {
      return pairs;
    }

    /**
     * The pair named `name`, or nullptr if there is none. The pair of an
     * automatic couple not made yet is made (with its couple's other pass),
     * resting until its bodies come within reach.
     */
    ContactPair *
    pair_named(const std::string &name);

    /** The names of the couples' pairs made so far, in that order (a
     *  checkpoint makes them again before it reads their nodes). */
    std::vector<std::string>
    automatic_pair_names() const;

    /**
     * Every dof of `body` that contact may ever touch: the pairs' and, for
     * a body of Scene/Contact bodies, its listed boundary's (which pairs
     * made later will touch). The bodies eliminate them last; a dynamic
     * scheme's redistributed mass takes theirs away.
     */
    std::vector<dealii::types::global_dof_index>
    contact_dofs(const Body &body) const;

    /** ContactPair::report_forces_scaled_by for every pair, and for the
     *  pairs made later. */
    void
    report_forces_scaled_by(const double scale);

    /**
     * The contact law on the end velocities of a step (Moreau-Jean's, with
     * each node's law_shift) instead of on its end position: the time
     * integrator chooses which nodes take part in a step, so a node that
     * goes behind the master is not pulled in within it.
     */
    void
    use_velocity_law()
    {
      velocity_law = true;
    }

    /** False under a velocity-level law (use_velocity_law()). */
    bool
    position_law() const
    {
      return !velocity_law;
    }

    /**
     * "the contact does not hold the bodies that rely on it, 'b' (a
     * translation along (1, 0))", or empty if no body relies on contact.
     */
    std::string
    held_by_contact_message() const;

    /** The body of that name, or nullptr (the scene reader checked the
     *  names a pair gives). */
    Body *
    body_named(const std::string &name) const;

    /** Index of a body in the simulation's list. */
    unsigned int
    body_index(const Body *body) const;

  private:
    bool velocity_law = false;

    /**
     * Makes the pairs of the couples the broad phase finds within reach at
     * the current state that are not made yet (resting if `mid_step`: the
     * step's detection is over) and lets every couple's pairs rest or not
     * as it finds.
     */
    void
    follow_broad_phase(const bool mid_step);

    /** Makes the pairs of the couple (i, j), i < j: i on j, and j on i with
     *  two passes. */
    void
    make_couple_pairs(const std::array<unsigned int, 2> &couple,
                      const bool                         resting);

    /** Scene/Contact bodies and its settings (no side if none). */
    const AutomaticContact automatic;
    /** Which couples are within reach (nullptr without automatic contact). */
    std::unique_ptr<BroadPhase> broad_phase;
    /** Each side's listed boundary's dofs (contact_dofs()). */
    std::vector<std::vector<dealii::types::global_dof_index>> side_dofs;
    /** Per pair: its slave and master sides, or none for a pair written
     *  or made at the start (a body on itself); and whether it rests. */
    std::vector<std::array<unsigned int, 2>> sides_of_pair;
    std::vector<bool>                        resting;
    /** The couples whose pairs are made, sorted. */
    std::vector<std::array<unsigned int, 2>> made_couples;
    double                                   reported_force_scale = 1.;
    /** The increment being solved (for pairs made within it). */
    double step_start = 0., step_end = 0.;

    const std::vector<std::unique_ptr<Body>> &bodies;
    dealii::TimerOutput                      &timer;
    std::vector<std::unique_ptr<ContactPair>> pairs;
    BiPotentialSolver::Settings               solver_settings;
    std::vector<std::vector<ContactNode>>     stored_nodes;
    /** The springs of bodies held by contact, as rank-one terms (active_nodes).
     */
    std::vector<DofVector> spring_loads, spring_rows;
    /**
     * A pair's tangent terms whose load is one dof, summed over its nodes
     * into one term per dof (active_nodes): the unit loads and the summed
     * rows. A deque, so that the terms' pointers stay put.
     */
    std::deque<DofVector> merged_loads, merged_rows;

    /** The bodies of the contact pairs. */
    std::vector<unsigned int> bodies_in_contact;
    /** The step (Contact solver/Method: condensed or sparse). */
    std::unique_ptr<ContactStep> step;
  };
} // namespace glissade
