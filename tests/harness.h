#pragma once

// glissade's one harness for its C++ tests (doc/design.md, "Tests"), in
// every test program (glissade_tests and the kernel programs of
// tests/surface, tests/hermite, tests/bipotential, which are written
// without deal.II, so this file uses the standard library only).
//
// A test is a function registered by name, GLISSADE_TEST(name) { ... }, and
// run by `program <name>`; `program --list` prints the names, which ctest
// reads after each build (tests/discover_tests.cmake): a test is named once,
// where it is written. GLISSADE_BENCHMARK(name) registers a group that is
// not a test (timings the benchmark target prints).
//
// Checks are counted one way. check(condition, what): a failure ends the
// test (what follows may rely on it). expect(condition, what): the line is
// printed with [ ok ] or [FAIL] and the test goes on, to show every figure
// of a table; it fails at its end. The program prints the count of checks
// and failures, and exits 0 only if a test ran and none failed. Every test
// prints the figures it checks, so a ctest log is a record of what was
// measured.

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace glissade_tests
{
  using TestFunction = std::function<void()>;

  struct RegisteredTest
  {
    TestFunction run;
    /** A ctest test (listed by --list), or a benchmark group (not). */
    bool is_test = true;
  };

  std::map<std::string, RegisteredTest> &
  registry();

  struct Registration
  {
    Registration(const std::string &name,
                 TestFunction       run,
                 const bool         is_test = true)
    {
      registry()[name] = {std::move(run), is_test};
    }
  };

  /** Several tests at once, from a table of names and functions. */
  struct Registrations
  {
    Registrations(
      const std::vector<std::pair<std::string, TestFunction>> &tests,
      const bool                                               is_test = true)
    {
      for (const auto &[name, run] : tests)
        registry()[name] = {run, is_test};
    }
  };

  /** The checks of the test that runs, and how many failed. */
  struct Tally
  {
    unsigned int checks   = 0;
    unsigned int failures = 0;
  };

  Tally &
  tally();

  class CheckFailed : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** A check whose failure ends the test. */
  inline void
  check(const bool condition, const std::string &what)
  {
    ++tally().checks;
    if (!condition)
      {
        ++tally().failures;
        throw CheckFailed(what);
      }
  }

  /** A check printed as a line of its table; the test goes on. */
  void
  expect(const bool condition, const std::string &what);
} // namespace glissade_tests

#define GLISSADE_TEST(name)                                                    \
  static void                         test_##name();                           \
  static glissade_tests::Registration registration_##name(#name, test_##name); \
  static void                         test_##name()

#define GLISSADE_BENCHMARK(name)                                            \
  static void                         benchmark_##name();                   \
  static glissade_tests::Registration registration_##name(#name,            \
                                                          benchmark_##name, \
                                                          false);           \
  static void                         benchmark_##name()
