// The work splitter: runs fn(i) for i in [0, count) on a few threads.
#pragma once

#include <cstddef>
#include <functional>

namespace raster {

// Threads to use when the caller asks for 0 ("all cores").
int default_thread_count();

// Calls fn(i) exactly once for every i in [0, count), spread over `threads` threads (0 = default_thread_count()).
// Each i is independent work that writes only its own output, so the result does not depend on the thread count.
// The first exception thrown by fn is rethrown on the calling thread after all threads stop.
void parallel_for(size_t count, int threads, const std::function<void(size_t)>& fn);

// Starts the worker threads parallel_for(_, threads, _) will use, without waiting for them: a program calls it
// before loading its scene so that the first frame finds them running. The threads persist until exit.
void start_threads(int threads);

}  // namespace raster
