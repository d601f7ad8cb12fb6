// The organic bench mesh: a noise-displaced, jittered cube sphere that looks like a 3D scan.
#pragma once

#include <cstdint>

#include "tools/bench_mesh.h"

namespace raster::tools {

// A lumpy, potato-like closed surface in the style of a 3D scan: a cube sphere (every cube face an N x N grid,
// projected onto the sphere, so cells near the cube's corners are smaller), each vertex jittered along the sphere
// and pushed in or out by a multi-octave noise of its direction, stretched unevenly. Quads split along their
// shorter diagonal, as a remesher would. The surface is star-shaped around the origin.
struct OrganicParams {
    int cells_per_face_side = 80;     // 6 * 80 * 80 * 2 = 76,800 triangles
    uint64_t seed = 20240607;         // the noise's and the jitter's fixed seed
    double jitter = 0.35;             // tangential jitter, in cells
    double lump_amplitude = 0.32;     // radial displacement of the coarsest octave
    double lump_frequency = 1.1;      // of the coarsest octave, per unit of direction
    int octaves = 5;                  // the finest spans about three cells
    Vec3 stretch{1.25, 0.95, 1.0};    // uneven scale: an elongated blob
};

Mesh make_organic(const OrganicParams& params);

}  // namespace raster::tools
