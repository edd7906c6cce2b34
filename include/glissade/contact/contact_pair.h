#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <glissade/body/body.h>
#include <glissade/contact/discretisation/contact_node.h>
#include <glissade/contact/surfaces/master_surface.h>
#include <glissade/description/scene_description.h>

#include <map>
#include <memory>
#include <set>
#include <vector>

namespace glissade
{
  class ContactDiscretisation;

  /**
   * A contact pair: the nodes of a slave boundary against a master surface
   * (a MasterSurface: another body's boundary seen through a smoothing, or
   * a rigid obstacle), node-to-segment or mortar (ContactDiscretisation).
   *
   * At the start of each increment begin_step() builds the master surface
   * from the current positions and keeps, as the active set, the slave
   * nodes within the alert distance (paper, section 2.3): the others are
   * not part of the condensed problem of that increment. In every Newton
   * iteration update_geometry() rebuilds the surface and re-projects the
   * active nodes: frame, gap, and their linearisation with the contact
   * tangent at the current reactions.
   */
  class ContactPair
  {
  public:
    /** `timer` receives the master surface build section. */
    ContactPair(const ContactDescription &description,
                Body                     &slave,
                Body                     *master,
                dealii::TimerOutput      &timer);

    ~ContactPair();

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

    /** Detection for the increment from step_start_time to time. */
    void
    begin_step(const double step_start_time, const double time);

    /**
     * Restricts the detection (begin_step(), activate_penetrating_nodes())
     * to the slave nodes inside `box`, where the others cannot be within
     * the alert distance of the master: they are left inactive and without
     * a counterpart, as rest() leaves every node. Automatic contact's
     * broad phase gives the master boundary's box grown by the alert
     * distance; a pair written by hand searches every node.
     */
    void
    search_only_within(const dealii::BoundingBox<2> &box)
    {
      search_box     = box;
      has_search_box = true;
    }

    /**
     * The increment from step_start_time to time without detection: the
     * bodies are out of each other's reach (ContactProblem's broad phase).
     * Every node is inactive and has no counterpart (no gap, no start gap);
     * the master surface is not rebuilt.
     */
    void
    rest(const double step_start_time, const double time);

    /**
     * A pair that cannot make sense: at t = 0, slave nodes lie deeper behind
     * the master surface than 5 % of the bodies' size (the bodies overlap,
     * the master boundary faces away from the slave, or the obstacle is on
     * the wrong side). Throws an InputError naming the entry; the state is
     * left as before.
     */
    void
    check_initial_state();

    /**
     * What check_initial_state() found behind the master that it let
     * through, deeper than the alert distance: "" if none, else what to
     * tell the user (an interference fit's overlap is its load, which the
     * first increment pushes out; bodies placed into each other by mistake
     * look the same).
     */
    const std::string &
    initial_overlap() const
    {
      return overlap_at_start;
    }

    /**
     * A slave node within the alert distance at t = 0, and the frame of the
     * slave boundary there (n pointing into the slave, as the master's).
     */
    struct InitialContact
    {
      dealii::Point<2>     position;
      dealii::Tensor<1, 2> normal, tangent;
    };

    /**
     * The slave nodes that check_initial_state() found within the alert
     * distance: the contacts that can hold a body from the start.
     */
    const std::vector<InitialContact> &
    initial_contacts() const
    {
      return contacts_at_start;
    }

    /** Rebuilds the surface and re-projects and linearises the active nodes. */
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

    /** The boundary ids of the slave boundary (Slave boundary lists names). */
    const std::set<dealii::types::boundary_id> &
    slave_boundary_ids() const
    {
      return slave_ids;
    }

    /** nullptr for a rigid obstacle. */
    Body *
    master()
    {
      return master_body;
    }

    const MasterSurface &
    surface() const
    {
      return *master_surface;
    }

    unsigned int
    n_active() const;

    /**
     * Every dof of `body` that this pair's dof maps can ever touch: the
     * slave nodes' dofs, or the master surface's (with the Hermite
     * derivatives). The bodies eliminate these last in their factorisation.
     */
    std::vector<dealii::types::global_dof_index>
    contact_dofs(const Body &body) const;

    /**
     * What the outputs report of a node's reaction and force: the local
     * problem's own (the contact force of the step's equation), times a
     * scale that a time integrator sets when its unknown is not the
     * physical force (Moreau-Jean's is the impulse over theta dt: the mean
     * force of the step is theta times it).
     */
    void
    report_forces_scaled_by(const double scale)
    {
      reported_force_scale = scale;
    }
    std::array<double, 2>
    reported_reaction(const ContactNode &node) const
    {
      return {{reported_force_scale * node.reaction[0],
               reported_force_scale * node.reaction[1]}};
    }
    dealii::Tensor<1, 2>
    reported_force(const ContactNode &node) const
    {
      return reported_force_scale * node.force();
    }

    /** Sum of the forces on the slave nodes (global frame), as reported. */
    dealii::Tensor<1, 2>
    total_force() const;

