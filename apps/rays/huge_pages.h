// Transparent huge pages for the heap. Page faults are a large share of a render's time on the
// virtual machines Rays is measured on (a 2.5 MB scene touches ~100 MB of fresh memory). glibc's
// own switch for this (the glibc.malloc.hugetlb tunable) is read only at process start, and
// re-executing the program to set it costs a second process start; instead the program grows the
// main heap once, advises the kernel to back that range with huge pages (MADV_HUGEPAGE), and
// hands it back to malloc, which keeps it (no trimming) and serves later allocations from it.
#pragma once

#include <cstddef>

namespace rays::cli {

/// Virtual heap range advised for huge pages at start; allocations beyond it get normal pages.
inline constexpr std::size_t kHugeHeapBytes = std::size_t(256) << 20;

/// Keeps large freed blocks in the heap for reuse and, unless RAYS_NO_HUGEPAGES is set, prepares
/// kHugeHeapBytes of heap advised for huge pages, starting on a 2 MiB boundary, which every
/// thread allocates from (one malloc arena). Costs no physical memory until pages are used.
void enableHugePages();

}  // namespace rays::cli
