// Shading: the lighting of the shading mode evaluated per face (flat), per vertex (Gouraud) or per sample, with
// textures and shadow visibility applied per sample.
#include "raster/shading/shade.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raster/shading/stylized_lighting.h"
#include "raster/shading/shadow_maps.h"
#include "raster/texture/texture_sampler.h"

namespace raster {

namespace {

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

bool any_mesh_has_parts(const Scene& scene) {
    return std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const SceneMesh& m) { return !m.parts.empty(); });
}

}  // namespace

Shader::Shader(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows)
    : scene_(scene), geometry_(geometry), mode_(scene.settings.shading) {
    specular_model_ = mode_ == ShadingMode::phong ? SpecularModel::phong : SpecularModel::blinn;
    lights_in_batches_ = mode_ == ShadingMode::phong || mode_ == ShadingMode::blinn_phong;
    if (any_mesh_has_parts(scene)) {
        triangle_material_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const uint32_t mesh = geometry.triangle_mesh[tri];
            triangle_material_[tri] = &material_of(scene.meshes[mesh], tri - geometry.mesh_first_triangle[mesh]);
        }
    }
    const bool textured = has_textures(scene);
    if (textured) textures_ = TextureLookup(scene, geometry);
    if (shadows && !shadows->empty() && mode_ != ShadingMode::unlit) {
        shadows_ = shadows;
        for (size_t light = 0; light < scene.lights.size(); ++light) {
            if (shadows->casts(light)) shadowed_lights_.push_back(light);
            else unshadowed_lights_.push_back(scene.lights[light]);
        }
        if (mode_ == ShadingMode::flat || mode_ == ShadingMode::gouraud)
            terms_stride_ = 1 + static_cast<int>(shadowed_lights_.size());
        face_normal_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec3& a = geometry.world_position[v.v[0]];
            face_normal_[tri] = glm::cross(geometry.world_position[v.v[1]] - a, geometry.world_position[v.v[2]] - a);
        }
    }
    const size_t stride = static_cast<size_t>(terms_stride_);
    if (mode_ == ShadingMode::gouraud) {
        auto light_vertex = [&](uint32_t vertex, const Material& material, LightingTerms* out) {
            lit_terms(geometry.world_position[vertex], geometry.world_normal[vertex], material, out);
        };
        if (!triangle_material_.empty()) {
            // A vertex between two materials is lit once for each: the terms are kept per triangle corner.
            vertex_terms_.resize(3 * geometry.triangles.size() * stride);
            for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri)
                for (int k = 0; k < 3; ++k)
                    light_vertex(geometry.triangles[tri].v[k], *triangle_material_[tri],
                                 &vertex_terms_[(3 * tri + k) * stride]);
        } else {
            vertex_terms_.resize(geometry.clip.size() * stride);
            for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
                const uint32_t first = geometry.mesh_first_vertex[mesh];
                const size_t count = scene.meshes[mesh].data.positions.size();
                for (size_t i = first; i < first + count; ++i)
                    light_vertex(static_cast<uint32_t>(i), scene.meshes[mesh].material, &vertex_terms_[i * stride]);
            }
        }
        if (!textured && !shadows_) {
            // Nothing varies per sample but the weights: each corner's final colour once per frame, as shade_point
            // forms it, so a sample is three products and two sums.
            corner_color_.resize(3 * geometry.triangles.size());
            for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri)
                for (int k = 0; k < 3; ++k) {
                    glm::vec3 corner_bary(0.0f);
                    corner_bary[k] = 1.0f;
                    const LightingTerms& terms = *corner_terms(tri, k);
                    corner_color_[3 * tri + k] = base_color(tri, corner_bary) * terms.diffuse + terms.specular;
                }
        }
    } else if (mode_ == ShadingMode::flat) {
        const glm::vec3 centroid_bary(1.0f / 3.0f);
        const bool per_face_terms = textured || shadows_;
        if (!per_face_terms) face_color_.resize(geometry.triangles.size());
        else face_terms_.resize(geometry.triangles.size() * stride);
        std::vector<LightingTerms> terms(stride);
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec3& a = geometry.world_position[v.v[0]];
            const glm::vec3& b = geometry.world_position[v.v[1]];
            const glm::vec3& c = geometry.world_position[v.v[2]];
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            const glm::vec3 normal = unit_or_zero(glm::cross(b - a, c - a));
            lit_terms(centroid, normal, material(tri), terms.data());
            const glm::vec3 base = base_color(tri, centroid_bary);
            if (!per_face_terms) face_color_[tri] = base * terms[0].diffuse + terms[0].specular;
            else
                for (size_t k = 0; k < stride; ++k)
                    face_terms_[tri * stride + k] = {base * terms[k].diffuse, terms[k].specular};
        }
    }
}

