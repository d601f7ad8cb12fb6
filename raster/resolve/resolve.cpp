// Resolve: per-pixel shading of the visibility buffer (SSAA or MSAA), sample averaging and depth visualisation.
#include "raster/resolve/resolve.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "raster/core/parallel.h"
#include "raster/image/to_byte.h"

namespace raster {

PixelResolver::PixelResolver(const Shader& shader, const ResolveParams& params, int samples)
    : shader_(shader), params_(params), samples_(samples) {
    for (int c = 0; c < 3; ++c) background_[c] = to_byte(params.background[c]);
    background_[3] = 0;
}

void PixelResolver::write_covered(const glm::vec3& color, uint8_t* out) const {
    for (int c = 0; c < 3; ++c) out[c] = to_byte(color[c]);
    if (params_.alpha) out[3] = 255;
}

void PixelResolver::background_row(uint8_t* out, int count) const {
    if (count <= 0) return;
    background(out);
    const size_t total = static_cast<size_t>(count) * static_cast<size_t>(channels());
    for (size_t filled = static_cast<size_t>(channels()); filled < total;) {
        const size_t copied = std::min(filled, total - filled);
        std::memcpy(out + filled, out, copied);
        filled += copied;
    }
}

void ResolveBatch::clear() {
    uniform_triangle.clear();
    uniform_bary.clear();
    uniform_out.clear();
    mixed.clear();
    triangle.clear();
    bary.clear();
    weight.clear();
}

void PixelResolver::finish(ResolveBatch& batch) const {
    const size_t uniform = batch.uniform_triangle.size();
    batch.colors.resize(std::max(uniform, batch.triangle.size()));
    shader_.shade_many(batch.uniform_triangle.data(), batch.uniform_bary.data(), uniform, batch.colors.data());
    for (size_t j = 0; j < uniform; ++j) write_covered(batch.colors[j], batch.uniform_out[j]);
    shader_.shade_many(batch.triangle.data(), batch.bary.data(), batch.triangle.size(), batch.colors.data());
    size_t point = 0;
    for (const ResolveBatch::MixedPixel& pixel : batch.mixed) {
        write_mixed(&batch.colors[point], &batch.weight[point], pixel.points, pixel.covered, pixel.out);
        point += pixel.points;
    }
    batch.clear();
}

void PixelResolver::write_mixed(const glm::vec3* colors, const int* weight, uint32_t points, int covered,
                                uint8_t* out) const {
    glm::vec3 sum(0.0f);
    for (uint32_t k = 0; k < points; ++k) sum += static_cast<float>(weight[k]) * colors[k];
    glm::vec3 color;
    if (params_.alpha) color = sum / static_cast<float>(covered);
    else color = (sum + static_cast<float>(samples_ - covered) * params_.background) / static_cast<float>(samples_);
    for (int c = 0; c < 3; ++c) out[c] = to_byte(color[c]);
    if (params_.alpha) out[3] = to_byte(static_cast<float>(covered) / static_cast<float>(samples_));
}

void size_image(Image& image, int width, int height, int channels) {
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels.resize(static_cast<size_t>(width) * height * channels);
}

void resolve_image(const VisibilityBuffer& visibility, const PixelResolver& resolver, int threads, Image& image) {
    size_image(image, visibility.width, visibility.height, resolver.channels());
    parallel_for(static_cast<size_t>(visibility.height), threads, [&](size_t row) {
        const int y = static_cast<int>(row);
        thread_local ResolveBatch batch;
        batch.clear();  // nothing left from a row that threw part-way
        for (int x = 0; x < visibility.width; ++x) {
            const size_t first = visibility.index(x, y, 0);
            resolver.add(&visibility.triangle[first], &visibility.bary[first], image.at(x, y), batch);
        }
        resolver.finish(batch);
    });
}

}  // namespace raster
