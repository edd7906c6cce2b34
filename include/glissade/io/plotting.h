#pragma once

#include <string>
#include <vector>

namespace glissade
{
  /**
   * Draws a run's or a study's PNGs from its CSVs with scripts/<script>
   * (matplotlib, run by Debian's /usr/bin/python3). The scripts are those
   * the build copies beside the program, or those in $GLISSADE_SCRIPTS.
   * Pictures are a convenience: if Python, matplotlib or the script is
   * missing the run still succeeds and says so. `arguments` follow the
   * directory on the script's command line.
   */
  void
  plot_with_python(const std::string              &script,
                   const std::string              &directory,
                   const std::vector<std::string> &arguments = {});
} // namespace glissade
