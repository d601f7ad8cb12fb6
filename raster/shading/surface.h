// What every shading model reads of a visible point: its triangle's material, base colour and texture value, the
// triangle's corners in world space, and the shadow maps' visibility of each light there. Built once per frame;
// the lookups the lighting loops make for every point are inline.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/core/unit_vector.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"
#include "raster/shading/lighting.h"
#include "raster/shading/texture_lookup.h"

namespace raster {

class ShadowMaps;  // shadow_maps.h

// Holds pointers into `scene`, `geometry` and `shadows`, which must outlive it. Shadows are looked up only in a lit
// shading mode with some light casting shadows; textures only in a textured scene; per-triangle materials only when
// a mesh has several.
class SurfaceLookup {
public:
    SurfaceLookup(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows);

    const Scene& scene() const { return scene_; }
    const TransformedScene& geometry() const { return geometry_; }
    const Material& material(uint32_t triangle) const {
        if (!triangle_material_.empty()) return *triangle_material_[triangle];
        return scene_.meshes[geometry_.triangle_mesh[triangle]].material;
    }
    // Whether some mesh has several materials, so that a vertex may be lit once per material it borders.
    bool materials_per_triangle() const { return !triangle_material_.empty(); }
    // The face colour, else the interpolated vertex colour, else the material colour; no texture.
    glm::vec3 base_color(uint32_t triangle, const glm::vec3& bary) const {
        const uint32_t mesh_index = geometry_.triangle_mesh[triangle];
        const MeshData& mesh = *scene_.meshes[mesh_index].data;
        const uint32_t local = triangle - geometry_.mesh_first_triangle[mesh_index];
        if (!mesh.face_colors.empty()) return mesh.face_colors[local];
        if (!mesh.colors.empty()) {
            const TriangleIndices& v = mesh.triangles[local];
            return bary.x * mesh.colors[v.v[0]] + bary.y * mesh.colors[v.v[1]] + bary.z * mesh.colors[v.v[2]];
        }
        return material(triangle).color;
    }
    // Whether base_color varies over the triangle (interpolated vertex colours), else it is one colour.
    bool base_varies(uint32_t triangle) const {
        const MeshData& mesh = *scene_.meshes[geometry_.triangle_mesh[triangle]].data;
        return mesh.face_colors.empty() && !mesh.colors.empty();
    }
    bool textured() const { return !textures_.empty(); }
    // The texture's value at the point when the triangle's material has one (it multiplies the base colour).
    bool texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const;
    // The fragment's opacity at the point (docs/transparency.md): the material's, times the texture's alpha when it
    // reads alpha; for a cut-out, 1 where that is at least the cut-off and 0 elsewhere.
    float opacity(uint32_t triangle, const glm::vec3& bary) const;
    // base * diffuse + specular, the base colour times the texel when there is one.
    glm::vec3 lit_color(uint32_t triangle, const glm::vec3& bary, const glm::vec3* texel,
                        const LightingTerms& terms) const;

    // A triangle's world positions and normals at its three corners.
    struct Corners {
        glm::vec3 position[3], normal[3];
    };
    Corners corners(uint32_t triangle) const {
        const TriangleIndices& v = geometry_.triangles[triangle];
        Corners corners;
        for (int i = 0; i < 3; ++i) {
            corners.position[i] = geometry_.world_position[v.v[i]];
            corners.normal[i] = geometry_.world_normal[v.v[i]];
        }
        return corners;
    }
    // The world position and the interpolated (not yet unit) normal at the point.
    static void surface_at(const Corners& corners, const glm::vec3& bary, glm::vec3& position, glm::vec3& normal) {
        position = glm::vec3(0.0f);
        normal = glm::vec3(0.0f);
        for (int i = 0; i < 3; ++i) {
            position += bary[i] * corners.position[i];
            normal += bary[i] * corners.normal[i];
        }
    }

    bool shadowed() const { return shadows_ != nullptr; }
    const std::vector<size_t>& shadowed_lights() const { return shadowed_lights_; }     // scene lights with maps
    const std::vector<Light>& unshadowed_lights() const { return unshadowed_lights_; }  // the others
    // Every scene light's visibility at the point (1 for a light without shadows), in a per-thread buffer; null
    // without shadow maps.
    const float* visibility_at(uint32_t triangle, const glm::vec3& bary) const;
    // Each shadowed light's visibility at `position` on `triangle`, into out[light * stride]; the other lights'
    // entries are left as they are.
    void shadow_visibility(uint32_t triangle, const glm::vec3& position, float* out, size_t stride) const;

private:
    const Scene& scene_;
    const TransformedScene& geometry_;
    std::vector<const Material*> triangle_material_;  // per triangle, only when a mesh has several materials
    TextureLookup textures_;                          // textured scenes only
    const ShadowMaps* shadows_ = nullptr;             // null when no light casts shadows
    std::vector<size_t> shadowed_lights_;
    std::vector<Light> unshadowed_lights_;
    std::vector<glm::vec3> face_normal_;  // with shadows: per triangle, (b - a) x (c - a) in world space
};

}  // namespace raster
