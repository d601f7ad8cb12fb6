// The Embree oracle: ray casts a scene at exactly raster's sample positions, with the same camera, near/far planes
// and triangle ids, into the same VisibilityBuffer type, so a comparator can read the two side by side.
#pragma once

#include <cstddef>

#include "raster/scene/scene.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/pipeline/visibility_buffer.h"

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

// Renders `scene` into `out` (resized to width x height x samples):
// - rays start at the eye and run through each sample's screen position (raster's fixed-point sample positions,
//   raster::sample_screen_position), in view space with direction z = -1, so t is the view depth and the
//   t-range [near, far] clips exactly as the projection's planes do;
// - triangles are the scene's, in view space (geometry.view * model), UNSNAPPED: the snap is the comparator's
//   business; the triangle id is the scene's global id (raster's);
// - barycentrics are Embree's (1 - u - v, u, v) w.r.t. the original vertices, view depth is the hit's t.
// With back-face culling the triangles facing away from the eye are left out (front = counter-clockwise in NDC).
// `geometry` is the real vertex stage's output for this scene (its view and projection matrices are used).
// Throws OracleError when Embree fails. The result does not depend on the thread count.
OracleStats render_oracle(const Scene& scene, const TransformedScene& geometry, const OracleOptions& options,
                          VisibilityBuffer& out);

}  // namespace raster::oracle
