// Setup references and the bins over them: a list's reference is its index across parts, a chunk's is its part and
// index, binning keeps draw order part after part, and a scene of many chunks renders in draw order.
#include "raster/pipeline/setup_table.h"

#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "raster/pipeline/front_end.h"
#include "raster/pipeline/render.h"
#include "raster/pipeline/tile_bins.h"

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

// An n x n grid of quads over [-1, 1]^2 at z = 0, facing the default camera, in one colour.
SceneMesh grid(int n, const glm::vec3& colour, float opacity = 1.0f) {
    SceneMesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            mesh.data.positions.emplace_back(-1.0f + 2.0f * x / n, -1.0f + 2.0f * y / n, 0.0f);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t corner = static_cast<uint32_t>(y * (n + 1) + x), above = corner + static_cast<uint32_t>(n + 1);
            mesh.data.triangles.push_back({{corner, corner + 1, above + 1}});
            mesh.data.triangles.push_back({{corner, above + 1, above}});
        }
    mesh.material.color = colour;
    mesh.material.opacity = opacity;
    mesh.source = "inline";
    return mesh;
}

Scene unlit_scene(std::vector<SceneMesh> meshes) {
    Scene scene;
    scene.settings.width = scene.settings.height = 96;
    scene.settings.shading = ShadingMode::unlit;
    scene.meshes = std::move(meshes);
    return scene;
}

int byte_of(double v) { return static_cast<int>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5)); }

TEST(TileBins, listEachTilesSetupsInDrawOrderPartAfterPartAndEveryVisibleOne) {
    const Scene scene = unlit_scene({grid(50, glm::vec3(0.5f)), grid(50, glm::vec3(0.5f))});
    RenderResult result;
    const FrontEnd front = run_front_end(scene, RenderOptions{}, PipelineStages{}, result);
    const SetupTable table = SetupTable::of_chunks(result.workspace.setup_chunks);
    ASSERT_EQ(table.parts(), 3u);  // 10,000 triangles in chunks of 4096
    std::vector<PartBins> parts;
    const TileBins bins = bin_setups(table, front.frame, 2, parts);
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

// Two coincident grids across three chunks: every depth test between them is a tie, which keeps the earlier
// triangle, so the first grid's colour must cover the image on both paths.
TEST(TiledRender, aSceneOfManyChunksKeepsTheDrawOrderAcrossThem) {
    const glm::vec3 first(0.81f, 0.13f, 0.27f), second(0.12f, 0.83f, 0.31f);
    for (RasterPath path : {RasterPath::tiled, RasterPath::reference}) {
        const Scene scene = unlit_scene({grid(50, first), grid(50, second)});
        RenderOptions options;
        options.path = path;
        options.threads = 2;
        const RenderResult result = render(scene, options);
        EXPECT_EQ(result.stats.rasterized, 10000u);
        const uint8_t* centre = result.image.at(48, 48);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(centre[c], byte_of(first[c])) << "channel " << c;
        for (uint32_t id : result.visibility.triangle) {
            if (id == kNoTriangle) continue;
            ASSERT_LT(id, 5000u) << "the second grid won a tie";
        }
    }
}

// A transparent grid between two chunks' opaque triangles: the opaque chunks keep theirs, the pass gets the rest.
TEST(TiledRender, aTransparentMeshAmongChunksGivesTheReferenceBytes) {
    Scene scene = unlit_scene({grid(40, glm::vec3(0.2f, 0.5f, 0.7f)), grid(30, glm::vec3(0.9f, 0.4f, 0.1f), 0.5f),
                               grid(40, glm::vec3(0.6f, 0.6f, 0.2f))});
    scene.meshes[1].model[3] = glm::vec4(0.2f, 0.1f, 0.5f, 1.0f);  // in front, shifted
    scene.meshes[2].model[3] = glm::vec4(-0.3f, 0.2f, -0.5f, 1.0f);
    RenderOptions options;
    options.threads = 2;
    RenderOptions reference_options = options;
    reference_options.path = RasterPath::reference;
    const RenderResult tiled = render(scene, options), reference = render(scene, reference_options);
    EXPECT_GT(tiled.stats.transparent_fragments, 0u);
    EXPECT_EQ(tiled.stats.transparent_fragments, reference.stats.transparent_fragments);
    EXPECT_EQ(tiled.image.pixels, reference.image.pixels);
}

}  // namespace
}  // namespace raster
