// A process's memory (include/glissade/base/memory_use.h).

#include <glissade/base/debug_log.h>
#include <glissade/base/memory_use.h>
#include <glissade/base/processes.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace glissade
{
  MemoryUse
  memory_use()
  {
    // Lines "VmRSS:    123456 kB" and "VmHWM: ..." (proc(5)).
    MemoryUse     use;
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      {
        const bool resident = line.rfind("VmRSS:", 0) == 0;
        const bool peak     = line.rfind("VmHWM:", 0) == 0;
        if (!resident && !peak)
          continue;
        std::istringstream fields(line.substr(6));
        std::size_t        kilobytes = 0;
        fields >> kilobytes;
        (resident ? use.resident : use.peak) = kilobytes * 1024;
      }
    return use;
  }



  void
  log_memory_use(const std::string &phase)
  {
    if (!debug_log::at(1))
      return;
    const MemoryUse    use = memory_use();
    std::ostringstream line;
    line << std::fixed << std::setprecision(3) << "    memory after " << phase
         << " (process " << processes::rank() << "): resident "
         << use.resident / 1e9 << " GB, peak " << use.peak / 1e9 << " GB\n";
    debug_log::stream() << line.str() << std::flush;
  }
} // namespace glissade
