#pragma once

#include <deal.II/base/types.h>

#include <glissade/contact/discretisation/contact_linearization.h>

#include <array>
#include <functional>

namespace glissade
{
  /**
   * What make_forces_discrete_gradients() needs of a node's dofs: how far
   * each moved over the step, and which rigid translations the two bodies
   * share (none against a rigid obstacle).
   */
  struct StepMotion
  {
    /** u - u_n on dof `dof` of body `body` (0: the slave, 1: the master). */
    std::function<double(unsigned int, dealii::types::global_dof_index)>
      increment;
    /**
     * The unit translations along x and y on that dof (1 on a value dof of
     * that component, 0 on a derivative dof). Empty against a rigid
     * obstacle: the reaction's other end is not in the dofs, and nothing
     * is to be conserved between the bodies.
     */
    std::function<std::array<double, 2>(unsigned int,
                                        dealii::types::global_dof_index)>
      translation;
    /** Slave and master are one body (self-contact): a dof is the same
     *  whichever side names it. */
    bool one_body = false;
    /** The size of the bodies: what round-off of the coordinates is
     *  relative to. */
    double length = 1.;
  };

  /**
   * Makes the forces of a contact node's unit reactions discrete gradients
   * of its gap and slip over the step (Gonzalez 1996; Hesch and Betsch 2009
   * for node-to-segment contact), so that
   *   normal force . du = g(u_n+1) - g(u_n) = `gap_change`,
   *   tangential force . du = the step's slip `slip` (skipped if NaN).
   * The reactions' work on the bodies is then exactly r_n dg + r_t slip,
   * which the contact laws make <= 0 in each step. With the forces of the
   * step's end alone (the gap's gradient there), a node that slides along
   * a curved master has its reaction do r_n/2 du.H.du more, of either sign
   * (H the gap's second derivative in the dofs): what let the contact
   * between two deformable bodies create energy.
   *
   * The normal force becomes the mean of the gap's gradients at the step's
   * start (`start_normal_force`, unless empty) and end, the trapezoidal
   * rule's, whose defect is third order in the step's motion on a smooth
   * curve; what remains of it (and at a faceted master's vertices, all of
   * it) goes along the step's motion w of the node's dofs with the bodies'
   * common translation taken out, which keeps the forces on the two bodies
   * equal and opposite. Nothing is added where the node did not move
   * relative to the master (w nil). The rows of the linearised gap and
   * slip become these forces too (W symmetric for the bi-potential
   * solver; Newton then converges at a rate of the order of |H du|).
   */
  void
  make_forces_discrete_gradients(ContactLinearization &linearization,
                                 const DofVector      &start_normal_force,
                                 double                gap_change,
                                 double                slip,
                                 const StepMotion     &motion);
} // namespace glissade
