#pragma once

#include <string>

namespace glissade
{
  /**
   * Holds an output directory for one run: an advisory lock (flock) on
   * `<directory>/.glissade-lock` for as long as the object lives. A second
   * run pointed at the same directory while the first is going is refused,
   * rather than both writing their VTU, contact tables and history into one
   * folder. The lock is the kernel's: it goes with the process, so a run
   * killed by SIGKILL leaves nothing stale behind (the empty file stays).
   */
  class DirectoryLock
  {
  public:
    /**
     * Creates the directory if needed and takes the lock; throws an
     * InputError naming `entry` if another process holds it.
     */
    DirectoryLock(const std::string &directory, const std::string &entry);
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

  private:
    int descriptor = -1;
  };
} // namespace glissade
