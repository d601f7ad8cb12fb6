// Allocator for full-frame sample planes: large blocks are 2 MiB aligned and marked for transparent huge pages,
// so touching a fresh frame costs a few page faults instead of thousands.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include <sys/mman.h>

namespace raster {

template <class T>
struct PlaneAllocator {
    using value_type = T;
    static constexpr size_t kHugePage = size_t{2} << 20;

    PlaneAllocator() = default;
    template <class U>
    PlaneAllocator(const PlaneAllocator<U>&) {}

    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (bytes < 2 * kHugePage) {
            if (void* p = std::malloc(bytes)) return static_cast<T*>(p);
            throw std::bad_alloc();
        }
        const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* p = std::aligned_alloc(kHugePage, rounded);
        if (!p) throw std::bad_alloc();
        ::madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without THP it is ordinary memory
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t) { std::free(p); }

    template <class U>
    bool operator==(const PlaneAllocator<U>&) const { return true; }
};

// A full-frame plane of per-sample or per-pixel values.
template <class T>
using Plane = std::vector<T, PlaneAllocator<T>>;

}  // namespace raster
