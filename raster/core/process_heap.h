// Process-wide heap set-up for the command-line programs: freed memory is kept for reuse and fresh memory comes in
// transparent huge pages, so a first frame touches its buffers with a few page faults instead of thousands.
#pragma once

#include <cstddef>

namespace raster {

// What prepare_process_heap did, for --stats and tests.
struct ProcessHeapSetup {
    bool tuned = false;        // malloc accepted the thresholds
    size_t huge_bytes = 0;     // bytes of heap marked for transparent huge pages (0 where the kernel has none)
};

// Call once, first thing in main, before any thread starts. Every thread allocates from the one main heap (glibc
// otherwise gives each thread an arena of its own, outside the marked region); blocks up to 32 MiB come from the
// heap rather than from mmap, and freed memory is never handed back, so a second frame, or the PNG encoder after
// the frame, reuses pages already touched; then `huge_region` bytes of untouched heap are reserved and marked
// MADV_HUGEPAGE, so that the frame's first touch of its setups, tiles and image faults in 2 MiB pages.
// Without transparent huge pages the marking is a no-op and the rest still holds.
ProcessHeapSetup prepare_process_heap(size_t huge_region = size_t{128} << 20);

}  // namespace raster
