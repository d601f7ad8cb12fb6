// Texture lookups: per textured triangle, its corner texture coordinates and the screen-space gradient of its
// perspective-correct barycentrics (derived in texture_lookup.h).
#include "raster/shading/texture_lookup.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {

BarycentricGradient barycentric_gradient(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, int width,
                                         int height) {
    // Columns of M: the vertices in pixel-homogeneous coordinates, in double so that a thin or distant triangle's
    // inverse keeps its digits.
    auto column = [&](const glm::vec4& v) {
        return glm::dvec3((static_cast<double>(v.x) + v.w) * 0.5 * width, (static_cast<double>(v.w) - v.y) * 0.5 * height,
                          static_cast<double>(v.w));
    };
    const glm::dmat3 m(column(a), column(b), column(c));
    const double det = glm::determinant(m);
    BarycentricGradient gradient;
    gradient.clip_w = glm::vec3(a.w, b.w, c.w);
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        gradient.column_x = gradient.column_y = glm::vec3(nan);
        return gradient;
    }
    const glm::dmat3 inverse = glm::inverse(m);
    // glm is column-major: inverse[j] is column j; its element i is row i.
    gradient.column_x = glm::vec3(inverse[0]);
    gradient.column_y = glm::vec3(inverse[1]);
    return gradient;
}

TextureLookup::TextureLookup(const Scene& scene, const TransformedScene& geometry) {
    // SSAA's footprint is a sample's share of the pixel, 1/sqrt(N) of its side; MSAA shades, and so filters, per pixel.
    const RenderSettings& settings = scene.settings;
    step_ = settings.msaa || settings.samples <= 1 ? 1.0f : 1.0f / std::sqrt(static_cast<float>(settings.samples));
    corner_uv_.resize(geometry.triangles.size());
    gradient_.resize(geometry.triangles.size());
    const int width = scene.settings.width, height = scene.settings.height;
    for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
        const SceneMesh& source = scene.meshes[mesh];
        if (source.data->corner_uvs.empty()) continue;
        const uint32_t first = geometry.mesh_first_triangle[mesh];
        for (uint32_t local = 0; local < source.data->triangles.size(); ++local) {
            if (!material_of(source, local).texture) continue;
            const TriangleIndices& v = geometry.triangles[first + local];
            corner_uv_[first + local] = source.data->corner_uvs[local];
            gradient_[first + local] =
                barycentric_gradient(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]], width, height);
        }
    }
}

TexturePoint TextureLookup::at(uint32_t triangle, const glm::vec3& bary) const {
    const TriangleUvs& corners = corner_uv_[triangle];
    const BarycentricGradient& g = gradient_[triangle];
    const float w = glm::dot(bary, g.clip_w);
    const glm::vec3 dbary_dx = (step_ * w) * (g.column_x - bary * (g.column_x.x + g.column_x.y + g.column_x.z));
    const glm::vec3 dbary_dy = (step_ * w) * (g.column_y - bary * (g.column_y.x + g.column_y.y + g.column_y.z));
    TexturePoint point;
    for (int i = 0; i < 3; ++i) {
        point.uv += bary[i] * corners.uv[i];
        point.duv_dx += dbary_dx[i] * corners.uv[i];
        point.duv_dy += dbary_dy[i] * corners.uv[i];
    }
    return point;
}

}  // namespace raster
