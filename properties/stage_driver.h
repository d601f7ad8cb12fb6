// Drives an implementation's stages on hand-made input: a frame (image, samples, snap bits, clip volume), clip-space
// triangles through clip, setup and rasterize, scenes through render(), and the frame's documented sample positions.
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "properties/implementation.h"
#include "raster/geometry/clip.h"
#include "raster/core/conventions.h"
#include "raster/frame/render.h"
#include "raster/scene/scene.h"
#include "raster/geometry/setup.h"
#include "raster/shading/shadow_maps.h"
#include "raster/rasterize/visibility_buffer.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {

// Where and how a property rasterizes. Generated frames have power-of-two sizes.
struct Frame {
    int width = 32;
    int height = 32;
    int samples = 1;
    SamplePattern pattern = SamplePattern::standard;
    int snap_bits = kDefaultSnapBits;
    ClipVolume volume{0.1f, 100.0f};

    int fixed_bits() const { return fixed_bits_for(snap_bits); }
    // Screen positions on the grid of 1/2^exact_bits() pixel have NDC coordinates that floats hold exactly
    // (|ndc| <= 1 in multiples of 2^-24), so a vertex made from one with a power-of-two w lands exactly there.
    int exact_bits() const;
};
std::ostream& operator<<(std::ostream& os, const Frame& frame);

// One triangle in clip space, in drawing order.
struct ClipTriangle {
    std::array<glm::vec4, 3> v;
};
std::ostream& operator<<(std::ostream& os, const ClipTriangle& triangle);

// The clip-space vertex that lands on `screen` (pixels, y down) at view depth w with reversed-Z depth `depth`:
// (ndc_x w, ndc_y w, depth w, w). Exact for positions on the frame's exact grid and power-of-two w.
glm::vec4 clip_from_screen(const Frame& frame, const glm::dvec2& screen, float w, float depth = 0.5f);

// NDC and screen position of a clip-space point (w > 0), in double, and the viewport mapping both ways
// (conventions.h: NDC (-1, +1) is screen (0, 0), y down).
glm::dvec2 ndc_of(const glm::dvec4& clip);
glm::dvec2 screen_of_ndc(const Frame& frame, const glm::dvec2& ndc);
glm::dvec2 ndc_of_screen(const Frame& frame, const glm::dvec2& screen);

// A sample of the frame at its documented position.
struct Sample {
    int x = 0, y = 0, s = 0;       // pixel and sample index
    size_t index = 0;              // in the visibility buffer
    reference::Point fixed;        // on the fixed-point grid
    glm::dvec2 screen;             // in pixels (exact)
};
std::vector<Sample> samples_of(const Frame& frame);

// "sample S of pixel (X, Y)", for failure messages.
std::string describe(const Sample& sample);

// The snapped screen vertex of a clip-space point, per conventions.h (the reference's computation).
reference::Point snapped(const Frame& frame, const glm::vec4& clip);

// Clips and sets up the triangles with the implementation's clip and setup stages; triangle i gets id i.
std::vector<TriangleSetup> set_up(const Implementation& impl, const Frame& frame,
                                  const std::vector<ClipTriangle>& triangles);

// Rasterizes setups with the implementation's sample positions on its backend: the reference_rasterize stage, or
// the tiled renderer's rasterize_tiled with the backend's SIMD, hierarchical Z and thread count.
VisibilityBuffer rasterize_setups(const Implementation& impl, const Frame& frame,
                                  const std::vector<TriangleSetup>& setups);

// set_up, then rasterize_setups: the triangles drawn in order into one visibility buffer.
VisibilityBuffer draw(const Implementation& impl, const Frame& frame, const std::vector<ClipTriangle>& triangles);

// For every sample, how many of the triangles cover it when each is drawn alone.
std::vector<int> coverage_counts(const Implementation& impl, const Frame& frame,
                                 const std::vector<ClipTriangle>& triangles);

// render() on the implementation's backend (renderer, SIMD, hierarchical Z, threads).
RenderResult render_with(const Implementation& impl, const Scene& scene);

// The scene's shadow maps, rendered by the shadow pass on the implementation's backend from the vertex stage's world
// positions (what a frame's shading reads).
ShadowMaps shadow_maps_with(const Implementation& impl, const Scene& scene, const std::vector<glm::vec3>& world_positions);

// How many times this thread has rasterized through rasterize_setups, render_with or shadow_maps_with: the registry's test uses it
// to check that exactly the properties registered as drawing ones draw.
size_t rasterizer_runs();

}  // namespace raster::properties
