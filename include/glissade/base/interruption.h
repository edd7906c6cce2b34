#pragma once

#include <stdexcept>
#include <string>

namespace glissade
{
  /**
   * SIGTERM and SIGINT, as batch schedulers and Ctrl-C send them. The
   * handler only records the signal; the run finishes the increment it is
   * solving, writes a checkpoint of that converged state and stops with
   * RunInterrupted. A second signal stops the process at once (the default
   * action is restored by the first).
   */
  namespace interruption
  {
    /** Installs the handler for SIGTERM and SIGINT. */
    void
    install_handlers();

    /** The signal received (0 if none). */
    int
    signal_received();

    /** "SIGTERM", "SIGINT" or the number. */
    std::string
    signal_name(int signal);
  } // namespace interruption

  /**
   * The run stopped on a signal after writing a checkpoint; the message
   * says after which increment and how to continue.
   */
  class RunInterrupted : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace glissade