void Shader::lit_terms(const glm::vec3& position, const glm::vec3& normal, const Material& material,
                       LightingTerms* out) const {
    const glm::vec3 to_eye = unit_or_zero(scene_.camera.eye - position);
    if (terms_stride_ == 1) {
        out[0] = evaluate_lighting(position, normal, to_eye, material, scene_.lights, scene_.settings.ambient_light,
                           SpecularModel::blinn, nullptr);
        return;
    }
    out[0] = evaluate_lighting(position, normal, to_eye, material, unshadowed_lights_, scene_.settings.ambient_light,
                       SpecularModel::blinn, nullptr);
    for (size_t k = 0; k < shadowed_lights_.size(); ++k)
        out[1 + k] = evaluate_lighting(position, normal, to_eye, material, {scene_.lights[shadowed_lights_[k]]},
                               glm::vec3(0.0f), SpecularModel::blinn, nullptr);
}

LightingTerms Shader::combined(const LightingTerms* terms, const float* visibility) const {
    LightingTerms out = terms[0];
    if (!visibility) return out;
    for (size_t k = 0; k < shadowed_lights_.size(); ++k) {
        const float visible = visibility[shadowed_lights_[k]];
        out.diffuse += terms[1 + k].diffuse * visible;
        out.specular += terms[1 + k].specular * visible;
    }
    return out;
}

const Material& Shader::material(uint32_t triangle) const {
    if (!triangle_material_.empty()) return *triangle_material_[triangle];
    return scene_.meshes[geometry_.triangle_mesh[triangle]].material;
}

const LightingTerms* Shader::corner_terms(uint32_t triangle, int corner) const {
    const size_t stride = static_cast<size_t>(terms_stride_);
    if (!triangle_material_.empty()) return &vertex_terms_[(3 * triangle + corner) * stride];
    return &vertex_terms_[geometry_.triangles[triangle].v[corner] * stride];
}

const float* Shader::visibility_at(uint32_t triangle, const glm::vec3& bary) const {
    if (!shadows_) return nullptr;
    thread_local std::vector<float> visibility;
    visibility.assign(scene_.lights.size(), 1.0f);
    const TriangleIndices& v = geometry_.triangles[triangle];
    glm::vec3 position(0.0f);
    for (int i = 0; i < 3; ++i) position += bary[i] * geometry_.world_position[v.v[i]];
    shadow_visibility(triangle, position, visibility.data(), 1);
    return visibility.data();
}

void Shader::shadow_visibility(uint32_t triangle, const glm::vec3& position, float* out, size_t stride) const {
    for (size_t light : shadowed_lights_)
        out[light * stride] = shadows_->visibility(light, position, face_normal_[triangle]);
}

glm::vec3 Shader::base_color(uint32_t triangle, const glm::vec3& bary) const {
    const uint32_t mesh_index = geometry_.triangle_mesh[triangle];
    const MeshData& mesh = scene_.meshes[mesh_index].data;
    const uint32_t local = triangle - geometry_.mesh_first_triangle[mesh_index];
    if (!mesh.face_colors.empty()) return mesh.face_colors[local];
    if (!mesh.colors.empty()) {
        const TriangleIndices& v = mesh.triangles[local];
        return bary.x * mesh.colors[v.v[0]] + bary.y * mesh.colors[v.v[1]] + bary.z * mesh.colors[v.v[2]];
    }
    return material(triangle).color;
}

bool Shader::base_varies(uint32_t triangle) const {
    const MeshData& mesh = scene_.meshes[geometry_.triangle_mesh[triangle]].data;
    return mesh.face_colors.empty() && !mesh.colors.empty();
}

