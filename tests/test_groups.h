#pragma once

// The command line of the kernel test programs (tests/surface, tests/hermite,
// tests/bipotential), which are written without deal.II: `program <group>`
// runs one group of checks, `program --list` prints the groups that are
// tests, one per line. ctest reads that list after each build
// (tests/discover_tests.cmake), so a group is named once, here in its
// program's table.

#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <string>

namespace glissade_tests
{
  using Groups = std::map<std::string, std::function<void()>>;

  /**
   * What argv asks for: a group of `tests` or of `others` (groups that are
   * not tests, e.g. timings for the benchmark target) is returned in
   * `chosen` with the result true; --list prints the names of `tests`, a
   * wrong argument prints the usage, and both return false with the exit
   * code in `exit_code`.
   */
  inline bool
  choose_group(const int              argc,
               char                 **argv,
               const Groups          &tests,
               const Groups          &others,
               std::function<void()> &chosen,
               int                   &exit_code)
  {
    if (argc == 2 && std::strcmp(argv[1], "--list") == 0)
      {
        for (const auto &test : tests)
          std::printf("%s\n", test.first.c_str());
        exit_code = 0;
        return false;
      }
    for (const Groups *groups : {&tests, &others})
      if (argc == 2 && groups->count(argv[1]) == 1)
        {
          chosen = groups->at(argv[1]);
          return true;
        }
    std::printf("usage: %s <group> | --list; groups:", argv[0]);
    for (const Groups *groups : {&tests, &others})
      for (const auto &group : *groups)
        std::printf(" %s", group.first.c_str());
    std::printf("\n");
    exit_code = 2;
    return false;
  }
} // namespace glissade_tests
