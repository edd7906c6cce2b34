#include <glissade/base/config.h>
#include <glissade/io/plotting.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace glissade
{
  void
  plot_with_python(const std::string &script, const std::string &directory)
  {
    const std::string path =
      std::string(GLISSADE_SOURCE_DIR) + "/scripts/" + script;
    if (!std::filesystem::exists("/usr/bin/python3") ||
        !std::filesystem::exists(path))
      {
        std::cout << "(no pictures: /usr/bin/python3 or " << path
                  << " missing)\n";
        return;
      }
    std::cout << std::flush;
    const std::string command =
      "/usr/bin/python3 '" + path + "' '" + directory + "'";
    if (std::system(command.c_str()) != 0)
      std::cout << "(pictures not drawn: '" << command << "' failed)\n";
  }
} // namespace glissade
