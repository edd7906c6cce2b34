#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/scene/parameter_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace glissade
{
  namespace
  {
    // A scene is a few kilobytes; a generated one with long point lists a
    // few hundred. Anything larger is not a parameter file.
    constexpr std::uintmax_t largest_parameter_file = 16u << 20;
    constexpr unsigned int   deepest_include        = 32;

    std::string
    chain_of(const std::vector<std::string> &stack)
    {
      std::string chain;
      for (const auto &file : stack)
        chain += (chain.empty() ? "" : " -> ") + file;
      return chain;
    }

    std::string
    read_text(const std::string &filename)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      const auto      status = fs::status(filename, error);
      if (error || !fs::exists(status))
        throw InputError(filename, "cannot open the parameter file");
      if (fs::is_directory(status))
        throw InputError(filename,
                         "is a directory, not a parameter file (.prm)");
      if (!fs::is_regular_file(status))
        throw InputError(filename,
                         "is not a regular file (a device or a pipe?): "
                         "give a parameter file (.prm)");
      const auto size = fs::file_size(filename, error);
      if (error || size > largest_parameter_file)
        throw InputError(filename,
                         "is larger than 16 MiB: not a parameter file");
      std::ifstream in(filename, std::ios::binary);
      if (!in)
        throw InputError(filename, "cannot open the parameter file");
      std::stringstream buffer;
      buffer << in.rdbuf();
      const std::string text_value = buffer.str();
      if (text_value.find('\0') != std::string::npos)
        throw InputError(filename,
                         "contains NUL bytes: a binary file, not a parameter "
                         "file (.prm)");
      if (text::trim(text_value).empty())
        throw InputError(filename,
                         "is empty: a scene needs at least Scene/Bodies and "
                         "a 'subsection Body <name>' with its mesh (see "
                         "doc/parameters.prm)");
      return text_value;
    }

    std::string
    expand(const std::string &filename, std::vector<std::string> &stack)
    {
      namespace fs = std::filesystem;
      std::error_code   error;
      const std::string canonical =
        fs::weakly_canonical(filename, error).string();
      for (const auto &open : stack)
        if (open == canonical)
          {
            stack.push_back(canonical);
            throw InputError(filename, "includes itself: " + chain_of(stack));
          }
      if (stack.size() >= deepest_include)
        throw InputError(filename,
                         "includes are nested more than 32 deep: " +
                           chain_of(stack));
      stack.push_back(canonical);

      std::istringstream in(read_text(filename));
      std::string        expanded, line;
      unsigned int       line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          const std::string stripped = text::trim(line);
          if (stripped.rfind("include", 0) == 0 && stripped.size() > 7 &&
              (stripped[7] == ' ' || stripped[7] == '\t'))
            {
              const std::string name = text::trim(stripped.substr(8));
              if (name.empty())
                throw InputError(filename + ", line " +
                                   std::to_string(line_number),
                                 "'include' names no file");
              expanded += expand(text::path_beside(filename, name), stack);
              expanded += '\n';
            }
          else
            expanded += line + '\n';
        }
      stack.pop_back();
      return expanded;
    }
  } // namespace



  std::string
  read_parameter_file(const std::string &filename)
  {
    std::vector<std::string> stack;
    return expand(filename, stack);
  }
} // namespace glissade
