#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /**
   * Draws a study's PNGs from its CSVs with scripts/<script> (matplotlib, run
   * by Debian's /usr/bin/python3). Pictures are a convenience: if Python or
   * matplotlib is missing the run still succeeds and says so. `arguments`
   * follow the directory on the script's command line.
   */
  void
  plot_with_python(const std::string              &script,
                   const std::string              &directory,
                   const std::vector<std::string> &arguments = {});
} // namespace glissade
