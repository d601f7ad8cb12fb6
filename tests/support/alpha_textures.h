// Texture alpha for the tests that build scenes in code: an RGBA image as an uncompressed 32-bit TGA (which
// stb_image reads with its alpha), and a square facing the default camera textured by it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "raster/scene/scene.h"
#include "raster/texture/texture.h"
#include "tests/support/quad_meshes.h"

namespace raster::test_support {

using Rgba = std::array<uint8_t, 4>;

// A width x height TGA of `texels` (row 0 the image's top), each R, G, B, A.
inline std::string tga_rgba(int width, int height, const std::vector<Rgba>& texels) {
    std::string out(18, '\0');
    out[2] = 2;  // uncompressed true colour
    out[12] = static_cast<char>(width & 0xff), out[13] = static_cast<char>(width >> 8);
    out[14] = static_cast<char>(height & 0xff), out[15] = static_cast<char>(height >> 8);
    out[16] = 32;
    out[17] = 0x28;  // 8 alpha bits, row 0 at the top
    for (const Rgba& t : texels)
        for (const uint8_t c : {t[2], t[1], t[0], t[3]}) out.push_back(static_cast<char>(c));
    return out;
}

// facing_pane(depth, half) in white, its texture coordinates running from (0, 0) at the bottom left to (1, 1) at the
// top right, textured by `image` with nearest filtering; the image's alpha is read, and `cutoff` makes it a cut-out.
inline SceneMesh alpha_textured_pane(double depth, double half, const std::string& image, float opacity,
                                     std::optional<float> cutoff = std::nullopt) {
    SceneMesh mesh = facing_pane(depth, half, glm::vec3(1.0f), opacity);
    mutable_data(mesh).corner_uvs = {{{{0, 0}, {1, 0}, {1, 1}}}, {{{0, 0}, {1, 1}, {0, 1}}}};
    TextureBinding binding;
    binding.path = "pane.tga";
    binding.encoded = std::make_shared<const std::string>(image);
    binding.texture = std::make_shared<const Texture>(decode_texture(image, binding.path));
    binding.alpha_texture = std::make_shared<const Texture>(decode_texture(image, binding.path, TextureChannels::alpha));
    binding.reads_alpha = true;
    binding.filter = TextureFilter::nearest;
    mesh.material.texture = binding;
    mesh.material.alpha_cutoff = cutoff;
    return mesh;
}

}  // namespace raster::test_support
