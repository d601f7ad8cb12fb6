// The Embree oracle's visibility: one ray per sample through the documented sample positions (sample_positions.h)
// from the oracle's own camera (camera.h), against the scene's triangles in view space, unsnapped. Embree answers
// which triangle a ray hits and where; everything else is the oracle's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "oracle/reference/sample_buffer.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// robust: RTC_SCENE_FLAG_ROBUST, Embree's watertight triangle test (the default).
// fast: no flag, Embree's faster and less careful traversal; for quick looks, not for verdicts.
enum class OracleMode { robust, fast };
const char* to_string(OracleMode mode);

struct OracleOptions {
    OracleMode mode = OracleMode::robust;
    int threads = 0;  // 0 = all cores; the output is the same for any value
};

struct OracleStats {
    size_t triangles = 0;  // triangles handed to Embree (after back-face culling, when the scene asks for it)
    double ms_build = 0;   // device, geometry and BVH
    double ms_trace = 0;   // one ray per sample
};

// Which surfaces a caster traces: the opaque ones (render_oracle: what the depth test keeps) or the transparent
// ones (layer_caster.h: every hit along the ray), by each triangle's material as the oracle reads it (layered_material).
enum class Surfaces { opaque, transparent };

// The scene triangles a caster hands Embree: those of `surfaces`, with finite view-space vertices and, when the
// scene culls back faces, facing the eye (front = counter-clockwise in NDC, decided exactly from the view-space
// vertices).
std::vector<uint32_t> traced_triangles(const Scene& scene, const OracleScene& geometry, Surfaces surfaces);

// Renders the visibility of `scene`'s opaque surfaces into `out` (resized to width x height x samples):
// - rays start at the eye and run through each sample's screen position, in view space with direction z = -1, so
//   t is the view depth and the t-range [near, far] clips exactly as the near and far planes do;
// - triangles are geometry's view-space vertices rounded to float, with their scene ids;
// - barycentrics are Embree's (1 - u - v, u, v) w.r.t. the original vertices, view depth is the hit's t.
// Transparent surfaces are not traced here (layer_caster.h). Throws OracleError when Embree fails. The result does not depend
// on the thread count.
OracleStats render_oracle(const Scene& scene, const OracleScene& geometry, const OracleOptions& options,
                          SampleBuffer& out);

}  // namespace raster::oracle
