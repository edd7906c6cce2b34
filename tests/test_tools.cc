#include "test_tools.h"

#include "source_tree.h"

namespace glissade_tests
{
  std::string
  source_path(const std::string &relative)
  {
    return std::string(GLISSADE_SOURCE_DIR) + "/" + relative;
  }
} // namespace glissade_tests
