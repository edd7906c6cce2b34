#include <glissade/base/debug_log.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace glissade
{
  namespace debug_log
  {
    unsigned int
    level()
    {
      static const unsigned int asked = []() -> unsigned int {
        const char *value = std::getenv("GLISSADE_DEBUG");
        if (value == nullptr)
          return 0;
        const std::string text(value);
        return text == "2" ? 2 : text == "3" ? 3 : 1;
      }();
      return asked;
    }



    std::ostream &
    stream()
    {
      return std::cerr;
    }
  } // namespace debug_log
} // namespace glissade
