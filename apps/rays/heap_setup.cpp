#include "heap_setup.h"

#include <malloc.h>

namespace rays::cli {

void prepareHeap() {
    mallopt(M_MMAP_THRESHOLD, 512 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    // The render's hot loops do not allocate, so the shared arena's lock is not contended.
    mallopt(M_ARENA_MAX, 1);
}

}  // namespace rays::cli
