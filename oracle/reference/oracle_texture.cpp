// The oracle's textures: decoding in double and the mean-over-footprint mip chain (oracle_texture.h).
#include "oracle/reference/oracle_texture.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace raster::oracle {

namespace {

void find_range(OracleTextureLevel& level) {
    level.min = level.max = level.texels.front();
    for (const glm::dvec3& t : level.texels) {
        level.min = glm::min(level.min, t);
        level.max = glm::max(level.max, t);
    }
}

// The length of [a, b) inside [c, c + 1).
double overlap(double a, double b, double c) { return std::max(0.0, std::min(b, c + 1.0) - std::max(a, c)); }

}  // namespace

OracleTexture load_oracle_texture(const std::string& path, OracleChannels channels) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("oracle: cannot open texture " + path);
    const std::string encoded((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    return decode_oracle_texture(encoded, path, channels);
}

OracleTexture decode_oracle_texture(const std::string& encoded, const std::string& path, OracleChannels which) {
    OracleTexture texture;
    texture.path = path;
    OracleTextureLevel level;
    int channels = 0;
    std::vector<double> values;
    const auto* bytes = reinterpret_cast<const stbi_uc*>(encoded.data());
    const int size = static_cast<int>(std::min<size_t>(encoded.size(), INT_MAX));
    if (stbi_is_hdr_from_memory(bytes, size)) {
        float* pixels = stbi_loadf_from_memory(bytes, size, &level.width, &level.height, &channels, 0);
        if (pixels) values.assign(pixels, pixels + static_cast<size_t>(level.width) * level.height * channels);
        stbi_image_free(pixels);
    } else if (stbi_is_16_bit_from_memory(bytes, size)) {
        stbi_us* pixels = stbi_load_16_from_memory(bytes, size, &level.width, &level.height, &channels, 0);
        if (pixels)
            for (size_t i = 0; i < static_cast<size_t>(level.width) * level.height * channels; ++i)
                values.push_back(pixels[i] / 65535.0);
        stbi_image_free(pixels);
    } else {
        stbi_uc* pixels = stbi_load_from_memory(bytes, size, &level.width, &level.height, &channels, 0);
        if (pixels)
            for (size_t i = 0; i < static_cast<size_t>(level.width) * level.height * channels; ++i)
                values.push_back(pixels[i] / 255.0);
        stbi_image_free(pixels);
    }
    if (values.empty()) throw std::runtime_error("oracle: cannot decode texture " + path);
    // Grey (and grey + alpha) is grey in every channel; alpha, when asked for, is the last of 2 or 4 channels.
    const bool has_alpha = channels == 2 || channels == 4;
    for (size_t i = 0; i < values.size(); i += channels) {
        const double r = values[i];
        if (which == OracleChannels::alpha) level.texels.push_back(glm::dvec3(has_alpha ? values[i + channels - 1] : 1.0));
        else level.texels.push_back(channels < 3 ? glm::dvec3(r) : glm::dvec3(r, values[i + 1], values[i + 2]));
    }
    find_range(level);
    texture.levels.push_back(std::move(level));
    while (texture.levels.back().width > 1 || texture.levels.back().height > 1)
        texture.levels.push_back(next_oracle_level(texture.levels.back()));
    return texture;
}

OracleTextureLevel next_oracle_level(const OracleTextureLevel& level) {
    OracleTextureLevel next;
    next.width = std::max(1, level.width / 2);
    next.height = std::max(1, level.height / 2);
    const double span_x = static_cast<double>(level.width) / next.width;
    const double span_y = static_cast<double>(level.height) / next.height;
    next.texels.assign(static_cast<size_t>(next.width) * next.height, glm::dvec3(0.0));
    // Every level-k texel adds its overlap with each footprint it meets; each footprint is then divided by its area.
    for (int y = 0; y < level.height; ++y) {
        for (int x = 0; x < level.width; ++x) {
            const int first_i = static_cast<int>(x / span_x), first_j = static_cast<int>(y / span_y);
            for (int j = first_j; j < next.height && j * span_y < y + 1; ++j) {
                const double wy = overlap(j * span_y, (j + 1) * span_y, y);
                for (int i = first_i; i < next.width && i * span_x < x + 1; ++i) {
                    const double w = wy * overlap(i * span_x, (i + 1) * span_x, x);
                    next.texels[static_cast<size_t>(j) * next.width + i] += w * level.texel(x, y);
                }
            }
        }
    }
    for (glm::dvec3& t : next.texels) t /= span_x * span_y;
    find_range(next);
    return next;
}

OracleTextures::OracleTextures(const Scene& scene) {
    for (const SceneMesh& mesh : scene.meshes) {
        for_each_material(mesh, [&](const Material& material) {
            if (!material.texture) return;
            const TextureBinding& binding = *material.texture;
            auto decode_into = [&](std::shared_ptr<const OracleTexture>& slot, OracleChannels channels) {
                if (slot) return;
                slot = std::make_shared<const OracleTexture>(binding.encoded
                                                                 ? decode_oracle_texture(*binding.encoded, binding.path, channels)
                                                                 : load_oracle_texture(binding.path, channels));
            };
            decode_into(by_path_[binding.path], OracleChannels::colour);
            if (binding.reads_alpha) decode_into(alpha_by_path_[binding.path], OracleChannels::alpha);
        });
    }
}

}  // namespace raster::oracle
