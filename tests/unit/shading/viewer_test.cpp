// The view vector: towards the eye for a perspective camera, the camera's back direction everywhere for an
// orthographic one.
#include "raster/shading/viewer.h"

#include <cmath>

#include <gtest/gtest.h>

namespace raster {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-6f);
    EXPECT_NEAR(a.y, b.y, 1e-6f);
    EXPECT_NEAR(a.z, b.z, 1e-6f);
}

TEST(Viewer, aPerspectiveViewVectorPointsFromThePointToTheEye) {
    Camera camera;
    camera.eye = {0.0f, 3.0f, 4.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    const Viewer viewer = viewer_of(camera);
    EXPECT_FALSE(viewer.parallel);
    expect_near(to_viewer(viewer, {0.0f, 0.0f, 0.0f}), {0.0f, 0.6f, 0.8f});
    expect_near(to_viewer(viewer, {0.0f, 3.0f, 0.0f}), {0.0f, 0.0f, 1.0f});
    expect_near(to_viewer(viewer, camera.eye), {0.0f, 0.0f, 0.0f});  // at the eye: zero
}

TEST(Viewer, anOrthographicViewVectorIsTheBackDirectionAtEveryPoint) {
    Camera camera;
    camera.projection = Projection::orthographic;
    camera.eye = {0.0f, 3.0f, 4.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    const Viewer viewer = viewer_of(camera);
    EXPECT_TRUE(viewer.parallel);
    for (const glm::vec3& point : {glm::vec3(0.0f), glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(5.0f, -2.0f, 1.0f), camera.eye})
        expect_near(to_viewer(viewer, point), {0.0f, 0.6f, 0.8f});
}

}  // namespace
}  // namespace raster