bool Shader::texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const {
    if (textures_.empty()) return false;
    const Material& m = material(triangle);
    if (!m.texture) return false;
    const TexturePoint point = textures_.at(triangle, bary);
    factor = sample_texture(*m.texture->texture, sampler_of(*m.texture, scene_.settings.texture_filter), point.uv,
                            point.duv_dx, point.duv_dy);
    return true;
}

Shader::SurfaceCorners Shader::surface_corners(uint32_t triangle) const {
    const TriangleIndices& v = geometry_.triangles[triangle];
    SurfaceCorners corners;
    for (int i = 0; i < 3; ++i) {
        corners.position[i] = geometry_.world_position[v.v[i]];
        corners.normal[i] = geometry_.world_normal[v.v[i]];
    }
    return corners;
}

void Shader::surface_at(const SurfaceCorners& corners, const glm::vec3& bary, glm::vec3& position, glm::vec3& normal) {
    position = glm::vec3(0.0f);
    normal = glm::vec3(0.0f);
    for (int i = 0; i < 3; ++i) {
        position += bary[i] * corners.position[i];
        normal += bary[i] * corners.normal[i];
    }
}

LightingTerms Shader::light_at(uint32_t triangle, const glm::vec3& bary, const float* visibility) const {
    glm::vec3 position, normal;
    surface_at(surface_corners(triangle), bary, position, normal);
    const glm::vec3 unit_normal = unit_or_zero(normal), to_eye = unit_or_zero(scene_.camera.eye - position);
    const RenderSettings& settings = scene_.settings;
    switch (mode_) {
        case ShadingMode::cel:
            return evaluate_cel_lighting(position, unit_normal, to_eye, material(triangle), scene_.lights,
                                         settings.ambient_light, settings.cel_bands, visibility);
        case ShadingMode::gooch:
            return evaluate_gooch_lighting(position, unit_normal, to_eye, material(triangle), scene_.lights,
                                           settings.gooch, visibility);
        default:
            return evaluate_lighting(position, unit_normal, to_eye, material(triangle), scene_.lights, settings.ambient_light,
                             specular_model_, visibility);
    }
}

void Shader::light_batch(const uint32_t* triangle, const glm::vec3* bary, size_t count, LightingBatch& batch) const {
    // Each run of points on one triangle reads its corners once.
    for (size_t j = 0; j < count;) {
        const uint32_t run_triangle = triangle[j];
        const SurfaceCorners corners = surface_corners(run_triangle);
        for (; j < count && triangle[j] == run_triangle; ++j) {
            glm::vec3 position, normal;
            surface_at(corners, bary[j], position, normal);
            for (int c = 0; c < 3; ++c) {
                batch.position[c][j] = position[c];
                batch.normal[c][j] = normal[c];
            }
        }
    }
    orient_points(batch, count, scene_.camera.eye);
    thread_local std::vector<float> visibility;
    if (shadows_) {
        visibility.assign(scene_.lights.size() * LightingBatch::kRow, 1.0f);
        for (size_t j = 0; j < count; ++j) {
            const glm::vec3 position(batch.position[0][j], batch.position[1][j], batch.position[2][j]);
            shadow_visibility(triangle[j], position, visibility.data() + j, LightingBatch::kRow);
        }
    }
    for (size_t first = 0, end; first < count; first = end) {  // runs of one material
        const Material& run_material = material(triangle[first]);
        for (end = first + 1; end < count && &material(triangle[end]) == &run_material;) ++end;
        light_points(batch, first, end - first, run_material, scene_.lights, scene_.settings.ambient_light,
                     specular_model_, shadows_ ? visibility.data() : nullptr);
    }
}

