// The oracle's textures: each image decoded on its own (its own stb_image copy) from the file the scene names or the
// bytes its scene file embeds, held in double, with its own mip chain, so no texel the oracle compares comes from
// raster's texture code.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster::oracle {

struct OracleTextureLevel {
    int width = 0, height = 0;
    std::vector<glm::dvec3> texels;  // row 0 is the image's top row
    glm::dvec3 min{0.0}, max{0.0};   // over the level, per channel
    const glm::dvec3& texel(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
};

// Every level of a texture (docs/textures.md): level 0 has the image's values, code / 255 (or / 65535), exactly;
// level k + 1 is max(1, floor(w / 2)) x max(1, floor(h / 2)) and each of its texels is the mean of level k over the
// texel's footprint, a rectangle of w / w' by h / h' level-k texels, texels cut by its sides counting by the part
// inside.
struct OracleTexture {
    std::string path;
    std::vector<OracleTextureLevel> levels;
};

// What an oracle texture holds of its image: the colour (grey replicated), or the alpha channel in all three
// components, code / full scale (1 where the image has no alpha).
enum class OracleChannels { colour, alpha };

// Decodes `path` (throws std::runtime_error when it cannot; raster loaded it, so that is a broken file system).
OracleTexture load_oracle_texture(const std::string& path, OracleChannels channels = OracleChannels::colour);
// Decodes an image's encoded bytes (a texture embedded in its scene file); `path` names it.
OracleTexture decode_oracle_texture(const std::string& encoded, const std::string& path,
                                    OracleChannels channels = OracleChannels::colour);

// The level below `level`, by the rule above.
OracleTextureLevel next_oracle_level(const OracleTextureLevel& level);

// The scene's textures, one per distinct image file, for the materials that have one; the alpha of those whose
// binding reads it, likewise.
class OracleTextures {
public:
    explicit OracleTextures(const Scene& scene);
    // The texture of a textured binding.
    const OracleTexture& of(const TextureBinding& binding) const { return *by_path_.at(binding.path); }
    // The alpha texture of a binding that reads alpha.
    const OracleTexture& alpha_of(const TextureBinding& binding) const { return *alpha_by_path_.at(binding.path); }

private:
    std::map<std::string, std::shared_ptr<const OracleTexture>> by_path_, alpha_by_path_;
};

}  // namespace raster::oracle
