// Decoded texture images and their mip chains: the texels a textured material samples.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace raster {

// One level of a texture: width x height texels, row-major, row 0 the image's top row.
struct TextureLevel {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;

    const glm::vec3& at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
};

// A texture: level 0 is the image; levels 1.. are the mip chain, present only when built (build_mip_chain).
struct Texture {
    std::string path;  // for messages
    std::vector<TextureLevel> levels;
};

// Limits on a texture image, checked before it is decoded, so a hostile header cannot exhaust memory.
inline constexpr int kMaxTextureDimension = 16384;
inline constexpr uint64_t kMaxTextureTexels = uint64_t{1} << 25;  // 32 M texels: 384 MiB as float RGB

// Which of an image's channels a decoded texture holds.
enum class TextureChannels {
    colour,  // RGB; a grey image replicated to RGB
    alpha,   // the alpha channel in all three components, (a, a, a); 1 where the image has none
};

// Decodes an image (PNG, JPEG, TGA, BMP, PSD, GIF, HDR, PNM: whatever stb_image reads) into level 0.
// Colour space (docs/textures.md): an 8- or 16-bit texel's value is the float nearest its code over 255 or 65535
// (an HDR value is taken as it is), in the one space raster uses for every colour, so an unlit texture drawn one
// texel per pixel writes back its own bytes. Alpha, when asked for, is its code over the full scale likewise.
// Throws InputError naming `name` when the bytes are not an image stb_image reads or exceed the limits above.
Texture decode_texture(std::string_view bytes, const std::string& name,
                       TextureChannels channels = TextureChannels::colour);

// Whether the image has an alpha channel (grey + alpha or RGBA); false for bytes stb_image cannot read.
bool image_has_alpha(std::string_view bytes);

// Reads and decodes a texture file (at most 1 GiB). Throws InputError naming the file.
Texture load_texture(const std::filesystem::path& path);

// The next level down: max(1, floor(w / 2)) x max(1, floor(h / 2)) texels (the OpenGL and Vulkan sizes), each the
// area-weighted mean of the texels of `level` it covers: a texel of a w -> w' step spans w / w' source texels, the
// ones cut at its ends counting by the fraction inside, so every level keeps the image's mean.
TextureLevel downsample(const TextureLevel& level);

// Appends levels until the last is 1 x 1; does nothing when they are already there.
void build_mip_chain(Texture& texture);

// Levels a full chain of a w x h image has: 1 + floor(log2(max(w, h))).
int mip_level_count(int width, int height);

}  // namespace raster
