// Hand-made scenes for the oracle's tests: unlit triangles (one mesh each) in front of a camera, built in code,
// and their exact reference geometry.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/scene/scene.h"

namespace raster::oracle::testing {

using Triangle = std::array<glm::vec3, 3>;

inline Scene scene_with_triangles(const std::vector<Triangle>& triangles, const Camera& camera, int width, int height,
                                  int samples = 1) {
    Scene scene;
    scene.path = "test-scene";
    scene.camera = camera;
    scene.settings.width = width;
    scene.settings.height = height;
    scene.settings.samples = samples;
    scene.settings.shading = ShadingMode::unlit;
    for (const Triangle& t : triangles) {
        SceneMesh mesh;
        mesh.source = "inline";
        mutable_data(mesh).positions = {t[0], t[1], t[2]};
        mutable_data(mesh).triangles = {{{0, 1, 2}}};
        scene.meshes.push_back(std::move(mesh));
    }
    return scene;
}

// A camera at the origin looking down -z.
inline Camera camera_at_origin(float fov_degrees = 45.0f, float near = 0.1f, float far = 100.0f) {
    Camera camera;
    camera.eye = glm::vec3(0.0f);
    camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.fov_y_degrees = fov_degrees;
    camera.near = near;
    camera.far = far;
    return camera;
}

// The reference geometry of a scene, as the comparison builds it.
inline ReferenceGeometry reference_for(const Scene& scene) { return ReferenceGeometry(scene, oracle_scene(scene)); }

// What a renderer that saw triangle `id` exactly at `screen` reports there (its hit rounded to float).
inline SampleEntry covered_by(uint32_t id, const ReferenceGeometry& reference, const glm::dvec2& screen) {
    const ExactHit hit = reference.hit(id, screen);
    return {id, glm::vec3(hit.bary), static_cast<float>(hit.view_depth)};
}

}  // namespace raster::oracle::testing
