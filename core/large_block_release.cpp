#include "tide/core/large_block_release.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace tide {

void release_large_blocks_to_the_system() {
#if defined(M_MMAP_THRESHOLD)
  // A fixed threshold also turns off glibc's dynamic one (mallopt(3)).
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
}

}  // namespace tide
