// Setup references: a frame's setups stay where the front end's chunks wrote them, and a 32-bit reference,
// part << 16 | index in the part, names one of them in the tile bins and the winner planes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/core/conventions.h"
#include "raster/geometry/clip.h"
#include "raster/geometry/setup.h"
#include "raster/scene/mesh.h"

namespace raster {

inline constexpr int kSetupRefShift = 16;
inline constexpr uint32_t kSetupsPerPart = uint32_t{1} << kSetupRefShift;
// The front end sets up scene triangles in chunks of this many; each chunk's setups are one part.
inline constexpr size_t kSetupChunkTriangles = 4096;
// A polygon clipped from one triangle is a fan of at most kMaxClippedVertices - 2 setups, so a chunk's setups fit
// in a part, and no reference (part < 2^16, index < 2^16 - 1) is kNoTriangle.
static_assert(kSetupChunkTriangles * (kMaxClippedVertices - 2) < kSetupsPerPart - 1, "a chunk's setups fit a part");
// The most parts a frame can have; the scene's triangle cap (kMaxSceneTriangles) keeps the chunks within it.
inline constexpr size_t kMaxSetupParts = size_t{1} << (32 - kSetupRefShift);
static_assert((kMaxSceneTriangles + kSetupChunkTriangles - 1) / kSetupChunkTriangles <= kMaxSetupParts,
              "a scene's chunks fit the parts");

// Where each part of a frame's setups lives. Reference r is part r >> 16, index r & 0xFFFF.
class SetupTable {
public:
    // Chunk k is part k: the front end's setups read in place.
    static SetupTable of_chunks(const std::vector<std::vector<TriangleSetup>>& chunks);
    static SetupTable of_chunks(std::vector<std::vector<TriangleSetup>>&&) = delete;  // would dangle
    // One list cut into parts of 2^16, so that reference i is setups[i].
    static SetupTable of_list(const std::vector<TriangleSetup>& setups);
    static SetupTable of_list(std::vector<TriangleSetup>&&) = delete;  // would dangle

    const TriangleSetup& operator[](uint32_t ref) const {
        return parts_[ref >> kSetupRefShift][ref & (kSetupsPerPart - 1)];
    }
    // Asks for every cache line of a setup without waiting for them: the tile loop reads setups the front end
    // wrote megabytes earlier.
    void prefetch(uint32_t ref) const {
        constexpr uintptr_t kLine = 64;
        const auto address = reinterpret_cast<uintptr_t>(&(*this)[ref]);
        for (uintptr_t line = address & ~(kLine - 1); line < address + sizeof(TriangleSetup); line += kLine)
            __builtin_prefetch(reinterpret_cast<const void*>(line));
    }
    size_t parts() const { return parts_.size(); }
    const TriangleSetup* part(size_t k) const { return parts_[k]; }
    uint32_t part_size(size_t k) const { return sizes_[k]; }
    static uint32_t ref(size_t part, uint32_t index) {
        return static_cast<uint32_t>(part << kSetupRefShift) | index;
    }

private:
    std::vector<const TriangleSetup*> parts_;
    std::vector<uint32_t> sizes_;
};

}  // namespace raster
