#include <glissade/base/config.h>
#include <glissade/io/plotting.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace glissade
{
  namespace
  {
    /** 'text' for a POSIX shell, its own single quotes escaped. */
    std::string
    shell_quoted(const std::string &text)
    {
      std::string quoted = "'";
      for (const char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }
  } // namespace



  void
  plot_with_python(const std::string              &script,
                   const std::string              &directory,
                   const std::vector<std::string> &arguments)
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
    std::string command =
      "/usr/bin/python3 " + shell_quoted(path) + " " + shell_quoted(directory);
    for (const std::string &argument : arguments)
      command += " " + shell_quoted(argument);
    if (std::system(command.c_str()) != 0)
      std::cout << "(pictures not drawn: '" << command << "' failed)\n";
  }
} // namespace glissade
