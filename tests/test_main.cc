#include <cmath>
#include <iomanip>

#include "source_tree.h"
#include "test_tools.h"

namespace glissade_tests
{
  std::map<std::string, TestFunction> &
  registry()
  {
    static std::map<std::string, TestFunction> tests;
    return tests;
  }

  std::string
  source_path(const std::string &relative)
  {
    return std::string(GLISSADE_SOURCE_DIR) + "/" + relative;
  }
} // namespace glissade_tests

int
main(int argc, char **argv)
{
  auto &tests = glissade_tests::registry();
  // ctest learns the test names from here (tests/discover_tests.cmake), so
  // a test is named once, where it is written.
  if (argc == 2 && std::string(argv[1]) == "--list")
    {
      for (const auto &t : tests)
        std::cout << t.first << '\n';
      return 0;
    }
  if (argc != 2 || tests.find(argv[1]) == tests.end())
    {
      std::cerr << "usage: glissade_tests <test>; tests:\n";
      for (const auto &t : tests)
        std::cerr << "  " << t.first << '\n';
      return 2;
    }
  std::cout << std::setprecision(10);
  try
    {
      std::cout << "test " << argv[1] << std::endl;
      tests[argv[1]]();
      std::cout << "test " << argv[1] << ": passed" << std::endl;
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cout << "test " << argv[1] << ": FAILED: " << e.what() << std::endl;
      return 1;
    }
}
