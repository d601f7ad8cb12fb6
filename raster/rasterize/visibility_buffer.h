// The seam between renderers and shading: per sample, which triangle is visible, where on it, and how far.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/core/conventions.h"
#include "raster/core/plane_allocator.h"

namespace raster {

// Both renderers (rasterizer and oracle) produce this; shading reads one, comparison reads two.
// Samples are stored pixel by pixel, row by row from the top, `samples` consecutive entries per pixel.
struct VisibilityBuffer {
    int width = 0;
    int height = 0;
    int samples = 0;
    Plane<uint32_t> triangle;    // scene triangle id, or kNoTriangle
    Plane<glm::vec3> bary;       // perspective-correct barycentrics w.r.t. the original triangle's vertices
    Plane<float> view_depth;     // distance along the view direction (-z in view space); 0 when empty

    // Sizes the planes for w x h pixels of s samples and marks every sample empty. Storage is reused when it fits.
    // Only `triangle` is cleared here; whoever fills the buffer writes bary and view_depth of every sample
    // (zero for empty ones), so a frame costs one pass over them, not two.
    void resize(int w, int h, int s) {
        width = w;
        height = h;
        samples = s;
        const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(s);
        triangle.assign(n, kNoTriangle);
        bary.resize(n);
        view_depth.resize(n);
    }
    size_t index(int x, int y, int s) const { return sample_index(x, y, s, width, samples); }
    size_t size() const { return triangle.size(); }
};

}  // namespace raster
