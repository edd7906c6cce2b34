#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The contact fields on a slave boundary as a line mesh in the current
   * configuration, each node once: what ContactSurfaceOutput (a pair's)
   * and BodyContactOutput (a body's, all its pairs together) write.
   */
  struct ContactLineFields
  {
    std::vector<dealii::Point<2>>            x;
    std::vector<std::array<unsigned int, 2>> faces;
    std::vector<double> pressure, shear, r_n, r_t, gap, slip, status;
    std::vector<dealii::Tensor<1, 2>> force;
  };

  /** Writes `fields` as an ASCII VTU file (a boundary is small) at `path`
   *  atomically. */
  void
  write_contact_line_vtu(const std::string       &path,
                         const ContactLineFields &fields);
} // namespace glissade
