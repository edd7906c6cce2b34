#pragma once

#include <string>

namespace glissade
{
  /**
   * The text of a .prm file, ready for deal.II's ParameterHandler, with
   * every `include <file>` line replaced by the text of that file.
   *
   * We expand includes ourselves rather than leaving them to
   * ParameterHandler because its expansion resolves a relative name against
   * the working directory, follows an include loop until the stack
   * overflows, and reads a device such as /dev/zero until memory runs out.
   * Here an included file is taken relative to the file that includes it,
   * a loop is an input error naming the chain of files, and only regular
   * text files of reasonable size are read: a directory, an empty file or
   * a binary file is refused with a message about the file.
   */
  std::string
  read_parameter_file(const std::string &filename);
} // namespace glissade
