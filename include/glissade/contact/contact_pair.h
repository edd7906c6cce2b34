#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <glissade/body/body.h>
#include <glissade/contact/bipotential_solver.h>
#include <glissade/contact/master_curve.h>
#include <glissade/contact/rigid_obstacle.h>
#include <glissade/scene/scene_description.h>

#include <memory>
#include <vector>

namespace glissade
{
  /**
   * One term of a linear map from the bodies' dof increments to a 2D
   * displacement: component `component` receives weight * du[dof] of body
   * `body` (0: slave, 1: master).
   */
  struct DofWeight
  {
    unsigned int            body;
    types::global_dof_index dof;
    unsigned int            component;
    double                  weight;
  };

  /** A slave node and its contact state. */
  struct ContactNode
  {
    unsigned int                           vertex;
    std::array<types::global_dof_index, 2> dofs;
    Point<2>                               reference_position;

    bool         active = false;
    bool         projected = false; // has a counterpart on the master
    /** Master segment of the last projection (-1: none or rigid). */
    int          segment = -1;
    double       s       = 0.;
    double       gap_at_step_start = 0.;
    double       gap    = 0.;
    Tensor<1, 2> tangent, normal;
    /** Reaction on the slave node in the (t, n) frame: r_n >= 0 pushes. */
    std::array<double, 2>         reaction = {{0., 0.}};
    BiPotentialSolver::NodeStatus status   = BiPotentialSolver::NodeStatus::open;
    /**
     * The slave's displacement relative to the master point, as a map of
     * the dofs (kinematics: how the gap moves), and the map that hands the
     * reaction to the dofs (forces: the same, or the paper's two segment
     * nodes for a B-spline master).
     */
    std::vector<DofWeight> kinematics, forces;

    /**
     * The state a checkpoint holds (Boost serialization): the reactions and
     * statuses warm-start the local solver of the next increment, so a
     * restart needs them to continue bit for bit; the maps are rebuilt by
     * the next detection.
     */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      int status_code = static_cast<int>(status);
      archive &active &projected &segment &s &gap_at_step_start &gap &tangent
        &normal &reaction[0] &reaction[1] &status_code;
      status = static_cast<BiPotentialSolver::NodeStatus>(status_code);
    }

    Tensor<1, 2>
    force() const
    {
      return reaction[0] * tangent + reaction[1] * normal;
    }
  };

  /**
   * A contact pair: the nodes of a slave boundary against a master surface
   * (another body's boundary seen through a MasterCurve, or a rigid
   * obstacle), node-to-segment.
   *
   * At the start of each increment begin_step() builds the master surface
   * from the current positions and keeps, as the active set, the slave
   * nodes within the alert distance (paper, section 2.3): the others are
   * not part of the condensed problem of that increment. In every Newton
   * iteration update_geometry() rebuilds the surface and re-projects the
   * active nodes: frame, gap and the dof maps.
   */
  class ContactPair
  {
  public:
    /** `timer` receives the master surface build section. */
    ContactPair(const ContactDescription &description,
                Body                     &slave,
                Body                     *master,
                const std::string        &source,
                TimerOutput              &timer);

    const std::string &
    name() const
    {
      return description.name;
    }

    const ContactDescription &
    settings() const
    {
      return description;
    }

    void
    begin_step(const double time);

    /**
     * A pair that cannot make sense: at t = 0, slave nodes lie deeper behind
     * the master surface than 5 % of the bodies' size (the master boundary
     * faces away from the slave, or the obstacle is on the wrong side).
     * Throws an InputError naming the entry; the state is left as before.
     */
    void
    check_initial_state();

    void
    update_geometry();

    /**
     * Activates the inactive slave nodes that have gone behind the master
     * during the increment (they were farther than the alert distance at
     * its start); returns how many. Newton then goes on with them, so that
     * a small alert distance costs iterations, never a penetration.
     */
    unsigned int
    activate_penetrating_nodes();

    std::vector<ContactNode> &
    nodes()
    {
      return slave_nodes;
    }

    const std::vector<ContactNode> &
    nodes() const
    {
      return slave_nodes;
    }

    Body &
    slave()
    {
      return slave_body;
    }

    const Body &
    slave() const
    {
      return slave_body;
    }

    /** nullptr for a rigid obstacle. */
    Body *
    master()
    {
      return master_body;
    }

    unsigned int
    n_active() const;

    /**
     * Every dof of `body` that this pair's dof maps can ever touch: the
     * slave nodes' dofs, or the master curve's (with the Hermite
     * derivatives). The bodies eliminate these last in their factorisation.
     */
    std::vector<types::global_dof_index>
    contact_dofs(const Body &body) const;

    /** Sum of the forces on the slave nodes (global frame). */
    Tensor<1, 2>
    total_force() const;

    /** The slave node at a reference position (for history output). */
    const ContactNode &
    node_at(const Point<2> &reference_position) const;

  private:
    /** Ordered chain of the master boundary's vertices (master on the right). */
    void
    build_master_chain(const std::string &source);

    /** Rebuilds the master curve from the current displacement. */
    void
    update_master_curve();

    /**
     * Projects one slave node at the current state; false if no
     * counterpart. With `keep_segment`, a node keeps the master segment of
     * its last projection while it still has an orthogonal projection
     * there: near a vertex of a faceted master two segments are about as
     * close, and letting the choice flip between Newton iterations makes
     * the contact constraint itself jump, so Newton would stall.
     */
    bool
    project(ContactNode &node, const bool keep_segment = false) const;

    /**
     * Orthogonal projection on one segment; false if s leaves
     * [-margin, 1 + margin].
     */
    bool
    project_on_segment(const Point<2> &x, const unsigned int segment,
                       double &s, const double margin) const;

    /** False for a node that no reaction can move (see the definition). */
    bool
    can_react(const ContactNode &node) const;

    /** Frame, gap and dof maps of a node at (segment, s). */
    void
    linearize(ContactNode &node, const Point<2> &x, const unsigned int segment,
              const double s) const;

    Point<2>
    current_position(const Body &body, const std::array<types::global_dof_index, 2> &dofs,
                     const Point<2> &X) const;

    const ContactDescription       description;
    Body                          &slave_body;
    Body                          *master_body;
    TimerOutput                   &timer;
    std::unique_ptr<RigidObstacle> obstacle;
    std::unique_ptr<MasterCurve>   curve;
    std::vector<ContactNode>       slave_nodes;
    double                         time = 0.;

    // Master chain: node vertices, their reference positions and value
    // dofs; for Hermite masters also the derivative dofs (x/y, d/dx, d/dy
    // per component) and, per segment, the reference tangents dX/ds at its
    // two ends (s in [0, 1] along the segment).
    bool                                                closed = false;
    std::vector<Point<2>>                               master_points;
    std::vector<std::array<types::global_dof_index, 2>> master_dofs;
    std::vector<std::array<types::global_dof_index, 6>> master_hermite_dofs;
    std::vector<std::array<Tensor<1, 2>, 2>>            segment_reference_tangents;
  };
} // namespace glissade
