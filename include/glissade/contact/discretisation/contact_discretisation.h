#pragma once

#include <deal.II/base/types.h>

#include <glissade/contact/discretisation/contact_node.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace glissade
{
  class Body;
  class MasterSurface;
  struct ContactDescription;

  /**
   * How a contact pair turns the geometry of its two sides into one
   * constraint per slave node (Contact <pair>/Discretisation): the node's
   * gap and slip, their rows in the dofs, the forces of its reaction and
   * its share of the contact tangent (ContactLinearization). Whatever the
   * discretisation, a slave node keeps one (tangential, normal) reaction
   * and the contact steps (condensed, sparse) and the local solvers see
   * the same ActiveNodes.
   *
   * - node-to-segment (node_to_segment.cc): the node against its closest
   *   point on the master surface (the paper's method).
   * - mortar (mortar.cc): the node's dual shape function's integral of the
   *   gap over the slave segments, segment-based (doc/contact.md,
   *   "Mortar"); on a NURBS slave (nurbs_slave_mortar.cc) the control
   *   point's rational function's integral over the slave's own curve.
   *
   * A new discretisation is a class here and a line in the table of
   * contact_discretisation.cc.
   */
  class ContactDiscretisation
  {
  public:
    /** What a discretisation is built from. */
    struct Context
    {
      const ContactDescription       &description;
      const Body                     &slave;
      const Body                     *master; // nullptr: a rigid obstacle
      const MasterSurface            &surface;
      const std::vector<ContactNode> &nodes;
      /** The boundaries the slave nodes come from. */
      const std::set<dealii::types::boundary_id> &slave_boundary_ids;
    };

    virtual ~ContactDiscretisation() = default;

    /**
     * After the master surface was rebuilt at the current state: what every
     * node shares (mortar: the segment integrals). Nothing by default.
     */
    virtual void
    update()
    {}

    /**
     * Projects a slave node at the current state and linearises it at its
     * reaction; false if it has no counterpart. With `keep_segment`, a
     * node-to-segment node keeps the master segment of its last projection
     * while it still has an orthogonal projection there.
     */
    virtual bool
    project(ContactNode &node, bool keep_segment) const = 0;

    /** The discretisation named `name` (one of names()). */
    static std::unique_ptr<ContactDiscretisation>
    create(const std::string &name, const Context &context);

    /** The names, as a Patterns::Selection string ("a|b"). */
    static std::string
    names_as_pattern();

    /** One sentence per discretisation, for the entry's documentation. */
    static std::string
    documentation();
  };
} // namespace glissade
