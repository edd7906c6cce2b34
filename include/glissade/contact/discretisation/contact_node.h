#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <glissade/contact/discretisation/contact_linearization.h>
#include <glissade/contact/local_solvers/bipotential_solver.h>
#include <glissade/contact/surfaces/master_surface.h>

#include <array>
#include <limits>

namespace glissade
{
  /**
   * A slave point and its contact state: a node of the slave boundary (a
   * mesh vertex), or a point of a NURBS body's boundary between its
   * control points (ContactPair: the boundary's Greville points).
   */
  struct ContactNode
  {
    /** The mesh vertex of a node; no_vertex for a point between nodes. */
    static constexpr unsigned int no_vertex = static_cast<unsigned int>(-1);
    unsigned int                  vertex    = no_vertex;
    /**
     * What the point's displacement is made of, sum_k weight_k u(dofs_k):
     * the vertex's dofs with weight 1 for a node, the boundary's control
     * points with their rational functions for a NURBS point.
     */
    SlaveShares      shares;
    dealii::Point<2> reference_position;
    /** The slave boundary's outward normal at the point, in the reference
     *  configuration (the vertex normal of a node). */
    dealii::Tensor<1, 2> reference_outward_normal;
    /**
     * A NURBS boundary's point: its share of the boundary's reference
     * area, the weights w with sum_g R_A(x_g) w_g = int R_A dA for every
     * control point A, so that a pressure p at the points, p w_g, makes the
     * consistent loads of p (ContactPair::tributary_areas); with mortar,
     * int R_A dA of its control point A, which its lambda_A acts on
     * (SlavePointArea). Zero for a node, whose faces give its share.
     */
    double collocation_area = 0.;

    /** The point's displacement in the slave body's dofs u. */
    template <class VectorType>
    dealii::Tensor<1, 2>
    displacement(const VectorType &u) const
    {
      dealii::Tensor<1, 2> result;
      for (const SlaveShare &share : shares)
        for (unsigned int c = 0; c < 2; ++c)
          result[c] += share.weight * u(share.dofs[c]);
      return result;
    }

    bool active    = false;
    bool projected = false; // has a counterpart on the master
    /** Master segment and s of the last projection (-1: none or rigid). */
    int                  segment = -1;
    double               s       = 0.;
    double               gap     = 0.;
    dealii::Tensor<1, 2> tangent, normal;
    /** Reaction on the slave node in the (t, n) frame: r_n >= 0 pushes. */
    std::array<double, 2>         reaction = {{0., 0.}};
    BiPotentialSolver::NodeStatus status = BiPotentialSolver::NodeStatus::open;
    /**
     * Segment changes within the current increment. From the second on,
     * the node keeps its segment (along its extension) for the rest of the
     * increment: on a C1 curve whose curvature jumps at a node, a slave
     * node whose equilibrium sits at that node would otherwise switch
     * sides at every Newton iteration, each side's tangent pointing to the
     * other. The point, the normal and the gap agree on both sides, so
     * this changes how Newton gets there, not where.
     */
    unsigned int segment_switches = 0;
    /** The last projection met a vertex with its cone (a faceted master). */
    bool at_vertex = false;
    /**
     * The directions (tangential, normal) of this node that the last local
     * solve augmented (ContactProblem): the next starts from them.
     */
    std::array<bool, 2> augmented = {{false, false}};
    /**
     * What the local problem adds to this node's (slip, gap) in the current
     * step: zero for the position-level law; a velocity-level law (Moreau-
     * Jean) shifts them so that the law holds on the end velocity
     * (TimeIntegrator).
     */
    std::array<double, 2> law_shift = {{0., 0.}};
    /**
     * Under a dynamic scheme, the gap at the step's start to the master as
     * it stood then (TimeIntegrator); NaN for a node without a
     * counterpart then.
     */
    double start_gap = 0.;
    /**
     * The same gap at the step's start with a rigid obstacle where it stands
     * at the step's end: the part of the gap's change that the dofs' motion
     * over the step makes (equal to start_gap against a deformable master).
     * The forces of the node's normal reaction are a discrete gradient of
     * the gap over that change (discrete_gradient.h).
     */
    double start_gap_in_dofs = std::numeric_limits<double>::quiet_NaN();
    /** Under a dynamic scheme, the gap's gradient at the step's start (its
     *  row there: mortar's normal force is not it); empty without one. */
    DofVector start_normal_force;

    /**
     * Gap, slip, their derivatives, the forces of the reaction and the
     * contact tangent at the last projection (rebuilt by every one).
     */
    ContactLinearization linearization;

    /**
     * Self-contact only (`facing`): what the projection needs to find the
     * part of the body's surface that faces the node (FacingView), set by
     * the pair from the current state before each projection.
     */
    bool       facing = false;
    FacingView facing_view;

    /**
     * The state a checkpoint holds (Boost serialization): the reactions and
     * statuses warm-start the local solver of the next increment, so a
     * restart needs them to continue bit for bit; the linearisation is
     * rebuilt by the next detection.
     */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      int status_code = static_cast<int>(status);
      archive &active &projected &segment &s &gap &tangent &normal
          &reaction[0] &
        reaction[1] & status_code;
      status = static_cast<BiPotentialSolver::NodeStatus>(status_code);
    }

    /**
     * What the forces of a unit reaction sum to on the slave, along the
     * node's frame: 1, but for mortar on a NURBS slave, whose forces follow
     * the curve's normal across the point's function, |int psi_A n| / int
     * R_A (set by its projection).
     */
    double resultant_factor = 1.;

    /** The resultant of the node's forces on the slave. */
    dealii::Tensor<1, 2>
    force() const
    {
      return resultant_factor * (reaction[0] * tangent + reaction[1] * normal);
    }
  };
} // namespace glissade
