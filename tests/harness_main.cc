// The main() of every test program (tests/harness.h).

#include <cstdio>
#include <exception>
#include <iomanip>
#include <iostream>
#include <string>

#include "harness.h"

namespace glissade_tests
{
  std::map<std::string, RegisteredTest> &
  registry()
  {
    static std::map<std::string, RegisteredTest> tests;
    return tests;
  }

  Tally &
  tally()
  {
    static Tally counts;
    return counts;
  }

  void
  expect(const bool condition, const std::string &what)
  {
    ++tally().checks;
    if (!condition)
      ++tally().failures;
    std::printf("  %s %s\n", condition ? "[ ok ]" : "[FAIL]", what.c_str());
    std::fflush(stdout);
  }
} // namespace glissade_tests

int
main(int argc, char **argv)
{
  using namespace glissade_tests;
  const auto &tests = registry();
  if (argc == 2 && std::string(argv[1]) == "--list")
    {
      for (const auto &[name, test] : tests)
        if (test.is_test)
          std::printf("%s\n", name.c_str());
      return 0;
    }
  const auto chosen = argc == 2 ? tests.find(argv[1]) : tests.end();
  if (chosen == tests.end())
    {
      std::fprintf(stderr, "usage: %s <test> | --list; tests:", argv[0]);
      for (const auto &[name, test] : tests)
        std::fprintf(stderr, " %s%s", name.c_str(), test.is_test ? "" : "*");
      std::fprintf(stderr, "\n(* a benchmark group, not a test)\n");
      return 2;
    }
  const std::string name = chosen->first;
  // (the figures tests print with iostreams, to ten digits)
  std::cout << std::setprecision(10);
  std::printf("test %s\n", name.c_str());
  std::fflush(stdout);
  std::string error;
  try
    {
      chosen->second.run();
    }
  catch (const std::exception &e)
    {
      error = e.what();
    }
  const Tally &counts = tally();
  // (a benchmark group may print figures without checking any)
  const bool passed = error.empty() && counts.failures == 0 &&
                      (counts.checks > 0 || !chosen->second.is_test);
  std::cout << std::flush;
  std::fflush(stdout);
  std::printf("test %s: %u checks, %u failed: %s%s%s\n",
              name.c_str(),
              counts.checks,
              counts.failures,
              passed ? "passed" : "FAILED",
              error.empty() ? "" : ": ",
              error.c_str());
  return passed ? 0 : 1;
}
