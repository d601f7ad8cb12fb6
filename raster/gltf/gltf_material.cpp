// glTF materials as raster's Blinn-Phong materials (gltf_material.h).
#include "raster/gltf/gltf_material.h"

#include <algorithm>
#include <cmath>

#include "raster/core/errors.h"
#include "raster/gltf/gltf_model.h"
#include "raster/texture/texture.h"

namespace raster {
namespace {

constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kClampToEdge = 33071, kMirroredRepeat = 33648;  // and REPEAT, 10497, the default

glm::vec3 rgb(const std::vector<double>& values, const std::string& at, const std::string& file) {
    if (values.size() < 3) throw InputError(file, 0, 0, at + ": a colour needs at least 3 numbers");
    for (int c = 0; c < 3; ++c)
        if (!(values[c] >= 0.0 && values[c] <= 1.0))
            throw InputError(file, 0, 0, at + ": colour components are in [0, 1], got " + std::to_string(values[c]));
    return {static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2])};
}

double unit_factor(double value, const std::string& at, const std::string& file) {
    if (!(value >= 0.0 && value <= 1.0)) throw InputError(file, 0, 0, at + ": must be in [0, 1], got " + std::to_string(value));
    return value;
}

TextureWrap wrap_of(int mode) {
    return mode == kClampToEdge ? TextureWrap::clamp : mode == kMirroredRepeat ? TextureWrap::mirror : TextureWrap::repeat;
}

// NEAREST or LINEAR minification reads level 0 only; a mipmap filter, or none named, reads the chain.
TextureFilter filter_of(int min_filter, int mag_filter) {
    if (min_filter == kNearest) return mag_filter == kLinear ? TextureFilter::bilinear : TextureFilter::nearest;
    if (min_filter == kLinear) return TextureFilter::bilinear;
    return TextureFilter::trilinear;
}

}  // namespace

glm::dvec2 GltfUvTransform::apply(const glm::dvec2& uv) const {
    const glm::dvec2 scaled = scale * uv;
    const double c = std::cos(rotation), s = std::sin(rotation);
    // The extension's rotation matrix has columns (cos, sin) and (-sin, cos).
    return offset + glm::dvec2(c * scaled.x - s * scaled.y, s * scaled.x + c * scaled.y);
}

float exponent_for_roughness(double roughness) {
    const double a = roughness * roughness;
    if (a * a < 2.0 / 4098.0) return 4096.0f;
    return static_cast<float>(std::clamp(2.0 / (a * a) - 2.0, 1.0, 4096.0));
}

GltfMaterials::GltfMaterials(const tinygltf::Model& model, std::string file, GltfWarnings& warnings)
    : model_(model), file_(std::move(file)), warnings_(warnings) {}

std::optional<GltfUvTransform> GltfMaterials::read_uv_transform(const tinygltf::Value& extension,
                                                                const std::string& at) const {
    auto fail = [&](const std::string& key, const std::string& message) {
        throw InputError(file_, 0, 0, at + "/" + key + ": " + message);
    };
    auto number = [&](const tinygltf::Value& value, const std::string& key) {
        if (!value.IsNumber()) fail(key, "must be a number");
        const double n = value.GetNumberAsDouble();
        if (!std::isfinite(n) || std::fabs(n) > 1e30) fail(key, "must be a finite number up to 1e30, got " + std::to_string(n));
        return n;
    };
    auto pair = [&](const std::string& key, glm::dvec2& out) {
        if (!extension.Has(key)) return;
        const tinygltf::Value& value = extension.Get(key);
        if (!value.IsArray() || value.ArrayLen() != 2) fail(key, "must be an array of 2 numbers");
        out = {number(value.Get(0), key + "/0"), number(value.Get(1), key + "/1")};
    };
    if (!extension.IsObject()) throw InputError(file_, 0, 0, at + ": must be an object");
    if (extension.Has("texCoord")) {
        const tinygltf::Value& set = extension.Get("texCoord");
        if (!set.IsInt() || set.GetNumberAsInt() < 0) fail("texCoord", "must be a texture coordinate set's number");
        if (set.GetNumberAsInt() != 0) {
            warnings_.say(at + "/texCoord: reads TEXCOORD_" + std::to_string(set.GetNumberAsInt()) +
                          "; raster reads TEXCOORD_0 only, so the texture is left out");
            return std::nullopt;
        }
    }
    GltfUvTransform transform;
    pair("offset", transform.offset);
    pair("scale", transform.scale);
    if (extension.Has("rotation")) transform.rotation = number(extension.Get("rotation"), "rotation");
    return transform;
}

