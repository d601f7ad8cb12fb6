// Quads for the tests that build scenes in code: any four corners, and a square facing the default camera.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster::test_support {

// The quad a, b, c, d as the triangles (a, b, c) and (a, c, d).
inline SceneMesh quad_mesh(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
    SceneMesh mesh;
    mutable_data(mesh).positions = {a, b, c, d};
    mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
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

// An n x n grid of quads over [-1, 1]^2 at z = 0, facing the default camera, of material colour `colour` and
// opacity `opacity`: 2 n^2 triangles, row by row.
inline SceneMesh grid_mesh(int n, const glm::vec3& colour, float opacity = 1.0f) {
    SceneMesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            mutable_data(mesh).positions.emplace_back(-1.0f + 2.0f * x / n, -1.0f + 2.0f * y / n, 0.0f);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const auto corner = static_cast<uint32_t>(y * (n + 1) + x), above = corner + static_cast<uint32_t>(n + 1);
            mutable_data(mesh).triangles.push_back({{corner, corner + 1, above + 1}});
            mutable_data(mesh).triangles.push_back({{corner, above + 1, above}});
        }
    mesh.material.color = colour;
    mesh.material.opacity = opacity;
    mesh.source = "inline";
    return mesh;
}

// An unlit scene of these meshes, 96 x 96 pixels, seen by the default camera.
inline Scene unlit_scene(std::vector<SceneMesh> meshes) {
    Scene scene;
    scene.settings.width = scene.settings.height = 96;
    scene.settings.shading = ShadingMode::unlit;
    scene.meshes = std::move(meshes);
    return scene;
}

}  // namespace raster::test_support
