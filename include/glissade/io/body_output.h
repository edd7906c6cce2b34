#pragma once

#include <glissade/description/scene_description.h>

#include <string>

namespace glissade
{
  class Body;

  /**
   * Writes `directory`/<name>-<index>.vtu for a body: the fields that
   * Output/VTU fields asks for (displacement, stress; a dynamic body's
   * velocity and acceleration beside the displacement), on patches that
   * follow its mapping. Returns the file's name.
   */
  std::string
  write_body_vtu(const Body           &body,
                 const std::string    &directory,
                 const unsigned int    index,
                 const OutputSettings &settings);
} // namespace glissade
