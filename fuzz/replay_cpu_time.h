// How the corpus replay measures one input: the CPU time of the whole process, and the limit that makes it a hang.
#pragma once

#include <functional>

namespace raster::fuzz {

// An input whose replay costs more CPU time than this fails the replay. It is the fuzzers' own hang limit
// (`timeout = 1` in fuzz/NAME.options), which they apply to their ASan + UBSan build, slower than this optimised one:
// an input near it here is past it there. A real hang, an endless loop, passes any limit.
inline constexpr double kHangCpuSeconds = 1.0;

// The CPU seconds this process has used so far, every thread's added up (CLOCK_PROCESS_CPUTIME_ID).
double process_cpu_seconds();

// The process CPU time that `work` costs. Process time rather than the calling thread's, because the renderer
// splits a frame across worker threads (`cli` inputs render with all cores) while the calling thread waits in
// join(): its own clock would miss a loop that spins in a worker. Unlike wall time, it does not grow while the
// process waits for a core that another ctest job holds, so the verdict is the same on a busy machine.
double cpu_seconds_of(const std::function<void()>& work);

}  // namespace raster::fuzz
