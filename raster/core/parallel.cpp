// The work splitter over oneTBB: one task arena per thread count, kept for the process, so worker threads are
// started once and reused by every frame; indices are handed out one at a time as workers become free.
#include "raster/core/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace raster {
namespace {

// The arena for `threads` concurrent workers (the caller included), created on first use and kept: an arena's
// threads persist across calls, which is what makes the first tile of a frame start at once.
tbb::task_arena& arena_for(int threads) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
    std::lock_guard<std::mutex> lock(mutex);
    std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
    if (!arena) {
        arena = std::make_unique<tbb::task_arena>(threads);
        arena->initialize();
    }
    return *arena;
}

}  // namespace

int default_thread_count() {
    const unsigned hardware = std::thread::hardware_concurrency();
    return hardware == 0 ? 1 : static_cast<int>(std::min(hardware, 64u));
}

void start_threads(int threads) {
    if (threads <= 0) threads = default_thread_count();
    if (threads > 1) arena_for(threads).enqueue([] {});  // an empty task wakes the arena's workers
}

void parallel_for(size_t count, int threads, const std::function<void(size_t)>& fn) {
    if (threads <= 0) threads = default_thread_count();
    const size_t workers = std::min<size_t>(static_cast<size_t>(threads), count);
    if (workers <= 1) {
        for (size_t i = 0; i < count; ++i) fn(i);
        return;
    }
    // Grain 1 with the simple partitioner: every index is its own task, taken by whichever thread is free (tiles
    // differ widely in cost). TBB cancels the rest and rethrows the first exception here.
    // Isolated: a thread waiting here never takes up another call's work, whose per-thread scratch it may hold.
    arena_for(static_cast<int>(workers)).execute([&] {
        tbb::this_task_arena::isolate([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1),
                          [&](const tbb::blocked_range<size_t>& range) {
                              for (size_t i = range.begin(); i != range.end(); ++i) fn(i);
                          },
                          tbb::simple_partitioner());
        });
    });
}

}  // namespace raster
