// glTF materials as raster's Blinn-Phong materials (docs/gltf.md#materials): the base colour, its texture, the
// metallic-roughness factors mapped to diffuse, specular and exponent, and the alpha mode.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/gltf/gltf_warnings.h"
#include "raster/gltf/tiny_gltf_config.h"
#include "raster/scene/material.h"
#include "raster/texture/texture.h"

namespace raster {

// KHR_texture_transform on a texture: uv' = T R S uv (the extension's offset, rotation in radians and scale), in
// glTF's texture space, before raster turns v up.
struct GltfUvTransform {
    glm::dvec2 offset{0.0}, scale{1.0};
    double rotation = 0.0;
    glm::dvec2 apply(const glm::dvec2& uv) const;
};

struct GltfMaterial {
    Material material;
    // The base colour factor: it multiplies COLOR_0, which replaces a raster material's colour, so a primitive with
    // vertex colours carries their product.
    glm::vec3 color_factor{1.0f};
    // MASK with a base colour alpha below the cut-off: no texel's alpha can reach it, so every triangle is cut away.
    bool cut_away = false;
    // The base colour texture's KHR_texture_transform, applied to the primitives' texture coordinates as they are read.
    std::optional<GltfUvTransform> uv_transform;
};

// The model's materials, each read once and each image decoded once.
class GltfMaterials {
public:
    // `file` names the model in messages and in its embedded images' names.
    GltfMaterials(const tinygltf::Model& model, std::string file, GltfWarnings& warnings);

    // Material `index` of the model, or raster's default material for -1 (a primitive that names none).
    const GltfMaterial& at(int index, const std::string& use);

private:
    // The texture; with `reads_alpha` (BLEND, MASK) and an image that has alpha, its alpha decoded too.
    std::optional<TextureBinding> base_color_texture(const tinygltf::TextureInfo& info, const std::string& at,
                                                     bool reads_alpha, std::optional<GltfUvTransform>& uv_transform);
    // The image's channels decoded within the model's texel cap; null, with a warning that ends with `outcome`
    // (what becomes of the material), when they cannot be.
    std::shared_ptr<const Texture> decode(const std::string& encoded, const std::string& name, TextureChannels channels,
                                          int image, const std::string& outcome);
    // The extension's transform; nothing when it names a texture coordinate set other than 0 (then the caller
    // leaves the texture out, as for any other set).
    std::optional<GltfUvTransform> read_uv_transform(const tinygltf::Value& extension, const std::string& at) const;

    const tinygltf::Model& model_;
    std::string file_;
    GltfWarnings& warnings_;
    std::map<int, GltfMaterial> materials_;
    struct GltfImage {
        std::shared_ptr<const std::string> encoded;
        std::shared_ptr<const Texture> colour, alpha;  // alpha decoded only when a BLEND or MASK material reads it
        bool alpha_tried = false;                      // once, whether or not it decoded
    };
    std::map<int, GltfImage> images_;
    uint64_t decoded_texels_ = 0, encoded_bytes_ = 0;
};

// The most texels a model's images may decode to together (two of the largest texture raster reads).
inline constexpr uint64_t kMaxGltfTexels = uint64_t{1} << 26;

// The Blinn-Phong exponent for a glTF roughness: 2 / a^2 - 2 with a = roughness^2 (the usual match of the
// Beckmann lobe), at least 1 and at most 4096.
float exponent_for_roughness(double roughness);

}  // namespace raster
