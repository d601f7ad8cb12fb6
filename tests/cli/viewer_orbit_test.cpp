// `raster view`'s orbit: the scene's own camera at yaw 0, pitch 0, distance 1, exactly; right-handed yaw about up;
// positive pitch raising the eye; the elevation clamp; distance scaling the eye and the clip planes; target, up and
// field of view kept.
#include "apps/viewer_orbit.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace raster::cli {
namespace {

Camera straight_on() {
    Camera camera;
    camera.eye = {0.0f, 0.0f, 5.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    return camera;
}

void expect_near(const glm::vec3& got, const glm::vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-5f);
    EXPECT_NEAR(got.y, want.y, 1e-5f);
    EXPECT_NEAR(got.z, want.z, 1e-5f);
}

TEST(ViewerOrbit, noOrbitIsTheScenesCameraExactly) {
    Camera teapot;  // corpus/scenes/teapot.yaml's
    teapot.eye = {0.0f, 3.2f, 9.5f};
    teapot.target = {0.0f, 0.1f, 0.0f};
    teapot.up = {0.0f, 1.0f, 0.0f};
    Camera odd;  // a tilted up, a target off the origin
    odd.eye = {-3.7f, 11.25f, 0.3f};
    odd.target = {1.5f, -2.0f, 4.25f};
    odd.up = {0.3f, 0.9f, -0.1f};
    for (const Camera& camera : {teapot, odd, straight_on()}) {
        const Camera same = orbit_camera(camera, 0.0, 0.0, 1.0);
        EXPECT_EQ(same.eye, camera.eye);
        EXPECT_EQ(same.target, camera.target);
        EXPECT_EQ(same.up, camera.up);
        EXPECT_EQ(same.near, camera.near);
        EXPECT_EQ(same.far, camera.far);
    }
}

TEST(ViewerOrbit, yawTurnsTheEyeRightHandedlyAboutUp) {
    // Seen from above (+y towards the viewer), +z turns counter-clockwise to +x.
    expect_near(orbit_camera(straight_on(), 90.0, 0.0, 1.0).eye, {5.0f, 0.0f, 0.0f});
    expect_near(orbit_camera(straight_on(), -90.0, 0.0, 1.0).eye, {-5.0f, 0.0f, 0.0f});
    expect_near(orbit_camera(straight_on(), 180.0, 0.0, 1.0).eye, {0.0f, 0.0f, -5.0f});
    expect_near(orbit_camera(straight_on(), 360.0, 0.0, 1.0).eye, {0.0f, 0.0f, 5.0f});
}

TEST(ViewerOrbit, positivePitchRaisesTheEyeAndDistanceScalesIt) {
    const float half = 5.0f * std::sqrt(0.5f);
    expect_near(orbit_camera(straight_on(), 0.0, 45.0, 1.0).eye, {0.0f, half, half});
    expect_near(orbit_camera(straight_on(), 0.0, -45.0, 1.0).eye, {0.0f, -half, half});
    expect_near(orbit_camera(straight_on(), 0.0, 0.0, 2.0).eye, {0.0f, 0.0f, 10.0f});
    expect_near(orbit_camera(straight_on(), 90.0, 45.0, 0.5).eye, {half / 2, half / 2, 0.0f});
}

TEST(ViewerOrbit, theElevationStopsShortOfUp) {
    EXPECT_DOUBLE_EQ(eye_elevation_degrees(straight_on()), 0.0);
    for (const double pitch : {89.0, 120.0, 180.0}) {
        const Camera camera = orbit_camera(straight_on(), 0.0, pitch, 1.0);
        EXPECT_NEAR(eye_elevation_degrees(camera), 89.0, 1e-4) << pitch;
        EXPECT_NEAR(glm::length(camera.eye), 5.0f, 1e-4f) << pitch;
    }
    EXPECT_NEAR(eye_elevation_degrees(orbit_camera(straight_on(), 0.0, -180.0, 1.0)), -89.0, 1e-4);
    // A scene already looking down more steeply keeps its own view, and the limit is its elevation.
    Camera steep = straight_on();
    steep.eye = {0.0f, 100.0f, 0.5f};
    const double elevation = eye_elevation_degrees(steep);
    EXPECT_GT(elevation, 89.0);
    EXPECT_DOUBLE_EQ(orbit_elevation_limit_degrees(steep), elevation);
    EXPECT_EQ(orbit_camera(steep, 0.0, 0.0, 1.0).eye, steep.eye);
    EXPECT_NEAR(eye_elevation_degrees(orbit_camera(steep, 0.0, 10.0, 1.0)), elevation, 1e-3);
}

TEST(ViewerOrbit, theClipPlanesFollowTheDistanceSoTheSceneStaysInside) {
    Camera camera = straight_on();
    camera.near = 1.0f;
    camera.far = 30.0f;
    const Camera away = orbit_camera(camera, 0.0, 0.0, 4.0);
    EXPECT_EQ(away.near, 1.0f);
    EXPECT_EQ(away.far, 120.0f);
    const Camera close = orbit_camera(camera, 0.0, 0.0, 0.25);
    EXPECT_EQ(close.near, 0.25f);
    EXPECT_EQ(close.far, 30.0f);
}

TEST(ViewerOrbit, theTargetUpAndLensStayTheScenes) {
    Camera camera = straight_on();
    camera.target = {1.0f, 2.0f, 3.0f};
    camera.eye = {1.0f, 2.0f, 8.0f};
    camera.fov_y_degrees = 30.0f;
    camera.near = 0.5f;
    camera.far = 50.0f;
    const Camera orbited = orbit_camera(camera, 90.0, 0.0, 1.0);
    expect_near(orbited.eye, {6.0f, 2.0f, 3.0f});  // about the target, not the origin
    EXPECT_EQ(orbited.target, camera.target);
    EXPECT_EQ(orbited.up, camera.up);
    EXPECT_EQ(orbited.fov_y_degrees, 30.0f);
    EXPECT_EQ(orbited.near, 0.5f);
    EXPECT_EQ(orbited.far, 50.0f);
}

}  // namespace
}  // namespace raster::cli
