// The heap's unused pages given back (include/glissade/base/freed_memory.h).

#include <glissade/base/freed_memory.h>

#include <cstddef>

#if defined(__GLIBC__)
#  include <malloc.h>
#endif

namespace glissade
{
  void
  return_freed_memory()
  {
#if defined(__GLIBC__)
    // (a trim walks the heap and its pages are faulted in again when used:
    // 0.3 ms a call on a small scene, where nothing is to be gained; so
    // only where tens of megabytes lie free)
    const std::size_t worth_it = std::size_t(64) << 20;
    if (mallinfo2().fordblks >= worth_it)
      malloc_trim(0);
#endif
  }
} // namespace glissade