std::shared_ptr<const Texture> GltfMaterials::decode(const std::string& encoded, const std::string& name,
                                                     TextureChannels channels, int image, const std::string& outcome) {
    try {
        auto decoded = std::make_shared<const Texture>(decode_texture(encoded, name, channels));
        const TextureLevel& level = decoded->levels.front();
        decoded_texels_ += static_cast<uint64_t>(level.width) * static_cast<uint64_t>(level.height);
        if (decoded_texels_ > kMaxGltfTexels)
            throw InputError("the model's images hold more than " + std::to_string(kMaxGltfTexels) + " texels");
        return decoded;
    } catch (const InputError& e) {
        warnings_.say("/images/" + std::to_string(image) + (channels == TextureChannels::alpha ? "'s alpha" : "") +
                      " cannot be decoded (" + e.message() + ")" + outcome);
        return nullptr;
    }
}

std::optional<TextureBinding> GltfMaterials::base_color_texture(const tinygltf::TextureInfo& info, const std::string& at,
                                                                bool reads_alpha,
                                                                std::optional<GltfUvTransform>& uv_transform) {
    if (info.index < 0) return std::nullopt;
    if (static_cast<size_t>(info.index) >= model_.textures.size())
        throw InputError(file_, 0, 0, at + "/index: there is no texture " + std::to_string(info.index));
    if (info.texCoord != 0) {
        warnings_.say(at + ": reads TEXCOORD_" + std::to_string(info.texCoord) + "; raster reads TEXCOORD_0 only, so the texture is left out");
        return std::nullopt;
    }
    if (const auto extension = info.extensions.find("KHR_texture_transform"); extension != info.extensions.end()) {
        uv_transform = read_uv_transform(extension->second, at + "/extensions/KHR_texture_transform");
        if (!uv_transform) return std::nullopt;
    }
    const tinygltf::Texture& texture = model_.textures[static_cast<size_t>(info.index)];
    const std::string texture_at = "/textures/" + std::to_string(info.index);
    if (texture.source < 0) {
        warnings_.say(texture_at + " names no image (or only an extension's); the texture is left out");
        return std::nullopt;
    }
    if (static_cast<size_t>(texture.source) >= model_.images.size())
        throw InputError(file_, 0, 0, texture_at + "/source: there is no image " + std::to_string(texture.source));
    TextureBinding binding;
    binding.path = file_ + "#/images/" + std::to_string(texture.source);
    GltfImage& image = images_[texture.source];
    if (!image.encoded) {
        image.encoded = std::make_shared<const std::string>(gltf_image_bytes(model_, texture.source, file_));
        // Many images may name one buffer view: each holds its own copy, and the copies together are capped.
        encoded_bytes_ += image.encoded->size();
        if (encoded_bytes_ > kMaxGltfExternalBytes)
            throw InputError(file_, 0, 0, "/images/" + std::to_string(texture.source) + ": the model's images hold more than " +
                                              std::to_string(kMaxGltfExternalBytes) + " encoded bytes");
        if (!image.encoded->empty())
            image.colour = decode(*image.encoded, binding.path, TextureChannels::colour, texture.source,
                                  "; the textures using it are left out");
    }
    if (!image.colour) return std::nullopt;
    binding.texture = image.colour;
    binding.encoded = image.encoded;
    if (reads_alpha && image_has_alpha(*image.encoded)) {
        if (!image.alpha_tried) {
            image.alpha_tried = true;
            image.alpha = decode(*image.encoded, binding.path, TextureChannels::alpha, texture.source,
                                 "; BLEND and MASK use the base colour factor's alpha alone");
        }
        binding.reads_alpha = image.alpha != nullptr;
        binding.alpha_texture = image.alpha;
    }
    if (texture.sampler >= 0) {
        if (static_cast<size_t>(texture.sampler) >= model_.samplers.size())
            throw InputError(file_, 0, 0, texture_at + "/sampler: there is no sampler " + std::to_string(texture.sampler));
        const tinygltf::Sampler& sampler = model_.samplers[static_cast<size_t>(texture.sampler)];
        binding.filter = filter_of(sampler.minFilter, sampler.magFilter);
        binding.wrap = wrap_of(sampler.wrapS);
        if (sampler.wrapT != sampler.wrapS)
            warnings_.say("/samplers/" + std::to_string(texture.sampler) +
                          ": wrapS and wrapT differ; raster wraps both directions as wrapS says");
    }
    return binding;
}

