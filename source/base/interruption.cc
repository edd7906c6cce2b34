#include <glissade/base/interruption.h>

#include <csignal>

namespace glissade
{
  namespace interruption
  {
    namespace
    {
      volatile std::sig_atomic_t received = 0;

      extern "C" void
      record_signal(const int signal)
      {
        received = signal;
        // The next one is not asked politely.
        std::signal(signal, SIG_DFL);
      }
    } // namespace



    void
    install_handlers()
    {
      std::signal(SIGTERM, record_signal);
      std::signal(SIGINT, record_signal);
    }



    int
    signal_received()
    {
      return received;
    }



    std::string
    signal_name(const int signal)
    {
      if (signal == SIGTERM)
        return "SIGTERM";
      if (signal == SIGINT)
        return "SIGINT";
      return "signal " + std::to_string(signal);
    }
  } // namespace interruption
} // namespace glissade
