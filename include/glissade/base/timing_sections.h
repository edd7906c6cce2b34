#pragma once

#include <chrono>

namespace glissade
{
  /**
   * The sections of a run's deal.II TimerOutput: one name per part of the
   * work, shared by the classes that time it and the timing table that
   * reports it. Detection contains the master surface build; the table
   * shows the two apart.
   */
  namespace timing
  {
    inline constexpr const char *assembly = "assembly of residual and tangent";
    inline constexpr const char *factorization = "factorization";
    inline constexpr const char *predictor     = "predictor solve";
    inline constexpr const char *detection = "contact detection and projection";
    inline constexpr const char *surface   = "master surface build";
    inline constexpr const char *compliance  = "compliance matrix W";
    inline constexpr const char *local_solve = "local bi-potential solve";
    inline constexpr const char *output      = "output (VTU, PVD, CSV)";
    inline constexpr const char *checkpoints = "checkpoints";

    /** The seconds since `start` (the timers kept beside TimerOutput's). */
    inline double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }
  } // namespace timing
} // namespace glissade
