// Binning: each tile's setups in draw order group after group, every one inside the setup's box, and every sample
// the reference rasterizer gives a triangle binned to its tile.
#include "raster/rasterize/tile_bins.h"

#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "raster/geometry/front_end.h"
#include "raster/frame/render.h"
#include "raster/geometry/sample_pattern.h"
#include "tests/support/quad_meshes.h"

namespace raster {
namespace {

TEST(TileBins, listEachTilesSetupsInDrawOrderGroupAfterGroupAndEveryVisibleOne) {
    const Scene scene = test_support::unlit_scene({test_support::grid_mesh(50, glm::vec3(0.5f)), test_support::grid_mesh(50, glm::vec3(0.5f))});
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const FrameParams frame = frame_params_for(scene, sample_offsets(1, SamplePattern::standard), 0);
    FrontEndSetups front_end;
    set_up_triangles_into(geometry, frame, false, {}, front_end);
    const SetupTable table = SetupTable::of_chunks(front_end.setup_chunks);
    ASSERT_EQ(table.parts(), 3u);  // 10,000 triangles in chunks of 4096
    std::vector<BinGroup> groups;
    const TileBins bins = bin_setups(table, frame, 2, groups);
    std::set<std::pair<size_t, uint32_t>> binned;  // (tile, scene triangle)
    for (size_t tile = 0; tile < bins.tiles(); ++tile) {
        const int tile_x = static_cast<int>(tile % bins.tiles_x) * kTileSize;
        const int tile_y = static_cast<int>(tile / bins.tiles_x) * kTileSize;
        int64_t previous = -1;
        bins.each_in_tile(tile, [&](uint32_t ref) {
            const TriangleSetup& t = table[ref];
            EXPECT_GT(static_cast<int64_t>(t.triangle_id), previous) << "tile " << tile;  // one setup per triangle
            previous = t.triangle_id;
            EXPECT_TRUE(t.max_x >= tile_x && t.min_x < tile_x + kTileSize && t.max_y >= tile_y &&
                        t.min_y < tile_y + kTileSize)
                << "setup of triangle " << t.triangle_id << " binned to tile " << tile << ", which its box misses";
            binned.emplace(tile, t.triangle_id);
        });
        EXPECT_EQ(bins.tile_empty(tile), previous == -1);
    }
    // Every sample the reference rasterizer gives a triangle has that triangle binned to the sample's tile.
    RenderOptions reference;
    reference.path = RasterPath::reference;
    const RenderResult drawn = render(scene, reference);
    size_t checked = 0;
    for (int py = 0; py < scene.settings.height; ++py)
        for (int px = 0; px < scene.settings.width; ++px) {
            const uint32_t id = drawn.visibility.triangle[drawn.visibility.index(px, py, 0)];
            if (id == kNoTriangle) continue;
            const size_t tile = static_cast<size_t>(py / kTileSize * bins.tiles_x + px / kTileSize);
            EXPECT_EQ(binned.count({tile, id}), 1u) << "triangle " << id << " covers (" << px << ", " << py << ")";
            ++checked;
        }
    EXPECT_GT(checked, 1000u);
}

}  // namespace
}  // namespace raster
