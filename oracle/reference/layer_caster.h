// The oracle's transparent layers: per sample, every hit of the ray through it on a transparent surface, collected
// by an Embree intersection filter that records each hit and rejects it so that traversal goes on
// (docs/transparency.md). Which of them lie in front of the opaque surface, and in what order, is the comparison's to
// decide with its bounds (layer_check.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/ray_caster.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

struct LayerHit {
    uint32_t triangle = 0;
    glm::vec3 bary{0.0f};  // (1 - u - v, u, v) of the original triangle, Embree's
    float view_depth = 0;  // the ray's t (view z = -1)
};

// Per sample (visibility-buffer order), its hits nearest first: hits[first[i] .. first[i + 1]).
struct SampleLayers {
    std::vector<uint32_t> first;
    std::vector<LayerHit> hits;
    size_t count(size_t sample) const { return first[sample + 1] - first[sample]; }
    const LayerHit* of(size_t sample) const { return hits.data() + first[sample]; }
};

// Traces every sample of `scene` (width x height x samples, the positions of sample_positions.h) against the
// transparent surfaces only, within [near, far]. Empty (no `first`) when the scene has none. Throws OracleError
// when Embree fails. Deterministic for any thread count.
SampleLayers trace_layers(const Scene& scene, const OracleScene& geometry, const OracleOptions& options);

}  // namespace raster::oracle
