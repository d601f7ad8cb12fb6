// Where samples are and which ray sees each: sample positions, the viewport mapping and camera rays, shared by the
// rasterizer (setup, rasterize) and the oracle so that both look through exactly the same points.
#pragma once

#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/geometry/sample_pattern.h"

namespace raster {

// A position on the fixed-point grid of 1/2^fixed_bits pixel (see conventions.h).
struct FixedPosition {
    int64_t x = 0, y = 0;
};

// Sample `sample` of pixel (px, py): the pixel's upper-left corner plus the sample's fixed-point offset.
inline FixedPosition sample_fixed_position(int px, int py, int sample, const FixedSampleOffsets& offsets,
                                           int fixed_bits) {
    return {(int64_t{px} << fixed_bits) + offsets.x[static_cast<size_t>(sample)],
            (int64_t{py} << fixed_bits) + offsets.y[static_cast<size_t>(sample)]};
}

// The same sample in screen pixels (exact: a fixed-point value scaled by a power of two).
glm::dvec2 sample_screen_position(int px, int py, int sample, const FixedSampleOffsets& offsets, int fixed_bits);

// The viewport mapping of conventions.h: NDC (-1, +1) is screen (0, 0), NDC (+1, -1) is (width, height).
inline glm::dvec2 screen_from_ndc(double ndc_x, double ndc_y, int width, int height) {
    return {(ndc_x + 1.0) * 0.5 * width, (1.0 - ndc_y) * 0.5 * height};
}

// Its inverse.
inline glm::dvec2 ndc_from_screen(const glm::dvec2& screen, int width, int height) {
    return {screen.x / (0.5 * width) - 1.0, 1.0 - screen.y / (0.5 * height)};
}

// The view-space direction of the camera ray through NDC point `ndc`: the ray starts at the eye (the view-space
// origin) and its direction has z = -1, so the ray parameter t IS the view depth, and the near and far planes
// are the planes t = near and t = far (not spheres). Solved in double from `projection` itself, so whatever
// projection the vertex stage used, the point t * direction projects back onto `ndc`.
glm::dvec3 view_ray_direction(const glm::mat4& projection, const glm::dvec2& ndc);

}  // namespace raster
