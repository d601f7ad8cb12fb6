// The oracle's visibility buffer: per sample, the scene triangle Embree's ray hits (or none), Embree's
// barycentrics of it and the hit's view depth. Samples are stored pixel by pixel, row by row from the top.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/core/conventions.h"

namespace raster::oracle {

struct SampleBuffer {
    int width = 0, height = 0, samples = 0;
    std::vector<uint32_t> triangle;   // scene triangle id, or kNoTriangle
    std::vector<glm::vec3> bary;      // (1 - u - v, u, v) of the original triangle; 0 when empty
    std::vector<float> view_depth;    // the ray parameter t (the ray's direction has view z = -1); 0 when empty

    void resize(int w, int h, int s) {
        width = w;
        height = h;
        samples = s;
        const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(s);
        triangle.assign(n, kNoTriangle);
        bary.assign(n, glm::vec3(0.0f));
        view_depth.assign(n, 0.0f);
    }
    size_t index(int x, int y, int s) const { return sample_index(x, y, s, width, samples); }
    size_t size() const { return triangle.size(); }
};

}  // namespace raster::oracle
