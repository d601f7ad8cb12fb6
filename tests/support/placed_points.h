// Where a scene mesh's model transform puts a point, and a float-tolerant comparison of points, for the loaders'
// tests that work placements out by hand.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "raster/scene/scene.h"
#include "raster/transform/model_matrix.h"

namespace raster::test_support {

// The point `p` of the mesh's object space in world space, by raster's model matrix.
inline glm::vec3 placed(const SceneMesh& mesh, const glm::vec3& p) {
    return glm::vec3(model_matrix(mesh.transform) * glm::vec4(p, 1.0f));
}

// Each coordinate within `tolerance`.
inline void expect_near(const glm::vec3& got, const glm::vec3& want, float tolerance = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

}  // namespace raster::test_support
