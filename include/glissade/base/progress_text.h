#pragma once

#include <string>

namespace glissade
{
  namespace progress_text
  {
    /** "12 s", "3 min 05 s", "2 h 10 min": a duration for a person. */
    std::string
    duration(const double seconds);

    /**
     * "elapsed 12 s, about 40 s left": the steps still to do at the mean
     * pace of the `done` steps that took `elapsed` seconds.
     */
    std::string
    time_left(const double       elapsed,
              const unsigned int done,
              const unsigned int remaining);
  } // namespace progress_text
} // namespace glissade
