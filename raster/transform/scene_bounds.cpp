// The box that bounds a scene in world space (scene_bounds.h).
#include "raster/transform/scene_bounds.h"

#include <algorithm>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raster/transform/model_matrix.h"

namespace raster {

std::optional<WorldBounds> world_bounds(const Scene& scene) {
    std::vector<glm::dvec3> points;
    for (const SceneMesh& mesh : scene.meshes) {
        const glm::mat4 model = model_matrix(mesh.transform);
        std::vector<bool> used(mesh.data->positions.size(), false);
        for (const TriangleIndices& triangle : mesh.data->triangles)
            for (const uint32_t v : triangle.v) {
                if (used[v]) continue;
                used[v] = true;
                points.push_back(glm::dvec3(glm::dmat4(model) * glm::dvec4(glm::dvec3(mesh.data->positions[v]), 1.0)));
            }
    }
    if (points.empty()) return std::nullopt;
    WorldBounds bounds;
    bounds.lo = bounds.hi = points.front();
    for (const glm::dvec3& p : points) {
        bounds.lo = glm::min(bounds.lo, p);
        bounds.hi = glm::max(bounds.hi, p);
    }
    bounds.centre = 0.5 * (bounds.lo + bounds.hi);
    for (const glm::dvec3& p : points) bounds.radius = std::max(bounds.radius, glm::length(p - bounds.centre));
    return bounds;
}

}  // namespace raster
