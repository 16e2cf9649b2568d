#include "meshprep/core/heap_policy.h"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace meshprep {

void keep_freed_memory_for_reuse() {
#if defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)  // glibc's mallopt
  constexpr int kMmapThreshold = 256 << 20;  // glibc: 128 KiB at first, adapting up to 32 MiB
  constexpr int kTrimThreshold = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
#endif
}

}  // namespace meshprep