void Shader::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const {
    if (!corner_color_.empty()) {  // Gouraud: shade_point's sum over the corners, in its order
        for (size_t j = 0; j < count; ++j) {
            const glm::vec3* corner = &corner_color_[3 * static_cast<size_t>(triangle[j])];
            const glm::vec3& b = bary[j];
            out[j] = glm::vec3(0.0f) + b[0] * corner[0] + b[1] * corner[1] + b[2] * corner[2];
        }
        return;
    }
    if (!face_color_.empty()) {  // flat: one colour per triangle
        for (size_t j = 0; j < count; ++j) out[j] = face_color_[triangle[j]];
        return;
    }
    if (!lights_in_batches_) {
        for (size_t j = 0; j < count; ++j) out[j] = shade_point(triangle[j], bary[j]);
        return;
    }
    thread_local LightingBatch batch;
    for (size_t start = 0; start < count; start += kLightingBatch) {
        const size_t n = std::min(kLightingBatch, count - start);
        light_batch(triangle + start, bary + start, n, batch);
        auto terms_of = [](size_t j) -> LightingTerms {  // batch is thread_local: no capture
            return {glm::vec3(batch.diffuse[0][j], batch.diffuse[1][j], batch.diffuse[2][j]),
                    glm::vec3(batch.specular[0][j], batch.specular[1][j], batch.specular[2][j])};
        };
        if (!textures_.empty()) {
            for (size_t j = 0; j < n; ++j) {
                const uint32_t tri = triangle[start + j];
                glm::vec3 texel(1.0f);
                const bool textured = texture_factor(tri, bary[start + j], texel);
                out[start + j] = lit_color(tri, bary[start + j], textured ? &texel : nullptr, terms_of(j));
            }
            continue;
        }
        // Untextured: lit_color's base * diffuse + specular, the base colour looked up once per run of a triangle
        // unless its vertices carry colours.
        for (size_t j = 0; j < n;) {
            const uint32_t run_triangle = triangle[start + j];
            const bool per_vertex = base_varies(run_triangle);
            const glm::vec3 run_base = base_color(run_triangle, glm::vec3(1.0f / 3.0f));
            for (; j < n && triangle[start + j] == run_triangle; ++j)
                out[start + j] = lit(per_vertex ? base_color(run_triangle, bary[start + j]) : run_base, terms_of(j));
        }
    }
}

glm::vec3 Shader::lit_color(uint32_t triangle, const glm::vec3& bary, const glm::vec3* texel,
                            const LightingTerms& terms) const {
    return lit(texel ? base_color(triangle, bary) * *texel : base_color(triangle, bary), terms);
}

glm::vec3 Shader::shade(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 color;
    shade_many(&triangle, &bary, 1, &color);
    return color;
}

glm::vec3 Shader::shade_point(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 texel(1.0f);
    const bool textured = texture_factor(triangle, bary, texel);
    const float* visibility = visibility_at(triangle, bary);
    switch (mode_) {
        case ShadingMode::unlit:
            return textured ? base_color(triangle, bary) * texel : base_color(triangle, bary);
        case ShadingMode::flat: {  // textured or shadowed: shade_many answers the rest from face_color_
            const LightingTerms terms = combined(&face_terms_[triangle * static_cast<size_t>(terms_stride_)], visibility);
            return (textured ? texel * terms.diffuse : terms.diffuse) + terms.specular;
        }
        case ShadingMode::gouraud: {
            // Each corner's colour is lit at the vertex, then the colours are interpolated. A face colour is
            // constant over the triangle, so base * interpolated terms is the same thing. A texture multiplies the
            // interpolated base * diffuse, not the highlight.
            glm::vec3 color(0.0f), lit(0.0f), highlight(0.0f);
            for (int i = 0; i < 3; ++i) {
                glm::vec3 corner_bary(0.0f);
                corner_bary[i] = 1.0f;
                const LightingTerms terms = combined(corner_terms(triangle, i), visibility);
                if (textured) {
                    lit += bary[i] * (base_color(triangle, corner_bary) * terms.diffuse);
                    highlight += bary[i] * terms.specular;
                } else {
                    color += bary[i] * (base_color(triangle, corner_bary) * terms.diffuse + terms.specular);
                }
            }
            return textured ? texel * lit + highlight : color;
        }
        case ShadingMode::phong:
        case ShadingMode::blinn_phong:
        case ShadingMode::cel:
        case ShadingMode::gooch: {
            return lit_color(triangle, bary, textured ? &texel : nullptr, light_at(triangle, bary, visibility));
        }
    }
    return glm::vec3(0.0f);
}

}  // namespace raster
