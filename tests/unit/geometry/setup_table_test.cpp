// Setup references: a list's reference is its index across parts, a chunk's is its part and its index in it, and a
// chunk no part can hold is refused.
#include "raster/geometry/setup_table.h"

#include <stdexcept>

#include <gtest/gtest.h>


namespace raster {
namespace {

std::vector<TriangleSetup> numbered_setups(size_t count) {
    std::vector<TriangleSetup> setups(count);
    for (size_t i = 0; i < count; ++i) setups[i].triangle_id = static_cast<uint32_t>(i);
    return setups;
}

TEST(SetupTable, aListsReferenceIsItsIndexAcrossParts) {
    const std::vector<TriangleSetup> setups = numbered_setups(70000);
    const SetupTable table = SetupTable::of_list(setups);
    ASSERT_EQ(table.parts(), 2u);
    EXPECT_EQ(table.part_size(0), 65536u);
    EXPECT_EQ(table.part_size(1), 70000u - 65536u);
    for (uint32_t i = 0; i < setups.size(); ++i) ASSERT_EQ(&table[i], &setups[i]) << i;
}

TEST(SetupTable, aChunksReferenceIsItsPartAndItsIndexInIt) {
    const std::vector<std::vector<TriangleSetup>> chunks = {numbered_setups(3), {}, numbered_setups(5)};
    const SetupTable table = SetupTable::of_chunks(chunks);
    ASSERT_EQ(table.parts(), 3u);
    EXPECT_EQ(table.part_size(1), 0u);
    for (size_t part = 0; part < chunks.size(); ++part)
        for (uint32_t i = 0; i < chunks[part].size(); ++i) {
            const uint32_t ref = SetupTable::ref(part, i);
            EXPECT_EQ(ref, part * 65536 + i);
            EXPECT_EQ(&table[ref], &chunks[part][i]);
        }
}

TEST(SetupTable, refusesAChunkThatNoPartCanHold) {
    const std::vector<std::vector<TriangleSetup>> chunks = {numbered_setups(kSetupsPerPart)};
    EXPECT_THROW(SetupTable::of_chunks(chunks), std::length_error);
}

}  // namespace
}  // namespace raster
