#include <glissade/base/input_error.h>
#include <glissade/base/text.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace glissade
{
  namespace text
  {
    std::string
    trim(const std::string &s)
    {
      const auto begin = s.find_first_not_of(" \t\n\r");
      if (begin == std::string::npos)
        return "";
      const auto end = s.find_last_not_of(" \t\n\r");
      return s.substr(begin, end - begin + 1);
    }



    std::vector<std::string>
    split_top_level(const std::string &s, const char separator)
    {
      std::vector<std::string> parts;
      std::string              current;
      int                      depth = 0;
      for (const char c : s)
        {
          if (c == '(')
            ++depth;
          else if (c == ')')
            --depth;
          if (c == separator && depth == 0)
            {
              parts.push_back(trim(current));
              current.clear();
            }
          else
            current += c;
        }
      if (!trim(current).empty() || !parts.empty())
        parts.push_back(trim(current));
      return parts;
    }



    std::array<double, 2>
    coordinates(const std::string &text_value, const std::string &where)
    {
      const auto parts = text::split_top_level(text_value, ',');
      if (parts.size() != 2)
        throw InputError(where,
                         "expected two coordinates 'x, y', got '" + text_value +
                           "'");
      // Every character must belong to the number ("0.5abc" and "0.5*t"
      // were read as 0.5), and the number must be finite and small enough
      // that squared distances do not overflow.
      std::array<double, 2> x;
      for (unsigned int i = 0; i < 2; ++i)
        {
          const std::string part = text::trim(parts[i]);
          char             *end  = nullptr;
          x[i]                   = std::strtod(part.c_str(), &end);
          if (part.empty() || *end != '\0')
            throw InputError(where,
                             "cannot read coordinates '" + text_value + "': '" +
                               part + "' is not a number");
          if (!std::isfinite(x[i]) || std::abs(x[i]) > 1e100)
            throw InputError(where,
                             "coordinates '" + text_value +
                               "': each must be finite and below 1e100 in "
                               "magnitude");
        }
      return x;
    }



    bool
    parse_point_location(const std::string &location, double &x, double &y)
    {
      const std::string l = trim(location);
      if (l.rfind("point(", 0) != 0 || l.back() != ')')
        return false;
      const auto coordinates = split_top_level(l.substr(6, l.size() - 7), ',');
      if (coordinates.size() != 2)
        return false;
      char *end = nullptr;
      x         = std::strtod(coordinates[0].c_str(), &end);
      if (*end != '\0')
        return false;
      y = std::strtod(coordinates[1].c_str(), &end);
      return *end == '\0';
    }



    std::string
    essential_message(const std::exception &e)
    {
      std::string       message = e.what();
      const std::string marker  = "Additional information:";
      const auto        begin   = message.find(marker);
      if (begin != std::string::npos)
        message = message.substr(begin + marker.size());
      const auto end = message.find("Stacktrace:");
      if (end != std::string::npos)
        message = message.substr(0, end);
      std::string compact;
      bool        space = false;
      for (const char c : message)
        if (c == '\n' || c == ' ' || c == '\t')
          space = true;
        else
          {
            if (space && !compact.empty())
              compact += ' ';
            compact += c;
            space = false;
          }
      return compact;
    }



    bool
    is_regular_file_of_at_most(const std::string       &path,
                               const unsigned long long largest)
    {
      std::error_code error;
      if (!std::filesystem::is_regular_file(path, error) || error)
        return false;
      const auto size = std::filesystem::file_size(path, error);
      return !error && size <= largest;
    }



    std::string
    path_beside(const std::string &file, const std::string &path)
    {
      if (path.empty() || path[0] == '/')
        return path;
      const auto slash = file.find_last_of('/');
      return slash == std::string::npos ? path :
                                          file.substr(0, slash + 1) + path;
    }



    std::string
    joined(const std::vector<std::string> &items, const std::string &separator)
    {
      std::string text;
      for (std::size_t i = 0; i < items.size(); ++i)
        text += (i > 0 ? separator : std::string()) + items[i];
      return text;
    }



  } // namespace text
} // namespace glissade
