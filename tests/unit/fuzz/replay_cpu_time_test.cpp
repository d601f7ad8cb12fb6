// The replay's clock: an input that spins in a worker thread past the limit is over it; one that only waits is not.
#include "fuzz/replay_cpu_time.h"

#include <time.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace raster::fuzz {
namespace {

// The CPU seconds the calling thread alone has used: the clock each spinning thread checks itself against.
double this_thread_cpu_seconds() {
    timespec now{};
    EXPECT_EQ(::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now), 0);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// Busy work until this thread has used `seconds` of CPU, however long that takes on a loaded machine.
void spin_for_cpu_seconds(double seconds) {
    const double start = this_thread_cpu_seconds();
    volatile unsigned long sink = 0;
    while (this_thread_cpu_seconds() - start < seconds) sink = sink + 1;
}

TEST(ReplayCpuTime, anInputSpinningInAWorkerThreadPastTheLimitIsOverIt) {
    // As a render does: the work runs on another thread while the calling one waits in join().
    const double spent = cpu_seconds_of([] {
        std::thread worker([] { spin_for_cpu_seconds(kHangCpuSeconds + 0.1); });
        worker.join();
    });
    EXPECT_GT(spent, kHangCpuSeconds);
    EXPECT_LT(spent, kHangCpuSeconds + 1.0);  // the join and the thread's start cost next to nothing
}

TEST(ReplayCpuTime, theWorkOfEveryThreadIsAddedUp) {
    const double spent = cpu_seconds_of([] {
        std::thread first([] { spin_for_cpu_seconds(0.2); });
        std::thread second([] { spin_for_cpu_seconds(0.2); });
        spin_for_cpu_seconds(0.2);
        first.join();
        second.join();
    });
    EXPECT_GE(spent, 0.6);
    EXPECT_LT(spent, 1.0);
}

TEST(ReplayCpuTime, waitingLongerThanTheLimitCostsNoCpuTime) {
    // What a ctest job on a busy machine does part of the time: it waits, and the wait is not the input's cost.
    const double spent =
        cpu_seconds_of([] { std::this_thread::sleep_for(std::chrono::duration<double>(kHangCpuSeconds + 0.2)); });
    EXPECT_LT(spent, 0.1);
}

TEST(ReplayCpuTime, processCpuSecondsCountsTheCallingThreadToo) {
    const double before = process_cpu_seconds();
    spin_for_cpu_seconds(0.05);
    EXPECT_GE(process_cpu_seconds() - before, 0.05);
}

}  // namespace
}  // namespace raster::fuzz
