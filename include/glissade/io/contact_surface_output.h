#pragma once

#include <glissade/contact/contact_pair.h>

#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The contact state of a pair on its slave boundary, each slave node
   * once (doc/user_guide.md, section 6.3): a table
   * `contact-<pair>-NNNNN.csv` and the same fields on the slave boundary
   * as a line mesh in the current configuration, `contact-<pair>-NNNNN.vtu`,
   * gathered in time by `contact-<pair>.pvd`.
   *
   * The pressure is the normal reaction over the node's tributary area:
   * half the current length of its slave faces times the body's
   * thickness; so the pressure integrated along the boundary (the
   * trapezoidal rule on the line mesh, times the thickness) is the total
   * normal force.
   */
  class ContactSurfaceOutput
  {
  public:
    /** The pair's slave faces, found once. */
    explicit ContactSurfaceOutput(const ContactPair &pair);

    /**
     * Writes the table and the VTU of increment `increment` (time t) into
     * `directory`, adds it to `records` (time, VTU file) and rewrites the
     * PVD file from them.
     */
    void
    write(const std::string                           &directory,
          const unsigned int                           increment,
          const double                                 t,
          std::vector<std::pair<double, std::string>> &records) const;

    /** What a node's status is called in the tables and coded in the VTU
     *  (inactive 0, open 1, stick 2, slip 3). */
    static std::pair<const char *, int>
    status_of(const ContactNode &node);

  private:
    const ContactPair &pair;
    /** The slave faces as pairs of indices into pair.nodes(). */
    const std::vector<std::array<unsigned int, 2>> &faces;
  };
} // namespace glissade
