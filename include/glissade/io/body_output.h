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
   *
   * On several processes every process calls it: each writes the cells of
   * its share (<name>-<index>.<process>.vtu, process in four digits) and
   * process 0 the record over the pieces, <name>-<index>.pvtu, whose name
   * is returned (as deal.II's parallel programs write their output).
   */
  std::string
  write_body_vtu(const Body           &body,
                 const std::string    &directory,
                 const unsigned int    index,
                 const OutputSettings &settings);
} // namespace glissade
