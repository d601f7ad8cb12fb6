// Sample positions, the viewport mapping and camera rays: the points both renderers look through.
#include "raster/geometry/camera_rays.h"

#include <gtest/gtest.h>

#include "raster/transform/transform.h"
#include "raster/geometry/vertex_stage.h"

namespace raster {
namespace {

TEST(CameraRays, sampleScreenPositionIsThePixelCornerPlusTheFixedOffset) {
    const int fixed_bits = 8;
    const std::vector<glm::vec2> offsets = sample_offsets(16, SamplePattern::standard);
    const FixedSampleOffsets fixed = fixed_sample_offsets(offsets, fixed_bits);
    for (int s = 0; s < 16; ++s) {
        const glm::dvec2 p = sample_screen_position(3, 5, s, fixed, fixed_bits);
        EXPECT_EQ(p.x, 3.0 + offsets[s].x) << s;  // standard offsets are multiples of 1/16: exact
        EXPECT_EQ(p.y, 5.0 + offsets[s].y) << s;
        const FixedPosition q = sample_fixed_position(3, 5, s, fixed, fixed_bits);
        EXPECT_EQ(q.x, 3 * 256 + fixed.x[s]);
        EXPECT_EQ(q.y, 5 * 256 + fixed.y[s]);
    }
}

TEST(CameraRays, screenFromNdcIsTheViewportMatrix) {
    const glm::mat4 viewport = viewport_matrix(640, 480);
    for (const glm::dvec2 ndc : {glm::dvec2(-1, 1), glm::dvec2(1, -1), glm::dvec2(0.25, -0.5), glm::dvec2(0, 0)}) {
        const glm::vec4 expected = viewport * glm::vec4(float(ndc.x), float(ndc.y), 0.0f, 1.0f);
        const glm::dvec2 screen = screen_from_ndc(ndc.x, ndc.y, 640, 480);
        EXPECT_NEAR(screen.x, expected.x, 1e-4);
        EXPECT_NEAR(screen.y, expected.y, 1e-4);
        const glm::dvec2 back = ndc_from_screen(screen, 640, 480);
        EXPECT_NEAR(back.x, ndc.x, 1e-15);
        EXPECT_NEAR(back.y, ndc.y, 1e-15);
    }
}

TEST(CameraRays, rayThroughAScreenPointProjectsBackOntoItAndItsParameterIsViewDepth) {
    Camera camera;
    camera.fov_y_degrees = 63.0f;
    camera.near = 0.25f;
    camera.far = 40.0f;
    const int width = 333, height = 201;
    const glm::dmat4 projection(projection_matrix(camera, width, height));
    for (const glm::dvec2 screen : {glm::dvec2(0, 0), glm::dvec2(333, 201), glm::dvec2(12.3125, 190.5), glm::dvec2(166.5, 100.5)}) {
        const glm::dvec3 direction =
            view_ray_direction(projection_matrix(camera, width, height), ndc_from_screen(screen, width, height));
        EXPECT_EQ(direction.z, -1.0);  // t along the ray is the view depth -z
        for (double t : {0.25, 3.7, 40.0}) {
            const glm::dvec4 clip = projection * glm::dvec4(t * direction, 1.0);
            EXPECT_NEAR(clip.w, t, 1e-12 * t);
            const glm::dvec2 back = screen_from_ndc(clip.x / clip.w, clip.y / clip.w, width, height);
            EXPECT_NEAR(back.x, screen.x, 1e-9);
            EXPECT_NEAR(back.y, screen.y, 1e-9);
        }
    }
}

TEST(CameraRays, aRayWithAnotherProjectionSolvesThatProjection) {
    // The integer-aspect projection of the bug catalogue: the ray must follow whatever matrix it is given.
    const glm::mat4 squashed = perspective_matrix(45.0f, 1.0f, 0.1f, 100.0f);
    const glm::dvec3 direction = view_ray_direction(squashed, glm::dvec2(0.5, -0.25));
    const glm::dvec4 clip = glm::dmat4(squashed) * glm::dvec4(2.0 * direction, 1.0);
    EXPECT_NEAR(clip.x / clip.w, 0.5, 1e-12);
    EXPECT_NEAR(clip.y / clip.w, -0.25, 1e-12);
}

}  // namespace
}  // namespace raster
