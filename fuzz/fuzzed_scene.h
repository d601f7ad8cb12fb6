// Scenes built from fuzzer bytes with FuzzedDataProvider, shared by the raster and differential targets.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <string>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster::fuzz {

// How large a fuzzed scene may get.
struct FuzzedSceneLimits {
    int max_side = 128;            // image width and height, 1..max_side (half the draws stay at most 16)
    int max_grid_side = 4;         // grid patterns up to max_grid_side^2 samples; standard patterns 1..16
    int max_triangles = 64;        // 1..max_triangles independent triangles
    // Positions (vertices, eye, target, up, lights) also from raw float bits and the table of extremes. The lens
    // (field of view, near, far) always draws from them.
    bool extreme_coordinates = true;
    // Precision modes (edges, interpolation, depth format, clipping, hierarchical Z), drawn last so that an input
    // that runs out first keeps the defaults (and inputs saved before modes existed still replay unchanged).
    bool precision_modes = true;
};

// A float: a third from ordinary values in [low, high], the rest (with extreme_floats) from raw bits or from the
// table of extremes (signed zeros, FLT_MIN, subnormals, FLT_MAX, 2^24, 1e-6 and 1e9, infinities, NaN).
float fuzzed_float(FuzzedDataProvider& input, float low, float high, bool extreme_floats);

// The same with infinities and NaN replaced by the largest finite float of the same sign: scene coordinates must
// be finite (validate_scene), so non-finite draws would only waste inputs.
float fuzzed_finite_float(FuzzedDataProvider& input, float low, float high, bool extreme_floats);
glm::vec3 fuzzed_finite_vec3(FuzzedDataProvider& input, float low, float high, bool extreme_floats);

// A scene: settings (size, samples, pattern, MSAA, shading, culling, snap bits), a camera, up to two lights and
// one mesh of independent triangles. Not validated: callers run validate_scene and skip what it rejects.
Scene fuzzed_scene(FuzzedDataProvider& input, const FuzzedSceneLimits& limits);

// The scene as text with every float written out exactly (%a), for failure reports: settings, camera, lights and
// each mesh's triangles.
std::string describe_scene(const Scene& scene);

}  // namespace raster::fuzz
