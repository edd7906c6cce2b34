// The heap's unused pages given back (include/glissade/base/freed_memory.h).

#include <glissade/base/freed_memory.h>

#include <cstddef>
#include <cstdint>

#if defined(__GLIBC__)
#  include <malloc.h>
#  include <unistd.h>
#endif

namespace glissade
{
#if defined(__GLIBC__)
  namespace
  {
    // The main heap's top as the program starts (its static objects'
    // allocations before it are small).
    const std::uintptr_t heap_at_start =
      reinterpret_cast<std::uintptr_t>(sbrk(0));
  } // namespace
#endif


  void
  return_freed_memory()
  {
#if defined(__GLIBC__)
    // (a trim walks the heap and its pages are faulted in again when used:
    // 0.3 ms a call on a small scene, where nothing is to be gained; so
    // only where tens of megabytes lie free)
    const std::size_t worth_it = std::size_t(64) << 20;
    // mallinfo2 itself consolidates every arena's free chunks (5 % of a
    // small dynamic run, called at each assembly): where the main heap has
    // grown by less than half what is worth giving back since the program
    // started, it cannot hold that much free. (The large blocks of a big
    // run, its factors, tangents and contact algebra, are mapped on their
    // own or lie in the main heap.)
    const auto heap_top = reinterpret_cast<std::uintptr_t>(sbrk(0));
    if (heap_top >= heap_at_start && heap_top - heap_at_start < worth_it / 2)
      return;
    if (mallinfo2().fordblks >= worth_it)
      malloc_trim(0);
#endif
  }
} // namespace glissade
