#pragma once

#include <glissade/contact/contact_pair.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * The contact state of one body as a slave, all its pairs together
   * (Output/Contact tables = per body): where automatic contact makes many
   * pairs, a table and a line mesh per body rather than per pair.
   * `contact-of-<body>-NNNNN.csv` holds each slave node of the body once,
   * with the sum of its forces over the pairs where it is active, its
   * smallest gap over the pairs that project it, and the pair that
   * carries most of its normal reaction; `contact-of-<body>-NNNNN.vtu` the
   * same fields on the slave boundaries in the current configuration,
   * gathered by `contact-of-<body>.pvd`.
   */
  class BodyContactOutput
  {
  public:
    explicit BodyContactOutput(const Body &body);

    /**
     * Writes the table and the VTU of increment `increment` (time t) from
     * the pairs among `pairs` whose slave is the body (nothing if there is
     * none), adds the VTU to `records` and rewrites the PVD file.
     */
    void
    write(const std::string                               &directory,
          const unsigned int                               increment,
          const double                                     t,
          const std::vector<std::unique_ptr<ContactPair>> &pairs,
          std::vector<std::pair<double, std::string>>     &records) const;

  private:
    const Body &body;
  };
} // namespace glissade
