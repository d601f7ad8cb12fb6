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
    // MASK with a base colour alpha below the cut-off: no texture alpha is read, so every triangle is cut away.
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
    std::optional<TextureBinding> base_color_texture(const tinygltf::TextureInfo& info, const std::string& at,
                                                     std::optional<GltfUvTransform>& uv_transform);
    // The extension's transform; nothing when it names a texture coordinate set other than 0 (then the caller
    // leaves the texture out, as for any other set).
    std::optional<GltfUvTransform> read_uv_transform(const tinygltf::Value& extension, const std::string& at) const;

    const tinygltf::Model& model_;
    std::string file_;
    GltfWarnings& warnings_;
    std::map<int, GltfMaterial> materials_;
    std::map<int, std::pair<std::shared_ptr<const Texture>, std::shared_ptr<const std::string>>> images_;
    uint64_t decoded_texels_ = 0, encoded_bytes_ = 0;
};

// The most texels a model's images may decode to together (two of the largest texture raster reads).
inline constexpr uint64_t kMaxGltfTexels = uint64_t{1} << 26;

// The Blinn-Phong exponent for a glTF roughness: 2 / a^2 - 2 with a = roughness^2 (the usual match of the
// Beckmann lobe), at least 1 and at most 4096.
float exponent_for_roughness(double roughness);

}  // namespace raster
