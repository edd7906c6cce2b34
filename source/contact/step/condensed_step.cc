#include <deal.II/base/timer.h>

#include <glissade/base/debug_log.h>
#include <glissade/base/timing_sections.h>
#include <glissade/body/body.h>
#include <glissade/contact/step/condensed_step.h>
#include <glissade/contact/step/contact_problem.h>

#include <algorithm>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using NodeStatus = BiPotentialSolver::NodeStatus;

    // The directions that the contact law holds at a node of this status:
    // the tangent if it sticks (with friction), the normal if it is closed.
    std::array<bool, 2>
    held_directions(const NodeStatus status, const double mu)
    {
      return {
        {status == NodeStatus::stick && mu > 0., status != NodeStatus::open}};
    }

    // The augmentation is exact only while its directions hold: an augmented
    // normal must end closed, an augmented tangent sticking. Those that do
    // not are released (from the augmentation and from `held`), and the
    // result is false, so that the problem is solved again without them.
    bool
    augmentation_consistent(const std::vector<NodeStatus>    &status,
                            Augmentation                     &augmentation,
                            std::vector<std::array<bool, 2>> &held)
    {
      bool consistent = true;
      for (unsigned int k = 0; k < augmentation.directions.size(); ++k)
        {
          auto &d = augmentation.directions[k];
          if (d[1] && status[k] == NodeStatus::open)
            d = held[k] = {{false, false}}, consistent = false;
          if (d[0] && status[k] != NodeStatus::stick)
            d[0] = held[k][0] = false, consistent = false;
        }
      return consistent;
    }

    // Escalation when a solve fails: the held directions, then every
    // direction of every node, then with a ten and a hundred times stiffer
    // augmentation. False once all of that has been tried.
    bool
    escalate_augmentation(unsigned int                           &stage,
                          Augmentation                           &augmentation,
                          const std::vector<std::array<bool, 2>> &held,
                          const std::vector<double>              &friction)
    {
      ++stage;
      if (stage == 1 && augmentation.directions != held)
        augmentation.directions = held;
      else if (stage <= 2)
        {
          stage = 2;
          for (unsigned int k = 0; k < friction.size(); ++k)
            augmentation.directions[k] = {{friction[k] > 0., true}};
        }
      else if (stage <= 4)
        augmentation.factor *= 10.;
      else
        return false;
      return true;
    }
  } // namespace



  CondensedStep::CondensedStep(const ContactStepContext &context)
    : bodies(context.bodies)
    , bodies_in_contact(context.bodies_in_contact)
    , settings(context.local_solver)
    , timer(context.timer)
    , eliminated_last(context.bodies.size())
  {}



  void
  CondensedStep::begin_step(ContactProblem &problem)
  {
    eliminate_touching_dofs_last(problem);
  }



  void
  CondensedStep::eliminate_touching_dofs_last(ContactProblem &problem)
  {
    // The dofs of the active nodes' rows and forces, per body: the ones
    // this increment's W needs. A declared contact area much larger than
    // what touches (Hertz: the whole arc, 1,256 dofs, for some 60 in
    // contact) otherwise puts a dense trailing block of its size into
    // every factorisation. A dof that joins later (a node activated or
    // sliding onto another segment within the increment) is still
    // answered, by back-substitutions.
    std::vector<std::vector<types::global_dof_index>> touching(bodies.size());
    for (const auto &pair : problem.contact_pairs())
      {
        const std::array<unsigned int, 2> b = {
          {problem.body_index(&pair->slave()),
           pair->master() ? problem.body_index(pair->master()) :
                            numbers::invalid_unsigned_int}};
        for (const auto &node : pair->nodes())
          if (node.active)
            {
              const ContactLinearization    &l       = node.linearization;
              std::vector<const DofVector *> vectors = {&l.gap_row,
                                                        &l.slip_row,
                                                        &l.tangential_force,
                                                        &l.normal_force};
              for (const auto &term : l.tangent_terms)
                {
                  vectors.push_back(&term.load);
                  vectors.push_back(&term.row);
                }
              for (const DofVector *v : vectors)
                for (const auto &e : *v)
                  if (b[e.body] != numbers::invalid_unsigned_int)
                    touching[b[e.body]].push_back(e.dof);
            }
      }
    for (const unsigned int b : bodies_in_contact)
      {
        // (a body held by contact keeps its declared area: its springs
        // are chosen among those dofs)
        if (touching[b].empty() ||
            !bodies[b]->system().free_rigid_motions().empty())
          continue;
        std::sort(touching[b].begin(), touching[b].end());
        touching[b].erase(std::unique(touching[b].begin(), touching[b].end()),
                          touching[b].end());
        if (touching[b] != eliminated_last[b])
          {
            eliminated_last[b] = touching[b];
            bodies[b]->system().set_contact_dofs(touching[b]);
          }
      }
  }



  bool
  CondensedStep::correct(ContactProblem              &problem,
                         std::vector<Vector<double>> &increments)
  {
    // Nodes that the free step would take behind the master join now,
    // linearised at the current state like the others (update_state());
    // under a velocity law the integrator chose the step's nodes.
    if (problem.position_law() &&
        problem.activate_nodes_crossed_by(increments) > 0)
      {
        TimerOutput::Scope scope(timer, timing::detection);
        for (auto &pair : problem.contact_pairs())
          pair->update_geometry();
      }

    // The active nodes of all pairs form one condensed problem: nodes of
    // different pairs couple through the bodies they share.
    std::vector<ContactNode *> active;
    const ActiveNodes          nodes = problem.active_nodes(active);
    result                           = BiPotentialSolver::Result();
    result.converged                 = true;
    if (active.empty())
      {
        // (with no node in contact, only a body that relies on contact
        // has a problem: nothing holds it)
        if (problem.held_by_contact_message().empty())
          return true;
        result.converged = false;
        result.message   = problem.held_by_contact_message() +
                         ": no slave node is in contact (all farther than "
                         "the alert distance)";
        return false;
      }

    // The reactions, and the condensed problem whose step they go with.
    std::vector<BiPotentialSolver::Vector2> r(active.size());
    for (unsigned int k = 0; k < active.size(); ++k)
      r[k] = {{active[k]->reaction[0], active[k]->reaction[1]}};
    const std::unique_ptr<CondensedProblem> condensed =
      solve_local_problem(problem, active, nodes, increments, r);
    if (!condensed)
      return false;
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        active[k]->reaction = {{r[k][0], r[k][1]}};
        active[k]->status   = result.status[k];
      }
    if (debug_log::at(2))
      for (const ContactNode *node : active)
        debug_log::stream()
          << "      node " << node->vertex << " segment " << node->segment
          << " s " << node->s << " gap " << node->gap << " r "
          << node->reaction[0] << ' ' << node->reaction[1] << std::endl;

    // Corrector: the Newton step.
    std::vector<Vector<double>> contact_forces(bodies.size());
    condensed->correct(r, increments, contact_forces);
    return true;
  }



  std::unique_ptr<CondensedProblem>
  CondensedStep::solve_local_problem(
    ContactProblem                          &problem,
    const std::vector<ContactNode *>        &active,
    const ActiveNodes                       &nodes,
    const std::vector<Vector<double>>       &predictor,
    std::vector<BiPotentialSolver::Vector2> &r)
  {
    // The directions the contact law holds at the start: closed normals,
    // sticking tangents. Where the Newton matrix alone is indefinite or
    // singular (a body past a limit point or held by contact only), the
    // local problem is augmented on them (theory.md, section 4.5): exact
    // as long as they stay closed and sticking, which is checked. A node
    // starts with the augmentation of its last solve.
    const unsigned int                            n     = active.size();
    const std::vector<BiPotentialSolver::Vector2> start = r;
    std::vector<std::array<bool, 2>>              held(n);
    Augmentation                                  augmentation;
    augmentation.directions.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        held[k] =
          held_directions(BiPotentialSolver::classify(start[k],
                                                      nodes.friction[k]),
                          nodes.friction[k]);
        // (a node at its cap yields: its normal is not held)
        if (start[k][1] >= nodes.normal_cap[k] * (1. - 1e-12))
          held[k] = {{false, false}};
        for (unsigned int c = 0; c < 2; ++c)
          augmentation.directions[k][c] = held[k][c] && active[k]->augmented[c];
      }

    // Solved, with a consistent augmentation, or escalated until it is.
    unsigned int                      stage = 0;
    std::unique_ptr<CondensedProblem> condensed;
    while (true)
      {
        {
          TimerOutput::Scope scope(timer, timing::compliance);
          condensed = std::make_unique<CondensedProblem>(nodes,
                                                         augmentation,
                                                         bodies,
                                                         predictor);
        }
        const bool solved =
          solve_contact_law(*condensed, nodes, start, held, augmentation, r);
        const bool consistent =
          solved && augmentation_consistent(result.status, augmentation, held);
        if (debug_log::at(1))
          debug_log::stream()
            << "    contact solve: " << augmentation.count()
            << " augmented directions (factor " << augmentation.factor << "), "
            << (result.polished ? "active set" : "Gauss-Seidel") << ": "
            << (solved ? (consistent ? "solved" : "inconsistent") :
                         "failed: " + result.message)
            << std::endl;
        if (consistent)
          break;
        if (solved)
          continue;
        if (!escalate_augmentation(stage, augmentation, held, nodes.friction))
          {
            explain_failure(problem, active, *condensed);
            return nullptr;
          }
      }

    for (unsigned int k = 0; k < n; ++k)
      active[k]->augmented = augmentation.directions[k];
    return condensed;
  }



  bool
  CondensedStep::solve_contact_law(
    const CondensedProblem                        &condensed,
    const ActiveNodes                             &nodes,
    const std::vector<BiPotentialSolver::Vector2> &start,
    const std::vector<std::array<bool, 2>>        &held,
    const Augmentation                            &augmentation,
    std::vector<BiPotentialSolver::Vector2>       &r)
  {
    result = BiPotentialSolver::Result();
    if (!condensed.regular())
      {
        result.message = "the Newton matrix with the contact terms is "
                         "singular on the contact dofs";
        return false;
      }
    // The bi-potential iteration (Gauss-Seidel), the paper's law solver.
    // Where W is not positive on the directions in play (the tangent alone
    // is indefinite), the law can have other solutions than the Newton
    // step's; if Gauss-Seidel changed the statuses there, or failed, the
    // active-set iteration from the held statuses finds the one that
    // continues them.
    TimerOutput::Scope      scope(timer, timing::local_solve);
    const BiPotentialSolver solver(settings);
    r      = start;
    result = solver.solve(condensed.compliance(),
                          condensed.free_displacement(),
                          nodes.friction,
                          r,
                          nodes.normal_cap);
    // (the active-set iteration knows no cap: not with a node at its cap)
    bool capped = false;
    for (unsigned int k = 0; k < r.size(); ++k)
      capped = capped || r[k][1] >= nodes.normal_cap[k] * (1. - 1e-12);
    bool check_branch = !result.converged && !capped;
    if (result.converged)
      {
        std::vector<std::array<bool, 2>> in_play = held;
        bool                             changed = false;
        for (unsigned int k = 0; k < held.size(); ++k)
          {
            const std::array<bool, 2> now =
              held_directions(result.status[k], nodes.friction[k]);
            changed = changed || now != held[k];
            for (unsigned int c = 0; c < 2; ++c)
              in_play[k][c] = in_play[k][c] || now[c];
          }
        check_branch = changed && augmentation.count() == 0 && !capped &&
                       !condensed.positive_definite_on(in_play);
      }
    if (!check_branch)
      return result.converged;

    std::vector<BiPotentialSolver::Vector2> continued = start;
    const BiPotentialSolver::Result         continuation =
      solver.solve_by_active_set(condensed.compliance(),
                                 condensed.free_displacement(),
                                 nodes.friction,
                                 continued);
    if (!continuation.converged)
      return result.converged;
    r      = continued;
    result = continuation;
    return true;
  }



  void
  CondensedStep::explain_failure(ContactProblem                   &problem,
                                 const std::vector<ContactNode *> &active,
                                 const CondensedProblem           &condensed)
  {
    if (!problem.held_by_contact_message().empty() && !condensed.regular())
      result.message = problem.held_by_contact_message() +
                       ": its contact nodes are open or slipping where they "
                       "would have to hold it";
    else if (condensed.regular())
      {
        const std::string where = not_positive_at(problem, active, condensed);
        if (!where.empty())
          result.message = where;
      }
  }



  std::string
  CondensedStep::not_positive_at(ContactProblem                   &problem,
                                 const std::vector<ContactNode *> &active,
                                 const CondensedProblem &condensed) const
  {
    // The first node whose own compliance is negative: pushing it gives
    // way, so the bodies are unstable there with the rest held.
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        const auto         w = condensed.compliance().diagonal_block(k);
        const unsigned int c = w[1][1] <= 0. ? 1 : w[0][0] < 0. ? 0 : 2;
        if (c == 2)
          continue;
        for (const auto &pair : problem.contact_pairs())
          for (const auto &node : pair->nodes())
            if (&node == active[k])
              {
                std::ostringstream message;
                message << "the bodies in contact are unstable at slave node ("
                        << node.reference_position[0] << ", "
                        << node.reference_position[1] << ") of pair '"
                        << pair->name() << "' (body '" << pair->slave().name()
                        << "'"
                        << (pair->master() ?
                              " on body '" + pair->master()->name() + "'" :
                              std::string(" on the obstacle"))
                        << "): its " << (c == 1 ? "normal" : "tangential")
                        << " compliance in the Newton matrix is " << w[c][c]
                        << " <= 0, so the tangent is not positive there even "
                           "with the contact's closed directions held. The "
                           "bodies are past a limit point of their own "
                           "(buckling, a sidesway, a folding corner), or the "
                           "increment is too large for the change of contact "
                           "status. Try more increments (Load program/Stage "
                           "increments), a support or friction that holds "
                           "the motion, or a finer mesh there";
                return message.str();
              }
      }
    return "";
  }
} // namespace glissade
