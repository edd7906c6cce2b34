#include <glissade/io/plotting.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <system_error>

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



    /**
     * Where `script` is: in $GLISSADE_SCRIPTS if that is set, otherwise in
     * the scripts/ folder that the build copies beside the glissade program
     * (the test and benchmark programs are one folder further down). Found
     * from the running program, so that a build or a copy of it that is
     * moved keeps its pictures. Empty if it is nowhere.
     */
    std::filesystem::path
    find_script(const std::string &script)
    {
      if (const char *from_environment = std::getenv("GLISSADE_SCRIPTS"))
        return std::filesystem::path(from_environment) / script;
      std::error_code             error;
      const std::filesystem::path program =
        std::filesystem::read_symlink("/proc/self/exe", error);
      if (error)
        return {};
      std::filesystem::path folder = program.parent_path();
      for (unsigned int level = 0; level < 2; ++level)
        {
          const std::filesystem::path candidate = folder / "scripts" / script;
          if (std::filesystem::exists(candidate, error))
            return candidate;
          folder = folder.parent_path();
        }
      return {};
    }
  } // namespace



  void
  plot_with_python(const std::string              &script,
                   const std::string              &directory,
                   const std::vector<std::string> &arguments)
  {
    const std::filesystem::path path = find_script(script);
    std::error_code             error;
    if (!std::filesystem::exists("/usr/bin/python3", error) || path.empty() ||
        !std::filesystem::exists(path, error))
      {
        std::cout << "(no pictures: /usr/bin/python3 or the script "
                  << (path.empty() ? script : path.string())
                  << " missing; set GLISSADE_SCRIPTS to the scripts/ folder "
                     "of the source tree)\n";
        return;
      }
    std::cout << std::flush;
    std::string command = "/usr/bin/python3 " + shell_quoted(path.string()) +
                          " " + shell_quoted(directory);
    for (const std::string &argument : arguments)
      command += " " + shell_quoted(argument);
    if (std::system(command.c_str()) != 0)
      std::cout << "(pictures not drawn: '" << command << "' failed)\n";
  }
} // namespace glissade
