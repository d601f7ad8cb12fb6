// Binning setups to tiles: each setup's bounding box in tiles, minus the tiles an edge keeps entirely outside.
#include "raster/pipeline/tile_bins.h"

namespace raster {

TileBins bin_setups(const std::vector<TriangleSetup>& setups, const FrameParams& frame,
                    std::vector<std::vector<uint32_t>>& lists) {
    TileBins bins{(frame.width + kTileSize - 1) / kTileSize, (frame.height + kTileSize - 1) / kTileSize, lists};
    bins.setups.resize(static_cast<size_t>(bins.tiles_x) * bins.tiles_y);
    for (std::vector<uint32_t>& list : bins.setups) list.clear();
    for (uint32_t index = 0; index < setups.size(); ++index) {
        const TriangleSetup& t = setups[index];
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
                bins.setups[static_cast<size_t>(ty) * bins.tiles_x + tx].push_back(index);
            }
    }
    return bins;
}

}  // namespace raster
