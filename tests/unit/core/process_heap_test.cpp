// Tests of the process heap set-up: a fresh frame buffer is touched in huge pages, and the region marked for them
// is most of the one asked for.
#include "raster/core/process_heap.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

namespace raster {
namespace {

// The kernel's transparent huge page mode ("always", "madvise", "never"), or "" without THP.
std::string huge_page_mode() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    if (!std::getline(in, line)) return "";
    const size_t open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

long minor_faults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

TEST(ProcessHeap, touchingAFreshFrameBufferFaultsInHugePagesNotPageByPage) {
    const std::string mode = huge_page_mode();
    if (mode != "always" && mode != "madvise") GTEST_SKIP() << "transparent huge pages are off here";
    ASSERT_TRUE(prepare_process_heap().tuned);
    // A first frame's buffer: 16 MiB written once. In 4 KiB pages that is 4096 faults (about 20 ms on this kind of
    // virtual machine); in the marked heap most of it comes in 2 MiB pages.
    constexpr size_t kBytes = size_t{16} << 20;
    const long pages = static_cast<long>(kBytes / static_cast<size_t>(sysconf(_SC_PAGESIZE)));
    const long before = minor_faults();
    void* buffer = std::malloc(kBytes);
    ASSERT_NE(buffer, nullptr);
    std::memset(buffer, 1, kBytes);
    asm volatile("" : : "r"(buffer) : "memory");  // the writes happen: the compiler may not drop them
    const long faults = minor_faults() - before;
    std::free(buffer);
    EXPECT_LT(faults, pages / 4) << "of " << pages << " pages";
}

TEST(ProcessHeap, marksMostOfTheRegionForHugePagesWhereTheKernelHasThem) {
    if (huge_page_mode().empty()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    constexpr size_t kRegion = size_t{128} << 20;
    const ProcessHeapSetup setup = prepare_process_heap(kRegion);
    ASSERT_TRUE(setup.tuned);
    // Each 30 MiB block loses at most one huge page to alignment, and the last block may run past the region.
    EXPECT_GE(setup.huge_bytes, kRegion / 2);
    EXPECT_LE(setup.huge_bytes, kRegion + (size_t{32} << 20));
}

}  // namespace
}  // namespace raster