const GltfMaterial& GltfMaterials::at(int index, const std::string& use) {
    if (const auto found = materials_.find(index); found != materials_.end()) return found->second;
    GltfMaterial out;
    if (index < 0) return materials_[index] = out;  // raster's default material (docs/gltf.md#materials)
    if (static_cast<size_t>(index) >= model_.materials.size())
        throw InputError(file_, 0, 0, use + ": there is no material " + std::to_string(index));
    const tinygltf::Material& m = model_.materials[static_cast<size_t>(index)];
    const std::string at = "/materials/" + std::to_string(index);
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const std::string pbr_at = at + "/pbrMetallicRoughness";
    out.color_factor = rgb(pbr.baseColorFactor, pbr_at + "/baseColorFactor", file_);
    const double alpha = pbr.baseColorFactor.size() > 3 ? unit_factor(pbr.baseColorFactor[3], pbr_at + "/baseColorFactor", file_) : 1.0;
    const double metallic = unit_factor(pbr.metallicFactor, pbr_at + "/metallicFactor", file_);
    const double roughness = unit_factor(pbr.roughnessFactor, pbr_at + "/roughnessFactor", file_);
    Material& material = out.material;
    material.name = m.name;
    material.color = out.color_factor;
    material.diffuse = glm::vec3(static_cast<float>(1.0 - metallic));
    material.specular = glm::vec3(static_cast<float>(0.04 * (1.0 - metallic))) + static_cast<float>(metallic) * out.color_factor;
    material.exponent = exponent_for_roughness(roughness);
    const bool blend = m.alphaMode == "BLEND", mask = m.alphaMode == "MASK";
    if (!blend && !mask && m.alphaMode != "OPAQUE" && !m.alphaMode.empty())
        throw InputError(file_, 0, 0, at + "/alphaMode: '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND");
    if (mask && !(std::isfinite(m.alphaCutoff) && m.alphaCutoff >= 0.0))
        throw InputError(file_, 0, 0, at + "/alphaCutoff: must be a finite number at least 0");
    // A cut-out whose factor is below its cut-off is cut everywhere: its texture is not read.
    if (mask) out.cut_away = alpha < m.alphaCutoff;
    if (!out.cut_away)
        material.texture = base_color_texture(pbr.baseColorTexture, pbr_at + "/baseColorTexture", blend || mask, out.uv_transform);
    // The alpha is the factor's times the texture's where the image has alpha (docs/gltf.md#materials); a cut-out
    // without texture alpha whose factor reaches the cut-off is opaque.
    const bool texture_alpha = material.texture && material.texture->reads_alpha;
    if (blend || (mask && texture_alpha)) material.opacity = static_cast<float>(alpha);
    if (mask && texture_alpha) material.alpha_cutoff = static_cast<float>(m.alphaCutoff);
    if (pbr.metallicRoughnessTexture.index >= 0 || m.normalTexture.index >= 0 || m.occlusionTexture.index >= 0 ||
        m.emissiveTexture.index >= 0)
        warnings_.say(at + ": metallic-roughness, normal, occlusion and emissive textures are not read");
    if (m.emissiveFactor.size() == 3 && (m.emissiveFactor[0] > 0 || m.emissiveFactor[1] > 0 || m.emissiveFactor[2] > 0))
        warnings_.say(at + ": emission is not rendered");
    return materials_[index] = out;
}

}  // namespace raster
