// Texture lookups for the shader: each textured triangle's texture coordinates and the per-pixel derivatives of its
// perspective-correct barycentrics, so a sample's level of detail comes from the triangle's own projective map.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster {

// How a triangle's perspective-correct barycentrics b change across the screen. With the triangle's vertices in
// pixel-homogeneous coordinates as the columns of M (rows X = (x + w) W / 2, Y = (w - y) H / 2, and w, from clip
// space), a point's b satisfies M b = W_b (px, py, 1) where W_b = w . b; so b = W_b M^-1 (px, py, 1), and
//   db/dpx = W_b (c_x - b (1 . c_x)),  db/dpy = W_b (c_y - b (1 . c_y)),
// c_x and c_y the first two columns of M^-1. This is exact (analytic per sample, not a 2x2-quad difference) and
// needs only b, so a sample, a pixel centre or a centroid all get the derivative at their own point.
struct BarycentricGradient {
    glm::vec3 column_x{0.0f};  // c_x
    glm::vec3 column_y{0.0f};  // c_y
    glm::vec3 clip_w{0.0f};    // w of the three vertices
};

// The gradient of the triangle with clip-space vertices a, b, c in a width x height image. A triangle whose M is
// singular (seen edge-on through the eye) gets non-finite columns, which take the coarsest mip level.
BarycentricGradient barycentric_gradient(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, int width,
                                         int height);

// Texture coordinates and their derivatives at one point of a triangle, over one footprint step: a pixel, or under
// SSAA with N samples 1/sqrt(N) of a pixel (each sample filters its own share of the pixel, and the resolve
// averages them); MSAA, shading once per pixel, steps a whole pixel.
struct TexturePoint {
    glm::vec2 uv{0.0f};
    glm::vec2 duv_dx{0.0f};  // per footprint step to the right
    glm::vec2 duv_dy{0.0f};  // per footprint step down
};

// For every triangle of the scene whose material is textured: its three texture coordinates and its gradient.
// Built only for textured scenes; other triangles are never looked up.
class TextureLookup {
public:
    TextureLookup() = default;
    TextureLookup(const Scene& scene, const TransformedScene& geometry);

    bool empty() const { return corner_uv_.empty(); }
    // Texture coordinates of global triangle `triangle` at barycentrics `bary`, with their derivatives.
    TexturePoint at(uint32_t triangle, const glm::vec3& bary) const;

private:
    std::vector<TriangleUvs> corner_uv_;         // per global triangle
    std::vector<BarycentricGradient> gradient_;  // per global triangle
    float step_ = 1.0f;                          // the footprint step, in pixels
};

}  // namespace raster
