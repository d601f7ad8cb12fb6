// The replay's CPU clock: clock_gettime(CLOCK_PROCESS_CPUTIME_ID), which counts every thread of the process.
#include "fuzz/replay_cpu_time.h"

#include <time.h>

#include <cstdio>
#include <cstdlib>

namespace raster::fuzz {

double process_cpu_seconds() {
    timespec now{};
    if (::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now) != 0) {
        // Linux always has this clock; without it no input could be timed, so stop rather than pass them all.
        std::perror("replay: clock_gettime(CLOCK_PROCESS_CPUTIME_ID)");
        std::abort();
    }
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double cpu_seconds_of(const std::function<void()>& work) {
    const double start = process_cpu_seconds();
    work();
    return process_cpu_seconds() - start;
}

}  // namespace raster::fuzz
