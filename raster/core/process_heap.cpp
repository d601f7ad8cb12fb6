// Process-wide heap set-up: glibc malloc thresholds and a heap region marked for transparent huge pages.
#include "raster/core/process_heap.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include <malloc.h>
#include <sys/mman.h>

namespace raster {
namespace {

constexpr size_t kHugePage = size_t{2} << 20;
constexpr int kMmapThreshold = 32 << 20;  // glibc's cap on 64-bit; larger blocks (sample planes): PlaneAllocator

// Marks the whole huge pages inside [begin, begin + bytes); returns how many bytes that is.
size_t mark_huge(void* begin, size_t bytes) {
    const auto first = (reinterpret_cast<uintptr_t>(begin) + kHugePage - 1) & ~(kHugePage - 1);
    const auto last = (reinterpret_cast<uintptr_t>(begin) + bytes) & ~(kHugePage - 1);
    if (last <= first || ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) != 0) return 0;
    return last - first;
}

}  // namespace

ProcessHeapSetup prepare_process_heap(size_t huge_region) {
    ProcessHeapSetup setup;
    setup.tuned = mallopt(M_ARENA_MAX, 1) == 1 && mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
                  mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1 && mallopt(M_TOP_PAD, 16 << 20) == 1;
    if (!setup.tuned) return setup;
    // Blocks below the mmap threshold that the heap grows for: they lie in fresh, untouched heap, and once freed
    // they stay there (below the trim threshold) for the frame's blocks to be carved from.
    const size_t block_bytes = static_cast<size_t>(kMmapThreshold) - kHugePage;
    std::vector<void*> blocks;
    for (size_t reserved = 0; reserved < huge_region; reserved += block_bytes) {
        void* block = std::malloc(block_bytes);
        if (!block) break;
        blocks.push_back(block);
        setup.huge_bytes += mark_huge(block, block_bytes);
    }
    for (void* block : blocks) std::free(block);
    return setup;
}

}  // namespace raster
