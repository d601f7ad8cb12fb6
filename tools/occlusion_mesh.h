// The occlusion bench mesh: stacked wavy sheets, each hidden behind the one before, for hierarchical Z.
#pragma once

#include "tools/bench_mesh.h"

namespace raster::tools {

// Stacked wavy sheets facing a camera at the origin looking down -z: layer k (0 nearest) lies around view
// distance first_distance + k * spacing and is sized to cover the whole field of view there (with a margin), so
// every pixel sees every layer. The sheets are written nearest first: drawn in file order, every layer after the
// first is hidden everywhere, the case hierarchical Z exists for (31 of 32 layers culled block by block); with
// farthest_first each layer would be nearer than all before it and nothing could be culled.
struct OcclusionParams {
    int layers = 32;
    int cells_per_side = 32;             // 32 * 32 * 2 = 2,048 triangles a layer
    double first_distance = 2.0;
    double spacing = 0.25;
    double half_fov_degrees = 20.0;      // the scene's fov / 2
    double coverage_margin = 1.2;        // sheet half-size / visible half-size at its distance
    double wave_amplitude = 0.05;        // < spacing / 2: neighbouring layers never touch
    double waves_per_sheet = 2.5;        // wavelengths across a sheet, the same apparent size for every layer
    bool farthest_first = false;         // true: the z-buffer's worst case, where hierarchical Z culls nothing
};

Mesh make_occlusion(const OcclusionParams& params);

}  // namespace raster::tools
