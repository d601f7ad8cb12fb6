// The oracle's texture lookups for its shader: per textured triangle its texture coordinates, its view-space
// vertices and its derivative-error inputs; per sample, the box of values the material's texture may give there,
// with the level of detail from the ray differentials of the oracle's own camera.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "oracle/reference/oracle_texture.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/texture_filters.h"
#include "oracle/reference/texture_precision.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// Texture coordinates and their derivatives per pixel step right (x) and down (y) at a point of a triangle.
struct UvDerivatives {
    glm::dvec2 uv{0.0}, d_dx{0.0}, d_dy{0.0};
    glm::dvec3 dbary_dx{0.0}, dbary_dy{0.0};
};

// By ray differentials (Igehy 1999): the point P = sum b_i v_i (view space) is where the camera ray D meets the
// triangle's plane (normal n); moving the pixel moves D by dD, and P by t (dD - D (n . dD) / (n . D)), t the view
// depth; the barycentrics follow from the triangle's edges e1, e2: d b1 = ((dP x e2) . n) / |n|^2,
// d b2 = ((e1 x dP) . n) / |n|^2, d b0 = -(d b1 + d b2). Non-finite where the ray grazes the plane.
UvDerivatives ray_differential(const OracleCamera& camera, const glm::dvec3 view[3], const glm::dvec2 uv[3],
                               const glm::dvec3& bary);

class OracleTextureSampling {
public:
    OracleTextureSampling(const Scene& scene, const OracleScene& geometry);

    // The box of values `material`'s texture may give for triangle `id` at any barycentrics in `bary`. The
    // material must be textured.
    Interval3 at(uint32_t id, const Material& material, const Interval3& bary) const;
    // The box of alpha values likewise, for a material whose texture reads alpha.
    Interval alpha_at(uint32_t id, const Material& material, const Interval3& bary) const;

private:
    // The texture coordinates and their derivatives over the barycentric box, raster's float error included.
    TextureFootprintBox footprint(uint32_t id, const SamplerState& sampler, const Interval3& bary) const;

    struct Triangle {
        glm::dvec3 view[3];
        glm::dvec2 uv[3];
        DerivativeErrorInputs error;
    };
    const OracleScene& geometry_;
    OracleTextures textures_;
    std::optional<TextureFilter> filter_override_;  // the render settings' texture_filter
    double step_ = 1.0;                             // the footprint step in pixels: 1/sqrt(N) under SSAA
    std::vector<Triangle> triangles_;  // per scene triangle; filled for textured ones
};

}  // namespace raster::oracle
