// Resolve: shades a visibility buffer (SSAA: every sample; MSAA: once per pixel per triangle) and averages the
// samples of each pixel into an 8-bit image.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/image/image.h"
#include "raster/shading/shade.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

struct ResolveParams {
    bool msaa = false;
    glm::vec3 background{0.0f};
    bool alpha = false;  // RGBA with alpha = covered fraction; RGB is then the mean of the covered samples only
};

// True when the pixel's n samples all hold the same value (one triangle, or all empty).
inline bool is_uniform(const uint32_t* samples, int n) {
    for (int s = 1; s < n; ++s)
        if (samples[s] != samples[0]) return false;
    return true;
}

// Pixels waiting to be shaded together (PixelResolver::add and finish), so that a shade_many call fills the
// lighting kernels' lanes across pixels. Two queues, each in the order its pixels were added.
struct ResolveBatch {
    // Pixels every sample of which shows one triangle, shaded once (PixelResolver::add_uniform): a point each.
    std::vector<uint32_t> uniform_triangle;
    std::vector<glm::vec3> uniform_bary;
    std::vector<uint8_t*> uniform_out;
    // Every other pixel: its `points` entries of the point arrays follow the previous pixel's.
    struct MixedPixel {
        uint8_t* out;
        uint32_t points;
        int covered;  // its covered samples
    };
    std::vector<MixedPixel> mixed;
    std::vector<uint32_t> triangle;
    std::vector<glm::vec3> bary;
    std::vector<int> weight;  // the samples each point's colour stands for
    std::vector<glm::vec3> colors;
    void clear();
};

// Colours pixels from their samples: shared by the full-frame resolve and the tiled renderer.
class PixelResolver {
public:
    // Once either queue of a batch holds this many points, the add or add_uniform that filled it shades the batch
    // (a pixel's points are queued whole, so the other queue may pass it by up to samples - 1): enough to fill the
    // kernels, few enough to stay in cache.
    static constexpr size_t kBatchPoints = 1024;

    PixelResolver(const Shader& shader, const ResolveParams& params, int samples);
    int channels() const { return params_.alpha ? 4 : 3; }
    // Resolves a pixel whose `samples` entries of `triangle` and `bary` are in pattern order into the channels()
    // bytes at `out`: an empty pixel at once, any other queued in `batch` (shaded at once if the batch is full).
    // Its bytes are final after finish(batch).
    void add(const uint32_t* triangle, const glm::vec3* bary, uint8_t* out, ResolveBatch& batch) const {
        add_with(triangle, out, batch, [bary](int s) { return bary[s]; });
    }
    // add with sample s's barycentrics given by bary_of(s), asked only for the samples the pixel is shaded at (a
    // renderer that has not worked them out yet computes only those).
    template <class BaryOf>
    void add_with(const uint32_t* triangle, uint8_t* out, ResolveBatch& batch, BaryOf&& bary_of) const {
        // A pixel whose samples all show the same triangle (or nothing) is the common case: one shade, no search.
        const bool uniform = is_uniform(triangle, samples_);
        if (uniform && triangle[0] == kNoTriangle) return background(out);
        if (uniform && shades_uniform_pixels_once()) return add_uniform(triangle[0], bary_of(0), out, batch);
        // The points to shade, in sample order, each with the number of samples its colour stands for: SSAA every
        // covered sample once; MSAA the first sample of each triangle, for all of that triangle's samples.
        const size_t first_point = batch.triangle.size();
        int covered = 0;
        for (int s = 0; s < samples_; ++s) {
            const uint32_t t = triangle[s];
            if (t == kNoTriangle) continue;
            ++covered;
            if (params_.msaa) {  // a triangle already among the pixel's points: one more sample for its weight
                size_t k = first_point;
                while (k < batch.triangle.size() && batch.triangle[k] != t) ++k;
                if (k < batch.triangle.size()) {
                    ++batch.weight[k];
                    continue;
                }
            }
            batch.triangle.push_back(t);
            batch.bary.push_back(bary_of(s));
            batch.weight.push_back(1);
        }
        batch.mixed.push_back({out, static_cast<uint32_t>(batch.triangle.size() - first_point), covered});
        if (batch.triangle.size() >= kBatchPoints) finish(batch);
    }
    // add for a pixel known to show `triangle` in every sample when shades_uniform_pixels_once (with MSAA or one
    // sample): shaded once at `bary`, the pattern's first sample.
    void add_uniform(uint32_t triangle, const glm::vec3& bary, uint8_t* out, ResolveBatch& batch) const {
        batch.uniform_triangle.push_back(triangle);
        batch.uniform_bary.push_back(bary);
        batch.uniform_out.push_back(out);
        if (batch.uniform_triangle.size() >= kBatchPoints) finish(batch);
    }
    // Shades every point in `batch` and writes its pixels; leaves it empty.
    void finish(ResolveBatch& batch) const;
    bool shades_uniform_pixels_once() const { return params_.msaa || samples_ == 1; }
    // A pixel no sample of which is covered.
    void background(uint8_t* out) const {
        for (int c = 0; c < 3; ++c) out[c] = background_[c];  // fixed counts: no library call per pixel
        if (params_.alpha) out[3] = 0;
    }
    // background() for `count` pixels side by side (a row of a tile nothing was drawn in): the same bytes, copied
    // in doubling blocks instead of written a channel at a time.
    void background_row(uint8_t* out, int count) const;

private:
    // A shaded colour into a pixel every sample of which it covers.
    void write_covered(const glm::vec3& color, uint8_t* out) const;
    // The weighted mean of a pixel's `points` colours and its uncovered samples' background.
    void write_mixed(const glm::vec3* colors, const int* weight, uint32_t points, int covered, uint8_t* out) const;
    const Shader& shader_;
    ResolveParams params_;
    int samples_;
    uint8_t background_[4];
};

// Sizes `image` for width x height pixels of `channels` bytes, reusing its storage when it fits.
void size_image(Image& image, int width, int height, int channels);

// The colour image. Uncovered samples take the background colour (or, with alpha, no part in the colour).
// MSAA shades each triangle in a pixel once, at the first of its samples in pattern order (always inside the
// triangle, so no extrapolation), weighted by how many samples it covers.
// `image` is resized (its storage reused when it fits) and every pixel written, rows in parallel on `threads`
// threads. The resolver's sample count must be the buffer's.
void resolve_image(const VisibilityBuffer& visibility, const PixelResolver& resolver, int threads, Image& image);

}  // namespace raster