    /** The slave node at a reference position (for history output). */
    const ContactNode &
    node_at(const dealii::Point<2> &reference_position) const;

    /**
     * The contact forces on the dofs at fixed reactions, F = sum_k
     * H_k(U)^T Q_k(U) r_k, at the current state (the active nodes as
     * projected last): body 0 the slave, 1 the master. For checking the
     * contact tangent against finite differences.
     */
    std::array<dealii::Vector<double>, 2>
    contact_forces() const;

    /** The slave faces, as pairs of indices into nodes(). */
    const std::vector<std::array<unsigned int, 2>> &
    slave_faces() const
    {
      return faces;
    }

    /**
     * Each slave node's tributary area in the current configuration: the
     * integral of its hat function over its adjacent faces, so that the
     * nodal forces of a uniform pressure divided by it give the pressure
     * back (thickness times half of each face; for a body of revolution
     * the rings 2 pi L (2 x_k + x_other) / 6 of each face, forces being
     * for the full turn). A NURBS boundary's point: its collocation area
     * in the reference configuration (ContactNode::collocation_area).
     */
    std::vector<double>
    tributary_areas() const;

    /**
     * After a converged increment: how far the master's open ends
     * (MasterSurface::open_ends, a rigid obstacle's) stand inside the
     * slave's faces, the deepest of the run kept with its time and the
     * face's length. Nothing for a NURBS slave, whose points are not a
     * polygon on its boundary.
     */
    void
    measure_corners(double time);

    /** What measure_corners() found, as a sentence; empty where the master
     *  has no open end. */
    std::string
    corner_report() const;

    /** The deepest that measure_corners() found (-1: nothing measured). */
    double
    deepest_corner_inside() const
    {
      return deepest_corner;
    }

    /**
     * The cap on each slave node's normal reaction in the local problem:
     * its tributary area times an abradable coating's yield pressure (over
     * the reported scale); infinity without a coating.
     */
    std::vector<double>
    normal_force_caps() const;

    /**
     * After a converged step: the coating worn along the paths of the
     * nodes that pressed on it at its yield pressure.
     */
    void
    wear_coating();

    /** The master surface's abradable coating, or nullptr. */
    const AbradableCoating *
    coating() const
    {
      return master_surface->coating();
    }
    AbradableCoating *
    coating()
    {
      return master_surface->coating();
    }

    /** The coating's removed area (zero without one). */
    double
    removed_area() const
    {
      return master_surface->removed_area();
    }

  private:
    /** See initial_overlap(). */
    std::string overlap_at_start;

    double reported_force_scale = 1.;
    /** The slave faces, as indices into the nodes. */
    std::vector<std::array<unsigned int, 2>> faces;

    /**
     * Projects one slave node at the current state and linearises it;
     * false if it has no counterpart. With `keep_segment`, the node keeps
     * the master segment of its last projection while it still has an
     * orthogonal projection there (MasterSurface::project).
     */
    bool
    project(ContactNode &node, const bool keep_segment = false) const;

    /** The surface at the current state (and the increment's end time);
     *  for self-contact, each node's FacingView too. */
    void
    update_surface();

    /** Self-contact: each node's outward normal at the current state, in
     *  its FacingView. */
    void
    update_facing_views();

    /**
     * Refuses a rigid obstacle whose normal points, at every slave node,
     * the same way as the slave boundary's outward normal: contact could
     * never close.
     */
    void
    check_obstacle_faces_slave();

    /** False for a node that no reaction can move (see the definition). */
    bool
    can_react(const ContactNode &node) const;

    const ContactDescription       description;
    Body                          &slave_body;
    Body                          *master_body;
    dealii::TimerOutput           &timer;
    std::unique_ptr<MasterSurface> master_surface;
    /** Node-to-segment or mortar (Discretisation). */
    std::unique_ptr<ContactDiscretisation> discretisation;
    std::vector<ContactNode>               slave_nodes;
    std::vector<InitialContact>            contacts_at_start;
    std::set<dealii::types::boundary_id>   slave_ids;
    /** The increment being solved: its start and end times. */
    double step_start = 0., step_end = 0.;
    /** The master is the slave's own body (self-contact). */
    bool self_contact = false;
    /** measure_corners(): the deepest so far (-1: not measured), when,
     *  and the face's length. */
    double deepest_corner = -1., deepest_corner_time = 0.,
           deepest_corner_face = 0.;
    /** search_only_within(). */
    dealii::BoundingBox<2> search_box;
    bool                   has_search_box = false;

    /** A slave node's position at the current state. */
    dealii::Point<2>
    position(const ContactNode &node) const;

    /** False for a node outside the search box (search_only_within()). */
    bool
    may_be_near_master(const ContactNode &node) const;

    /** Leaves a node inactive and without a counterpart (rest()). */
    static void
    rest_node(ContactNode &node);
  };
} // namespace glissade
