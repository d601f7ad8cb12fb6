// Binning setups to tiles: each setup's bounding box in tiles, minus the tiles an edge keeps entirely outside.
#include "raster/rasterize/tile_bins.h"

#include "raster/core/parallel.h"

namespace raster {
namespace {

// Bins the setups of parts [first_part, end_part): the (tile, reference) pairs in draw order, then counted and placed
// tile by tile.
void bin_parts(const SetupTable& table, size_t first_part, size_t end_part, const FrameParams& frame, int tiles_x,
               size_t tiles, BinGroup& out) {
    out.touched.clear();
    for (size_t part = first_part; part < end_part; ++part) {
        const TriangleSetup* setups = table.part(part);
        for (uint32_t index = 0; index < table.part_size(part); ++index) {
            const TriangleSetup& t = setups[index];
            const uint32_t ref = SetupTable::ref(part, index);
            const int tx0 = t.min_x / kTileSize, tx1 = t.max_x / kTileSize;
            const int ty0 = t.min_y / kTileSize, ty1 = t.max_y / kTileSize;
            const bool single_tile = tx0 == tx1 && ty0 == ty1;
            for (int ty = ty0; ty <= ty1; ++ty)
                for (int tx = tx0; tx <= tx1; ++tx) {
                    if (!single_tile) {  // skip tiles of the bounding box that an edge keeps entirely outside
                        const int x0 = std::max(t.min_x, tx * kTileSize), x1 = std::min(t.max_x, tx * kTileSize + kTileSize - 1);
                        const int y0 = std::max(t.min_y, ty * kTileSize), y1 = std::min(t.max_y, ty * kTileSize + kTileSize - 1);
                        bool outside = false;
                        for (int i = 0; i < 3 && !outside; ++i)
                            outside = edge_range(t, i, x0, x1, y0, y1, frame.fixed_bits, frame.extent).max < 0;
                        if (outside) continue;
                    }
                    out.touched.emplace_back(static_cast<uint32_t>(ty * tiles_x + tx), ref);
                }
        }
    }
    // A counting sort by tile, stable, so each tile's references stay in draw order.
    out.first.assign(tiles + 1, 0);
    for (const auto& [tile, ref] : out.touched) ++out.first[tile + 1];
    for (size_t tile = 0; tile < tiles; ++tile) out.first[tile + 1] += out.first[tile];
    out.refs.resize(out.touched.size());
    for (const auto& [tile, ref] : out.touched) out.refs[out.first[tile]++] = ref;
    for (size_t tile = tiles; tile > 0; --tile) out.first[tile] = out.first[tile - 1];  // back to each tile's start
    out.first[0] = 0;
}

}  // namespace

TileBins bin_setups(const SetupTable& table, const FrameParams& frame, int threads, std::vector<BinGroup>& groups) {
    TileBins bins{(frame.width + kTileSize - 1) / kTileSize, (frame.height + kTileSize - 1) / kTileSize, groups};
    // Consecutive parts binned together: enough groups to keep the threads busy, few enough that the groups' tile
    // offsets (tiles + 1 each) stay small however many parts a huge mesh makes.
    const size_t count = std::min(table.parts(), kBinGroups);
    groups.resize(count);
    parallel_for(count, threads, [&](size_t group) {
        bin_parts(table, group * table.parts() / count, (group + 1) * table.parts() / count, frame, bins.tiles_x,
                  bins.tiles(), groups[group]);
    });
    return bins;
}

}  // namespace raster
