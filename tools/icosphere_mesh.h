// The icosphere bench mesh: a subdivided icosahedron on the unit sphere.
#pragma once

#include "tools/bench_mesh.h"

namespace raster::tools {

// The icosahedron (12 vertices on the unit sphere), each of its 20 faces subdivided into 4 `subdivisions` times,
// new vertices projected onto the sphere. Normals are the positions (unit radius).
Mesh make_icosphere(int subdivisions);

}  // namespace raster::tools
