// What the comparator reads of raster's output, as plain views of memory raster owns: its per-sample visibility
// (the production renderer writes it when asked) and its image as decoded from the file bytes it wrote.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace raster::oracle {

// Samples pixel by pixel, row by row from the top, `samples` consecutive entries per pixel.
struct RasterSamples {
    int width = 0, height = 0, samples = 0;
    const uint32_t* triangle = nullptr;  // scene triangle id, or kNoTriangle
    const glm::vec3* bary = nullptr;     // barycentrics of the original triangle
    const float* view_depth = nullptr;
    size_t size() const { return static_cast<size_t>(width) * height * samples; }
};

// Row-major, top row first, `channels` bytes per pixel.
struct RasterPixels {
    int width = 0, height = 0, channels = 0;
    const uint8_t* pixels = nullptr;
    const uint8_t* at(int x, int y) const { return pixels + (static_cast<size_t>(y) * width + x) * channels; }
};

}  // namespace raster::oracle
