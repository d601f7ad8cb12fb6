// Materials: Blinn-Phong coefficients, an optional texture with its sampler state, and the per-triangle parts
// (OBJ `usemtl`) that give one mesh several materials.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace raster {

// How a texture is looked up (docs/textures.md). Only trilinear and anisotropic read the mip chain.
enum class TextureFilter {
    nearest,      // the texel under the point, level 0 (magnified and minified alike: aliases)
    bilinear,     // the 2x2 texels around the point, level 0
    trilinear,    // bilinear in the two mip levels around the level of detail, blended (the default)
    anisotropic,  // trilinear taps along the footprint's major axis, up to max_anisotropy of them
};

// What a texture coordinate outside [0, 1] reads.
enum class TextureWrap {
    repeat,  // the texture tiles: u and u + 1 read the same texel
    clamp,   // the edge texel continues outwards
    mirror,  // the texture tiles, every other copy mirrored
};

struct Texture;  // raster/texture/texture.h: the decoded texels and their mip chain

// A material's texture: the image and how it is sampled. The image's value multiplies the base colour.
struct TextureBinding {
    std::shared_ptr<const Texture> texture;
    std::string path;  // the image file, as resolved by the loader (the oracle decodes it on its own)
    // The image's encoded bytes when it is not a file of its own (a glTF buffer or data URI), else null; `path`
    // then names it uniquely ("model.glb#/images/0") and the oracle decodes these bytes on its own.
    std::shared_ptr<const std::string> encoded;
    TextureFilter filter = TextureFilter::trilinear;
    TextureWrap wrap = TextureWrap::repeat;
    int max_anisotropy = 16;  // anisotropic only: most taps along the major axis, in [1, 64]
    // Whether the image's alpha multiplies the material's opacity (glTF BLEND and MASK; docs/transparency.md),
    // sampled as the colour is. Only for an image with an alpha channel; raster's copy of that channel is
    // `alpha_texture`, each texel (a, a, a) so that it is filtered by the colour's own code.
    bool reads_alpha = false;
    std::shared_ptr<const Texture> alpha_texture;
};

// How a texture is sampled: a binding's filter (or the render settings' override), wrap and anisotropy cap.
struct SamplerState {
    TextureFilter filter = TextureFilter::trilinear;
    TextureWrap wrap = TextureWrap::repeat;
    int max_anisotropy = 16;
};

// The binding's sampler, its filter replaced by `filter_override` when that is set.
inline SamplerState sampler_of(const TextureBinding& binding, const std::optional<TextureFilter>& filter_override = {}) {
    return {filter_override.value_or(binding.filter), binding.wrap, binding.max_anisotropy};
}

// Blinn-Phong coefficients, each RGB. The base colour multiplies ambient and diffuse; specular is the highlight's
// own colour. The base colour is the mesh's face colour, else its interpolated vertex colour, else `color`; a
// texture multiplies it.
struct Material {
    glm::vec3 color{1.0f};
    glm::vec3 ambient{0.1f};
    glm::vec3 diffuse{0.7f};
    glm::vec3 specular{0.2f};
    float exponent = 32.0f;
    float opacity = 1.0f;  // 1 opaque; below 1 the surface is blended over what lies behind it (docs/transparency.md)
    // A cut-out (glTF MASK) read only with a texture that reads alpha: a fragment whose opacity times the texture's
    // alpha is at least the cut-off is opaque (opacity 1), any other is dropped (opacity 0).
    std::optional<float> alpha_cutoff;
    std::optional<TextureBinding> texture;  // none for an untextured material: no texture memory, no texture work
    std::string name;                       // the MTL or scene name, for messages; may be empty
};

// Whether the material's surfaces go to the transparency pass: an opacity below 1, or a texture's alpha read.
inline bool is_blended(const Material& material) {
    return material.opacity < 1.0f || (material.texture && material.texture->reads_alpha);
}

// Triangles from `first_triangle` (local to the mesh) to the next part's first use `material` (OBJ `usemtl`).
struct MaterialPart {
    uint32_t first_triangle = 0;
    Material material;
};

const char* to_string(TextureFilter filter);
const char* to_string(TextureWrap wrap);
// Parse a filter or wrap name as the scene files and the CLI spell it; false when unknown.
bool parse_texture_filter(const std::string& name, TextureFilter& out);
bool parse_texture_wrap(const std::string& name, TextureWrap& out);

// Whether `filter` reads mip levels past level 0.
inline bool uses_mip_chain(TextureFilter filter) {
    return filter == TextureFilter::trilinear || filter == TextureFilter::anisotropic;
}

}  // namespace raster
