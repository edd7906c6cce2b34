#pragma once

#include <glissade/base/progress_text.h>

#include <chrono>
#include <iostream>
#include <string>

namespace glissade
{
  /**
   * One line per run of a study, before the run starts: "[3/8] case1_beam_ring,
   * hermite (elapsed 1 min 05 s, about 2 min 10 s left)". The estimate is
   * the mean time of the runs done so far, so it is rough where runs differ
   * in cost (the sweeps of the trade study).
   */
  class StudyProgress
  {
  public:
    explicit StudyProgress(const unsigned int n_runs)
      : n_runs(n_runs)
      , start(std::chrono::steady_clock::now())
    {}

    /** Announces the next run; its line ends with `ending` (a newline, or
     *  nothing when the run's own result follows on the same line). */
    void
    next(const std::string &what, const std::string &ending = "\n")
    {
      const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      std::cout << "[" << done + 1 << "/" << n_runs << "] " << what << " ("
                << progress_text::time_left(elapsed, done, n_runs - done)
                << ") ..." << ending << std::flush;
      ++done;
    }

    /** A run that will not be made after all. */
    void
    skip()
    {
      if (n_runs > done)
        --n_runs;
    }

  private:
    unsigned int                                n_runs;
    unsigned int                                done = 0;
    const std::chrono::steady_clock::time_point start;
  };
} // namespace glissade
