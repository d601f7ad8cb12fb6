// Quads for the tests that build scenes in code: any four corners, and a square facing the default camera.
#pragma once

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster::test_support {

// The quad a, b, c, d as the triangles (a, b, c) and (a, c, d).
inline SceneMesh quad_mesh(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
    SceneMesh mesh;
    mesh.data.positions = {a, b, c, d};
    mesh.data.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    mesh.source = "inline";
    return mesh;
}

// A square of half-size `half` facing the default camera (at z = 5, looking down -z) at view depth `depth`, of
// material colour `colour` and opacity `opacity`.
inline SceneMesh facing_pane(double depth, double half, const glm::vec3& colour, float opacity) {
    const float z = static_cast<float>(5.0 - depth), h = static_cast<float>(half);
    SceneMesh mesh = quad_mesh({-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z});
    mesh.material.color = colour;
    mesh.material.opacity = opacity;
    return mesh;
}

}  // namespace raster::test_support
