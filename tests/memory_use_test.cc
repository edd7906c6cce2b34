// A process's memory as the operating system counts it (memory_use.h),
// against the bytes of an array the test fills.

#include <glissade/base/memory_use.h>

#include <iostream>
#include <vector>

#include "test_tools.h"

using namespace glissade;
using namespace glissade_tests;

// 200 MB filled: the resident memory grows by them (within 5 % below and
// 10 % above: the pages of the array, and what the program touches
// meanwhile), and the high-water mark is at least the resident memory.
GLISSADE_TEST(memory_use_counts_an_array)
{
  const MemoryUse     before = memory_use();
  const std::size_t   bytes  = std::size_t(200) << 20;
  std::vector<double> array(bytes / sizeof(double), 1.);
  const MemoryUse     after = memory_use();
  const double        grown = double(after.resident) - double(before.resident);
  std::cout << "  resident " << before.resident / 1e6 << " MB -> "
            << after.resident / 1e6 << " MB for " << bytes / 1e6
            << " MB filled (sum " << array[0] + array.back() << "); peak "
            << after.peak / 1e6 << " MB" << std::endl;
  check(before.resident > 0 && before.peak >= before.resident,
        "no resident memory or a peak below it");
  check(grown >= 0.95 * bytes && grown <= 1.10 * bytes,
        "the resident memory did not grow by the array's bytes");
  check(after.peak >= after.resident, "the peak is below the resident memory");
}
