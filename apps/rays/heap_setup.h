// The CLI's malloc settings, made once at start: large blocks come from the heap and stay there
// when freed (a later buffer of the render reuses pages already mapped instead of faulting in
// fresh ones), and every thread allocates from the one arena of the main heap.
//
// The heap is not advised for transparent huge pages (it was until 2026-11-24): on the virtual
// machines Rays is measured on, a huge page of fresh memory often comes from blocks the guest has
// reported free to the host, and faulting it back costs more than the 4 KB faults it saves
// (balls2.pov's parse: median 7 ms on 4 KB pages against 15-28 ms advised; docs/design-notes.md).
// Buffers of 4 MiB and more (BVH arrays, images) still get huge pages (rays/accel/huge_pages.h).
#pragma once

namespace rays::cli {

/// Raises malloc's mmap and trim thresholds (blocks below 512 MiB come from the heap and are
/// kept for reuse) and limits malloc to one arena (worker threads' own arenas would be mapped
/// apart, each a new set of page faults).
void prepareHeap();

}  // namespace rays::cli
