// The shadow pass: for each light that casts shadows, the six faces of its cube map rendered from the light, depth
// only, by the frame's own front end and raster backend (docs/shadows.md). Its output is the ShadowMaps that
// shading reads (shadow_maps.h).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "raster/frame/raster_backend.h"
#include "raster/shading/shadow_maps.h"
#include "raster/scene/scene.h"

namespace raster {

// The faces' near and far planes for a light: far is twice the largest distance (max norm) from the light to a
// vertex of the scene, near is far / 2^16 (and at least 2^-100); a light on every vertex gets far = 1. Surfaces
// nearer the light than `near` cast no shadow from it.
struct ShadowClipPlanes {
    float near = 0.0f, far = 0.0f;
};
ShadowClipPlanes shadow_clip_planes(const std::vector<glm::vec3>& world_positions, const glm::vec3& light);

// Renders a cube for every light of `scene` that casts shadows, from every opaque scene triangle (both faces;
// snapped at the default sub-pixel precision, one sample at each texel centre, full clipping, reversed-Z,
// fixed-point edges), with `world_positions` the vertex stage's world positions of the scene's vertices, on
// `threads` threads. Transparent triangles cast no shadow (docs/transparency.md).
ShadowMaps render_shadow_maps(const Scene& scene, const std::vector<glm::vec3>& world_positions,
                              const RasterBackend& backend, int threads);

}  // namespace raster
