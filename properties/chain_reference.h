// The independent reference the scene-file properties share: a scale-rotate-translate chain applied in double
// (Rodrigues' formula written here), and the documented camera of their 64-pixel frame, from (0, 0, 8) towards the
// origin with a 45-degree field of view, in double.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "properties/building_blocks.h"

namespace raster::properties {

inline constexpr int kChainFrameSide = 64;  // pixels per side of the frame

// The scene files' preamble for that frame and camera, unlit (the checks read coverage only).
extern const char* const kChainFramePreamble;

// The chain in double: scale, then the rotation about its axis, then the offset.
glm::dvec3 chain_moved(const ScaleRotateTranslate& chain, const glm::dvec3& object);

// The documented camera and viewport (conventions.h): view = world - eye, NDC = focal (x, y) / -z_view, screen
// x = (ndc_x + 1) W / 2, y = (1 - ndc_y) H / 2.
glm::dvec2 chain_frame_screen_of(const glm::dvec3& world);

// The signed distance of p from the line a -> b, positive on the triangle's inside for a counter-clockwise (on
// screen) vertex order.
double signed_distance(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p);

}  // namespace raster::properties
