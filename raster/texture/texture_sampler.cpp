// Texture lookups: wrap, nearest, bilinear, the level of detail, trilinear and anisotropic filtering.
#include "raster/texture/texture_sampler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace raster {

namespace {

// Texel coordinates are kept below this magnitude before they are made integers: far past any texture's size, so
// wrapping is unchanged, and inside long long.
constexpr double kTexelCoordinateLimit = 1.0e15;

double finite_or_zero(double value) {
    return std::isfinite(value) ? std::clamp(value, -kTexelCoordinateLimit, kTexelCoordinateLimit) : 0.0;
}

const glm::vec3& texel(const TextureLevel& level, long long x, long long y, TextureWrap wrap) {
    return level.at(wrap_texel(x, level.width, wrap), wrap_texel(y, level.height, wrap));
}

}  // namespace

int wrap_texel(long long i, int size, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::repeat: {
            const long long r = i % size;
            return static_cast<int>(r < 0 ? r + size : r);
        }
        case TextureWrap::clamp:
            return static_cast<int>(std::clamp<long long>(i, 0, size - 1));
        case TextureWrap::mirror: {
            const long long period = 2LL * size;
            long long r = i % period;
            if (r < 0) r += period;
            return static_cast<int>(r < size ? r : period - 1 - r);
        }
    }
    return 0;
}

glm::dvec2 texel_space(const TextureLevel& level, glm::vec2 uv) {
    return glm::dvec2(finite_or_zero(static_cast<double>(uv.x) * level.width),
                      finite_or_zero((1.0 - static_cast<double>(uv.y)) * level.height));
}

glm::vec3 sample_nearest(const TextureLevel& level, glm::vec2 uv, TextureWrap wrap) {
    const glm::dvec2 p = texel_space(level, uv);
    return texel(level, static_cast<long long>(std::floor(p.x)), static_cast<long long>(std::floor(p.y)), wrap);
}

glm::vec3 sample_bilinear(const TextureLevel& level, glm::vec2 uv, TextureWrap wrap) {
    const glm::dvec2 p = texel_space(level, uv) - 0.5;
    const double x0 = std::floor(p.x), y0 = std::floor(p.y);
    const float fx = static_cast<float>(p.x - x0), fy = static_cast<float>(p.y - y0);
    const auto x = static_cast<long long>(x0), y = static_cast<long long>(y0);
    const glm::vec3 top = glm::mix(texel(level, x, y, wrap), texel(level, x + 1, y, wrap), fx);
    const glm::vec3 bottom = glm::mix(texel(level, x, y + 1, wrap), texel(level, x + 1, y + 1, wrap), fx);
    return glm::mix(top, bottom, fy);
}

Footprint texture_footprint(const TextureLevel& level0, const SamplerState& binding, glm::vec2 duv_dx,
                            glm::vec2 duv_dy) {
    const glm::vec2 size(static_cast<float>(level0.width), static_cast<float>(level0.height));
    const float rho_x = glm::length(duv_dx * size), rho_y = glm::length(duv_dy * size);
    Footprint footprint;
    const float rho_max = std::max(rho_x, rho_y), rho_min = std::min(rho_x, rho_y);
    if (!std::isfinite(rho_max)) {
        footprint.lod = INFINITY;
        return footprint;
    }
    if (binding.filter != TextureFilter::anisotropic || !(rho_max > 0.0f)) {
        footprint.lod = std::log2(rho_max);
        return footprint;
    }
    const float ratio = rho_min > 0.0f ? rho_max / rho_min : INFINITY;
    footprint.taps = static_cast<int>(std::min<float>(std::ceil(ratio), static_cast<float>(binding.max_anisotropy)));
    footprint.taps = std::max(footprint.taps, 1);
    footprint.lod = std::log2(rho_max / static_cast<float>(footprint.taps));
    footprint.major_axis = rho_x >= rho_y ? duv_dx : duv_dy;
    return footprint;
}

glm::vec3 sample_trilinear(const Texture& texture, glm::vec2 uv, float lod, TextureWrap wrap) {
    const int last = static_cast<int>(texture.levels.size()) - 1;
    if (!(lod > 0.0f)) return sample_bilinear(texture.levels[0], uv, wrap);  // magnified, or NaN
    if (lod >= static_cast<float>(last)) return sample_bilinear(texture.levels[last], uv, wrap);
    const int level = static_cast<int>(lod);
    const float fraction = lod - static_cast<float>(level);
    const glm::vec3 fine = sample_bilinear(texture.levels[level], uv, wrap);
    if (fraction == 0.0f) return fine;
    return glm::mix(fine, sample_bilinear(texture.levels[level + 1], uv, wrap), fraction);
}

glm::vec3 sample_texture(const Texture& texture, const SamplerState& binding, glm::vec2 uv, glm::vec2 duv_dx,
                         glm::vec2 duv_dy) {
    switch (binding.filter) {
        case TextureFilter::nearest:
            return sample_nearest(texture.levels[0], uv, binding.wrap);
        case TextureFilter::bilinear:
            return sample_bilinear(texture.levels[0], uv, binding.wrap);
        case TextureFilter::trilinear:
            return sample_trilinear(texture, uv,
                                    texture_footprint(texture.levels[0], binding, duv_dx, duv_dy).lod, binding.wrap);
        case TextureFilter::anisotropic: {
            const Footprint footprint = texture_footprint(texture.levels[0], binding, duv_dx, duv_dy);
            if (footprint.taps == 1) return sample_trilinear(texture, uv, footprint.lod, binding.wrap);
            // Taps spread evenly over the major axis, centred on the point: offsets (k + 1/2) / taps - 1/2.
            glm::vec3 sum(0.0f);
            for (int k = 0; k < footprint.taps; ++k) {
                const float offset = (static_cast<float>(k) + 0.5f) / static_cast<float>(footprint.taps) - 0.5f;
                sum += sample_trilinear(texture, uv + offset * footprint.major_axis, footprint.lod, binding.wrap);
            }
            return sum / static_cast<float>(footprint.taps);
        }
    }
    return glm::vec3(0.0f);
}

}  // namespace raster
