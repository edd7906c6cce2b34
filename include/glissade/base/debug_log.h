#pragma once

#include <ostream>

namespace glissade
{
  /**
   * The diagnostics `GLISSADE_DEBUG` asks for, on standard error (user
   * guide, section 7): level 1 (any value) prints each Newton iteration's
   * norms and the contact solve, 2 adds a line per active contact node, 3
   * each change of a node's status in the active-set passes. The variable
   * is read once.
   */
  namespace debug_log
  {
    /** 0 when GLISSADE_DEBUG is not set; 2 or 3 when it says so; else 1. */
    unsigned int
    level();

    /** True if the diagnostics of `wanted` are asked for. */
    inline bool
    at(const unsigned int wanted)
    {
      return level() >= wanted;
    }

    /** Where the diagnostics go. */
    std::ostream &
    stream();
  } // namespace debug_log
} // namespace glissade
