// Process-wide heap set-up for the command-line programs: freed memory is kept for reuse and fresh memory comes in
// transparent huge pages, so a first frame touches its buffers with a few page faults instead of thousands.
#pragma once

#include <cstddef>

namespace raster {

// What prepare_process_heap did.
struct ProcessHeapSetup {
    bool tuned = false;     // glibc accepted every malloc option (false under a sanitizer's malloc, or off glibc)
    size_t huge_bytes = 0;  // bytes of heap marked MADV_HUGEPAGE (0 where madvise refuses it)
};

// Call once, first thing in main, before any thread starts. Every thread allocates from the one main heap (glibc
// otherwise gives each thread an arena of its own, outside the marked region); blocks below 32 MiB come from the
// heap rather than from mmap, and the heap is trimmed only when over 1 GiB is free at its top, so a second frame,
// or the PNG encoder after the frame, reuses pages already touched. Then about `huge_region` bytes of untouched
// heap are reserved, marked MADV_HUGEPAGE and freed, so that the frame's first touch of its setups, tiles and
// image faults in 2 MiB pages where the kernel has transparent huge pages (elsewhere the marking changes nothing).
// Blocks of 32 MiB or more (sample planes: PlaneAllocator) are mmap'd as before. Off glibc it does nothing.
ProcessHeapSetup prepare_process_heap(size_t huge_region = size_t{128} << 20);

}  // namespace raster
