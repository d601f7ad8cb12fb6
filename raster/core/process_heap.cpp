// Process-wide heap set-up: glibc malloc thresholds and a heap region marked for transparent huge pages.
#include "raster/core/process_heap.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#if defined(__GLIBC__) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace raster {

#if defined(__GLIBC__) && defined(__linux__)
namespace {

constexpr size_t kHugePage = size_t{2} << 20;
// The largest threshold glibc's own adjustment would reach on 64-bit: blocks below it come from the heap; larger
// ones (sample planes, which have PlaneAllocator) stay with mmap.
constexpr int kMmapThreshold = 32 << 20;

// Marks the whole huge pages inside [begin, end); returns how many bytes that is.
size_t mark_huge(uintptr_t begin, uintptr_t end) {
    const uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1), last = end & ~(kHugePage - 1);
    if (last <= first || ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) != 0) return 0;
    return last - first;
}

}  // namespace

ProcessHeapSetup prepare_process_heap(size_t huge_region) {
    ProcessHeapSetup setup;
    // Each option on its own: one that glibc refuses leaves the others in force, and `tuned` false.
    const bool options[] = {mallopt(M_ARENA_MAX, 1) == 1, mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1,
                            mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1, mallopt(M_TOP_PAD, 16 << 20) == 1};
    setup.tuned = std::all_of(std::begin(options), std::end(options), [](bool accepted) { return accepted; });
    if (!setup.tuned) return setup;  // a sanitizer's or another allocator's malloc: nothing to mark
    // Blocks below the mmap threshold that the heap grows for: they lie in fresh, untouched heap, and once freed
    // they stay there (below the trim threshold) for the frame's blocks to be carved from. They are consecutive in
    // the heap, so the whole span up to the break (the top pad included) is marked at once.
    const size_t block_bytes = static_cast<size_t>(kMmapThreshold) - kHugePage;
    std::vector<void*> blocks;
    for (size_t reserved = 0; reserved < huge_region; reserved += block_bytes) {
        void* block = std::malloc(block_bytes);
        if (!block) break;
        blocks.push_back(block);
    }
    if (!blocks.empty()) {
        const auto [low, high] = std::minmax_element(blocks.begin(), blocks.end());
        const auto begin = reinterpret_cast<uintptr_t>(*low);
        const auto end = reinterpret_cast<uintptr_t>(*high) + block_bytes;
        const auto brk = reinterpret_cast<uintptr_t>(::sbrk(0));
        // Not one span of the heap means glibc fell back to mmap for some block: freeing unmaps it, and a marking
        // would go with it, so nothing is marked.
        if (begin < end && end <= brk && brk - begin <= 2 * huge_region + (size_t{64} << 20))
            setup.huge_bytes = mark_huge(begin, brk);
    }
    for (void* block : blocks) std::free(block);
    return setup;
}

#else

ProcessHeapSetup prepare_process_heap(size_t) { return {}; }  // glibc's options only

#endif

}  // namespace raster
