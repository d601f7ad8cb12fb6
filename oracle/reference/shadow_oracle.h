// The oracle's shadows: for each light that casts shadows, the ray-traced answer (an Embree ray from the light to
// the exact shading point) and what a correct shadow map may answer there (shadow_index.h over the footprint and
// reference depth of shadow_precision.h). A disagreement between the two is allowed only where the map's own limits
// can flip the test: an occluder's edge within the footprint, or a surface within the bias and the map's precision
// of the receiver's reference depth. Everywhere else the map must give the exact answer.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "oracle/reference/interval.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shadow_index.h"
#include "oracle/reference/shadow_rays.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

inline constexpr int kShadowSplits = 4;

enum class ShadowVerdict : uint8_t {
    lit,           // the map must say lit (visibility 1), as the ray does
    shadowed,      // the map must say shadowed (visibility 0), as the ray does
    open_edge,     // an occluder's edge crosses the footprint: any visibility
    open_depth,    // a surface is within the bias and precision of the reference depth: any visibility
    inconsistent,  // the ray and the exact footprint disagree (should never happen; counted, and any visibility)
};
inline constexpr int kShadowVerdictCount = 5;
const char* to_string(ShadowVerdict verdict);  // "lit", "shadowed", "open_edge", "open_depth", "inconsistent"
inline bool is_open(ShadowVerdict v) { return v >= ShadowVerdict::open_edge; }

struct LightVisibility {
    Interval allowed{1.0};  // every visibility a correct shadow map may give (1, 0 or [0, 1])
    bool exact_lit = true;  // the ray-traced answer
    ShadowVerdict verdict = ShadowVerdict::lit;
};

class ShadowOracle {
public:
    // Holds references to `scene` and `geometry` (oracle_scene of a lit scene), which must outlive it.
    ShadowOracle(const Scene& scene, const OracleScene& geometry, int threads);
    ~ShadowOracle();

    bool casts(size_t light) const { return light < index_of_light_.size() && index_of_light_[light] >= 0; }

    // Light `light` (one that casts shadows) at the shading point of triangle `receiver` with barycentrics
    // anywhere in the box `bary`; the ray goes to the point at the box's centre. Where the map's answer is open
    // over a box whose points spread over more than an eighth of a face pixel, the box is cut in quarters (up to
    // kShadowSplits times) and their answers joined: interval arithmetic forgets that the point and its reference
    // depth move together along the receiver's plane, and the quarters recover most of that.
    LightVisibility visibility(size_t light, uint32_t receiver, const Interval3& bary) const;
    // The ray-traced answer alone, at the point with barycentrics `bary` (exact) on triangle `receiver`.
    bool exact_lit(size_t light, uint32_t receiver, const glm::dvec3& bary) const;

    // A world-space box holding raster's float shading point for barycentrics in `bary` on triangle `id`.
    Interval3 position_at(uint32_t id, const Interval3& bary) const;

private:
    // What the map may answer over a box, joined over its pieces.
    struct MapAnswers {
        bool lit = false, shadowed = false, edge = false, depth = false;
        double lowest_reference = 0.0;  // the smallest reference depth met, and the largest point depth
        double deepest = 0.0;
    };
    void map_answers(const ShadowIndex& index, const glm::dvec3& light, uint32_t receiver, const Interval3& bary,
                     int splits, MapAnswers& out) const;
    // Whether an occluder's boundary edge crosses a footprint of the point (shadow_precision.h).
    bool edge_near(size_t light, uint32_t receiver, const Interval3& bary) const;

    const Scene& scene_;
    const OracleScene& geometry_;
    std::vector<int> index_of_light_;
    std::vector<std::unique_ptr<ShadowIndex>> indices_;
    std::unique_ptr<ShadowRays> rays_;
    std::vector<Interval3> face_normal_;  // per triangle: its unit normal, widened by raster's float error
};

}  // namespace raster::oracle
