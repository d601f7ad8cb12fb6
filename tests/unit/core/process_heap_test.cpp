// Tests of the process heap set-up: a fresh frame buffer lies in heap marked for huge pages, and the marked region
// is most of the one asked for.
#include "raster/core/process_heap.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/mman.h>

namespace raster {
namespace {

// The kernel's flags ("VmFlags" in /proc/self/smaps, e.g. "rd wr mr mw me ac hg") for the mapping holding `p`;
// "" when it cannot be read.
std::string mapping_flags(const void* p) {
    const auto address = reinterpret_cast<uintptr_t>(p);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream header(line);
        if (header >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= address && address < end;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line.substr(8) + " ";
    }
    return "";
}

// Whether the kernel takes MADV_HUGEPAGE on anonymous memory: asked on a mapping of the test's own, not the heap.
bool kernel_takes_huge_page_advice() {
    constexpr size_t kBytes = size_t{4} << 20;
    void* p = ::mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return false;
    const auto aligned = (reinterpret_cast<uintptr_t>(p) + (size_t{2} << 20) - 1) & ~((size_t{2} << 20) - 1);
    const bool taken = ::madvise(reinterpret_cast<void*>(aligned), size_t{2} << 20, MADV_HUGEPAGE) == 0;
    ::munmap(p, kBytes);
    return taken;
}

// Each test sets the heap up first, and skips where there is nothing to check: another malloc than glibc's, or a
// kernel that refuses the advice.
class ProcessHeap : public ::testing::Test {
protected:
    void SetUp() override {
        setup = prepare_process_heap();
        if (!setup.tuned) GTEST_SKIP() << "this malloc is not glibc's (a sanitizer build?): nothing is set up";
        if (!kernel_takes_huge_page_advice()) GTEST_SKIP() << "madvise(MADV_HUGEPAGE) is refused here";
    }
    ProcessHeapSetup setup;
};

TEST_F(ProcessHeap, aFreshFrameBufferLiesInHeapMarkedForHugePages) {
    // A first frame's buffer: 16 MiB, carved from the reserved heap. Without the set-up glibc would mmap it, in a
    // mapping of its own without the flag, and its first touch would fault 4,096 pages one by one.
    constexpr size_t kBytes = size_t{16} << 20;
    char* buffer = static_cast<char*>(std::malloc(kBytes));
    ASSERT_NE(buffer, nullptr);
    const std::string flags = mapping_flags(buffer + kBytes / 2);
    std::free(buffer);
    ASSERT_FALSE(flags.empty()) << "cannot read /proc/self/smaps";
    EXPECT_NE(flags.find(" hg "), std::string::npos) << "VmFlags:" << flags;
}

TEST_F(ProcessHeap, marksMostOfTheRegionAskedFor) {
    // Five blocks of 30 MiB and the 16 MiB top pad, less at most a huge page at each end of the span.
    EXPECT_GE(setup.huge_bytes, size_t{128} << 20);
    EXPECT_LE(setup.huge_bytes, size_t{200} << 20);
}

}  // namespace
}  // namespace raster
