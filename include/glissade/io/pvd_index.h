#pragma once

#include <string>
#include <utility>
#include <vector>

namespace glissade
{
  /**
   * Writes (atomically) the PVD file `file` that lists the VTU files of a
   * time series: `records` holds (time, VTU file name relative to the PVD).
   * Written here rather than by DataOutBase::write_pvd_record, which stamps
   * the date into the file: the same scene must give the same bytes
   * (ctest -R determinism).
   */
  void
  write_pvd_index(const std::string                                 &file,
                  const std::vector<std::pair<double, std::string>> &records);
} // namespace glissade
