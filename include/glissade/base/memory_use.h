#pragma once

#include <cstddef>
#include <string>

namespace glissade
{
  /**
   * This process's memory as the operating system counts it: what it holds
   * now (resident set) and the most it has held (its high-water mark), in
   * bytes; zero where /proc/self/status cannot be read (not Linux).
   */
  struct MemoryUse
  {
    std::size_t resident = 0;
    std::size_t peak     = 0;
  };

  /** This process's memory now. */
  MemoryUse
  memory_use();

  /**
   * The line GLISSADE_DEBUG prints after a phase of a Newton iteration:
   * "memory after <phase> (process p): resident ... GB, peak ... GB", on
   * standard error, by every process (doc/parallel.md: the model of a
   * process's memory is checked against these).
   */
  void
  log_memory_use(const std::string &phase);
} // namespace glissade
