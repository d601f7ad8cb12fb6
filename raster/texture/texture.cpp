// Texture images: decoded through stb_image into float RGB (or an alpha channel), and their area-weighted mip chain.
#include "raster/texture/texture.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace raster {

namespace {

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

template <typename Code>
void fill_level(TextureLevel& level, const Code* pixels, int channels, float full_scale, TextureChannels which) {
    level.texels.resize(static_cast<size_t>(level.width) * level.height);
    const bool grey = channels < 3, has_alpha = channels == 2 || channels == 4;
    for (size_t i = 0; i < level.texels.size(); ++i) {
        const Code* p = pixels + i * channels;
        // A division, so that each texel is the float nearest code / full scale.
        if (which == TextureChannels::alpha)
            level.texels[i] = glm::vec3(has_alpha ? static_cast<float>(p[channels - 1]) / full_scale : 1.0f);
        else
            level.texels[i] = glm::vec3(p[0], grey ? p[0] : p[1], grey ? p[0] : p[2]) / full_scale;
    }
}

// The weights with which source texels [first, first + count) make destination texel `i` of a size -> target
// step along one axis: each source texel counts by the length of it inside [i s, (i + 1) s), s = size / target,
// over s.
struct AxisWeights {
    int first = 0;
    std::vector<double> weight;
};

std::vector<AxisWeights> axis_weights(int size, int target) {
    std::vector<AxisWeights> out(target);
    const double span = static_cast<double>(size) / target;
    for (int i = 0; i < target; ++i) {
        const double begin = i * span, end = (i + 1) * span;
        out[i].first = static_cast<int>(std::floor(begin));
        const int last = std::min(size - 1, static_cast<int>(std::ceil(end)) - 1);
        for (int s = out[i].first; s <= last; ++s)
            out[i].weight.push_back((std::min<double>(end, s + 1) - std::max<double>(begin, s)) / span);
    }
    return out;
}

}  // namespace

Texture decode_texture(std::string_view bytes, const std::string& name, TextureChannels which) {
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) throw InputError(name, 0, 0, "texture file over 2 GiB");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels))
        throw InputError(name, 0, 0, std::string("not an image raster can read: ") + stbi_failure_reason());
    if (width < 1 || height < 1 || width > kMaxTextureDimension || height > kMaxTextureDimension ||
        static_cast<uint64_t>(width) * height > kMaxTextureTexels)
        throw InputError(name, 0, 0, "texture is " + std::to_string(width) + " x " + std::to_string(height) +
                                         ", over the limit of " + std::to_string(kMaxTextureDimension) +
                                         " per side and " + std::to_string(kMaxTextureTexels) + " texels");
    Texture texture;
    texture.path = name;
    TextureLevel level;
    int w = 0, h = 0, n = 0;
    const char* failure = nullptr;
    if (stbi_is_hdr_from_memory(data, length)) {
        std::unique_ptr<float, StbFree> pixels(stbi_loadf_from_memory(data, length, &w, &h, &n, 0));
        if (!pixels) failure = stbi_failure_reason();
        else level.width = w, level.height = h, fill_level(level, pixels.get(), n, 1.0f, which);
    } else if (stbi_is_16_bit_from_memory(data, length)) {
        std::unique_ptr<stbi_us, StbFree> pixels(stbi_load_16_from_memory(data, length, &w, &h, &n, 0));
        if (!pixels) failure = stbi_failure_reason();
        else level.width = w, level.height = h, fill_level(level, pixels.get(), n, 65535.0f, which);
    } else {
        std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(data, length, &w, &h, &n, 0));
        if (!pixels) failure = stbi_failure_reason();
        else level.width = w, level.height = h, fill_level(level, pixels.get(), n, 255.0f, which);
    }
    if (failure) throw InputError(name, 0, 0, std::string("cannot decode the texture: ") + failure);
    for (const glm::vec3& texel : level.texels)
        if (!std::isfinite(texel.x) || !std::isfinite(texel.y) || !std::isfinite(texel.z))
            throw InputError(name, 0, 0, "the texture holds a value that is not a finite number");
    texture.levels.push_back(std::move(level));
    return texture;
}

bool image_has_alpha(std::string_view bytes) {
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) return false;
    int width = 0, height = 0, channels = 0;
    return stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width,
                                 &height, &channels) &&
           (channels == 2 || channels == 4);
}

Texture load_texture(const std::filesystem::path& path) {
    return decode_texture(read_file_bytes(path, uint64_t{1} << 30), path.string());
}

TextureLevel downsample(const TextureLevel& level) {
    TextureLevel out;
    out.width = std::max(1, level.width / 2);
    out.height = std::max(1, level.height / 2);
    const std::vector<AxisWeights> across = axis_weights(level.width, out.width);
    const std::vector<AxisWeights> down = axis_weights(level.height, out.height);
    out.texels.resize(static_cast<size_t>(out.width) * out.height);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            double sum[3] = {0.0, 0.0, 0.0};
            for (size_t j = 0; j < down[y].weight.size(); ++j) {
                for (size_t i = 0; i < across[x].weight.size(); ++i) {
                    const double w = down[y].weight[j] * across[x].weight[i];
                    const glm::vec3& t = level.at(across[x].first + static_cast<int>(i), down[y].first + static_cast<int>(j));
                    for (int c = 0; c < 3; ++c) sum[c] += w * t[c];
                }
            }
            out.texels[static_cast<size_t>(y) * out.width + x] =
                glm::vec3(static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2]));
        }
    }
    return out;
}

int mip_level_count(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

void build_mip_chain(Texture& texture) {
    if (texture.levels.empty()) return;
    const int count = mip_level_count(texture.levels[0].width, texture.levels[0].height);
    texture.levels.reserve(count);
    while (static_cast<int>(texture.levels.size()) < count) texture.levels.push_back(downsample(texture.levels.back()));
}

}  // namespace raster
