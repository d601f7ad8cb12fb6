// The transparent layers' check (docs/transparency.md): per sample, which of the oracle's transparent hits raster
// must composite in front of the opaque surface, in which order, and where the precision model leaves that open:
// a layer's edge within the radius of the sample (it may or may not cover it; a triangle Embree missed is found
// from a grid of the transparent polygons; a hit Embree reports outside the exact triangle, a triangle it misses
// inside, and a culled one whose facing is uncertain are open too), a layer's depth within the tolerance of the opaque surface's (the depth
// test may go either way), or two layers' depths within each other's (sorted: their order may go either way).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "oracle/reference/layer_caster.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_buffer.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

enum class LayerOpen : uint8_t { none, edge, depth, order };
inline constexpr int kLayerOpenCount = 4;
const char* to_string(LayerOpen open);  // "none", "edge", "depth", "order"

struct LayerVerdicts {
    std::vector<LayerOpen> open;      // per sample: the first reason found, or none
    std::vector<uint8_t> in_front;    // per hit of SampleLayers: 1 where raster must composite it
};

struct LayerCheckInputs {
    const Scene* scene = nullptr;
    const SampleLayers* layers = nullptr;
    const SampleBuffer* oracle = nullptr;  // the opaque surfaces
    const ReferenceGeometry* reference = nullptr;
    std::vector<uint32_t> transparent;     // every transparent triangle (culled ones too), for the near misses
    std::vector<glm::dvec2> offsets;
    int threads = 0;
};

// Deterministic for any thread count.
LayerVerdicts check_layers(const LayerCheckInputs& inputs);

// Whether raster's and Embree's view depths of triangles a and b at `screen` can order either way: the exact depths
// within the sum of both triangles' agreement tolerances (sample_classifier.h), or either unbounded.
bool view_depth_tie(const ReferenceGeometry& reference, uint32_t a, double a_depth, uint32_t b, double b_depth,
                    const glm::dvec2& screen);

}  // namespace raster::oracle
