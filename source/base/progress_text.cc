#include <glissade/base/progress_text.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace glissade
{
  namespace progress_text
  {
    std::string
    duration(const double seconds)
    {
      std::ostringstream text;
      const long         s = std::lround(seconds);
      if (seconds < 10.)
        text << std::fixed << std::setprecision(1) << seconds << " s";
      else if (s < 120)
        text << s << " s";
      else if (s < 7200)
        text << s / 60 << " min " << std::setw(2) << std::setfill('0') << s % 60
             << " s";
      else
        text << s / 3600 << " h " << std::setw(2) << std::setfill('0')
             << (s % 3600) / 60 << " min";
      return text.str();
    }



    std::string
    time_left(const double       elapsed,
              const unsigned int done,
              const unsigned int remaining)
    {
      std::string text = "elapsed " + duration(elapsed);
      if (done > 0 && remaining > 0)
        text += ", about " + duration(elapsed / done * remaining) + " left";
      return text;
    }
  } // namespace progress_text
} // namespace glissade
