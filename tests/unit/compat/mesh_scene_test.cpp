// A mesh file alone as a scene: the default camera holds a sphere inside the narrower field of view with the
// documented margin and direction, and the loader frames the sphere about the triangles' vertices, keeps the OBJ's
// materials and the PLY's colours, and refuses a mesh with nothing to draw.
#include "raster/compat/mesh_scene.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

using test_support::TempDir;

constexpr double kPi = 3.14159265358979323846;

// The camera's view of a point, worked out in double from its eye, target and up: right, up and depth along the
// view, and the point's normalised device x and y for an image of `aspect`.
struct Seen {
    double depth, ndc_x, ndc_y;
};
Seen see(const Camera& camera, double aspect, const glm::dvec3& point) {
    const glm::dvec3 eye(camera.eye), forward = glm::normalize(glm::dvec3(camera.target) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 q = point - eye;
    const double depth = glm::dot(q, forward), tan_half = std::tan(camera.fov_y_degrees * kPi / 360.0);
    return {depth, glm::dot(q, right) / (depth * tan_half * aspect), glm::dot(q, up) / (depth * tan_half)};
}

struct Box {
    glm::vec3 lo, hi;
    float aspect;
};

TEST(MeshScene, framingHoldsTheBoundingSphereInTheNarrowerFieldWithFivePercentToSpare) {
    const Box boxes[] = {
        {{-1, -1, -1}, {1, 1, 1}, 4.0f / 3.0f},       // the default 640 x 480 image
        {{-1, -1, -1}, {1, 1, 1}, 0.5f},              // a tall image: the horizontal field is the narrower
        {{0, 0, 0}, {10, 0.5f, 3}, 2.0f},             // long and flat
        {{-3, 0, -3}, {3, 0, 3}, 1.0f},               // a floor of no thickness
        {{1e4f, 2e4f, -5e3f}, {1e4f + 2, 2e4f + 1, -5e3f + 4}, 1.5f},  // far from the origin
    };
    for (const Box& box : boxes) {
        SCOPED_TRACE(testing::Message() << "aspect " << box.aspect << ", lo " << box.lo.x << ", hi " << box.hi.x);
        // The sphere through the box's corners.
        const glm::dvec3 centre = 0.5 * (glm::dvec3(box.lo) + glm::dvec3(box.hi));
        const double radius = 0.5 * glm::length(glm::dvec3(box.hi) - glm::dvec3(box.lo));
        const Camera camera = framing_camera(glm::vec3(centre), static_cast<float>(radius), box.aspect);
        const glm::dvec3 to_eye = glm::dvec3(camera.eye) - centre;
        const double distance = glm::length(to_eye);
        // The camera is worked out in double and stored in float: each coordinate of the eye is rounded by at most
        // |eye| 2^-24, so the vector to the eye moves by at most sqrt(3) |eye| 2^-24, and a component of it over
        // the distance (numerator and denominator both moved) by at most twice that over the distance: 2 sqrt(3)
        // < 4. 1e-6 more for the double arithmetic and the target's own rounding.
        const double tolerance = 1e-6 + 4.0 * std::ldexp(glm::length(glm::dvec3(camera.eye)), -24) / distance;
        // Looking at the centre from 30 degrees up and 30 degrees right of +z.
        EXPECT_NEAR(glm::length(glm::dvec3(camera.target) - centre), 0.0, 1e-6 * (1.0 + glm::length(centre)));
        EXPECT_NEAR(to_eye.y / distance, 0.5, tolerance);
        EXPECT_NEAR(to_eye.x / to_eye.z, std::tan(kPi / 6.0), 2.0 * tolerance);
        EXPECT_EQ(camera.fov_y_degrees, 45.0f);
        // The sphere grown by 5% just fits the narrower half-angle.
        const double half_y = 22.5 * kPi / 180.0, half_x = std::atan(box.aspect * std::tan(half_y));
        EXPECT_NEAR(std::asin(1.05 * radius / distance), std::min(half_y, half_x), 2.0 * tolerance);
        // Every corner of the box is in the image and between the clip planes.
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                               corner & 4 ? box.hi.z : box.lo.z);
            const Seen seen = see(camera, box.aspect, p);
            EXPECT_LT(std::abs(seen.ndc_x), 1.0) << corner;
            EXPECT_LT(std::abs(seen.ndc_y), 1.0) << corner;
            EXPECT_GT(seen.depth, camera.near) << corner;
            EXPECT_LT(seen.depth, camera.far) << corner;
        }
    }
}

TEST(MeshScene, aMeshOfOnePointIsFramedAsASphereOfRadiusOne) {
    const Camera camera = framing_camera({2, 3, 4}, 0.0f, 1.0f);
    const double distance = glm::length(glm::dvec3(camera.eye) - glm::dvec3(2, 3, 4));
    EXPECT_NEAR(1.05 / distance, std::sin(22.5 * kPi / 180.0), 1e-5);
    EXPECT_GT(camera.near, 0.0f);
}

TEST(MeshScene, theLightIsAboveAndLeftOfTheViewAtTheCamerasDistance) {
    const Camera camera = framing_camera({0, 0, 0}, 1.0f, 1.0f);
    const Light light = framing_light(camera);
    const glm::dvec3 to_eye = glm::dvec3(camera.eye) - glm::dvec3(camera.target);
    const glm::dvec3 to_light = glm::dvec3(light.position) - glm::dvec3(camera.target);
    EXPECT_NEAR(glm::length(to_light), glm::length(to_eye), 1e-4);
    const Seen seen = see(camera, 1.0, glm::dvec3(light.position));
    EXPECT_LT(seen.ndc_x, 0.0);  // left
    EXPECT_GT(seen.ndc_y, 0.0);  // above
    EXPECT_EQ(light.color, glm::vec3(1.0f));
    EXPECT_FALSE(light.attenuate);
    EXPECT_FALSE(light.shadows);
}

TEST(MeshScene, anObjFileLoadsAsAFramedSceneWithItsOwnMaterials) {
    TempDir dir;
    dir.write("red.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    // Vertex 5 is far away and in no face: the framing ignores it.
    const auto path = dir.write("cube.obj", "mtllib red.mtl\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 3\nv 900 900 900\n"
                                            "usemtl red\nf 1 2 3\nf 1 3 4\n");
    const SceneFile file = load_scene_file(path);
    EXPECT_EQ(file.format, SceneFormat::mesh);
    EXPECT_STREQ(to_string(file.format), "mesh");
    ASSERT_EQ(file.scene.meshes.size(), 1u);
    EXPECT_EQ(material_of(file.scene.meshes[0], 0).name, "red");
    EXPECT_EQ(file.scene.lights.size(), 1u);
    // The box of the faces' vertices is (0, 0, 0)-(2, 1, 3); the farthest of them from its centre (1, 0.5, 1.5) is
    // (0, 1, 3), at sqrt(1 + 0.25 + 2.25).
    const Camera expected = framing_camera({1.0f, 0.5f, 1.5f}, std::sqrt(3.5f), 640.0f / 480.0f);
    EXPECT_EQ(file.scene.camera.eye, expected.eye);
    EXPECT_EQ(file.scene.camera.target, expected.target);
    EXPECT_EQ(file.scene.camera.near, expected.near);
    EXPECT_EQ(file.scene.camera.far, expected.far);
    EXPECT_TRUE(file.request.output.empty());
}

TEST(MeshScene, aPlyFileInMemoryKeepsItsVertexColours) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n";
    const SceneFile file = parse_scene_file(ply, "triangle.PLY");
    EXPECT_EQ(file.format, SceneFormat::mesh);
    ASSERT_EQ(file.scene.meshes.size(), 1u);
    // The colours are the file's, and the material's own colour is white, so the base colour is theirs alone.
    const SceneMesh& mesh = file.scene.meshes[0];
    ASSERT_EQ(mesh.data->colors.size(), 3u);
    EXPECT_EQ(mesh.data->colors[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.data->colors[2], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.material.color, glm::vec3(1.0f));
    EXPECT_TRUE(mesh.parts.empty());
}

TEST(MeshScene, aMeshNoFloatCameraCanFrameIsRefusedAsTheMeshsProblem) {
    const std::string cases[] = {
        "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nf 1 2 3\n",    // the camera's own arithmetic overflows
        "v 3e38 0 0\nv -3e38 0 0\nv 0 1 0\nf 1 2 3\n",   // its box's float sum alone would overflow
        "v 0 0 0\nv 1e-39 0 0\nv 0 1e-39 0\nf 1 2 3\n",  // near would be subnormal
    };
    for (const std::string& obj : cases) {
        try {
            parse_scene_file(obj, "extreme.obj");
            ADD_FAILURE() << "framed: " << obj;
        } catch (const InputError& error) {
            EXPECT_EQ(error.file(), "extreme.obj");
            EXPECT_NE(error.message().find("the mesh's bounding sphere"), std::string::npos) << error.what();
            EXPECT_NE(error.message().find("cannot be framed"), std::string::npos) << error.what();
        }
    }
    // Inside the range: coordinates near 1e15, and an extent of 1e-15.
    EXPECT_NO_THROW(parse_scene_file("v 1e15 0 0\nv 1.5e15 0 0\nv 1e15 1e14 0\nf 1 2 3\n", "big.obj"));
    EXPECT_NO_THROW(parse_scene_file("v 0 0 0\nv 1e-15 0 0\nv 0 1e-15 0\nf 1 2 3\n", "small.obj"));
}

TEST(MeshScene, aMeshWithoutTrianglesIsRefusedNamingTheFile) {
    TempDir dir;
    const auto path = dir.write("points.obj", "v 0 0 0\nv 1 0 0\n");
    try {
        load_scene_file(path);
        FAIL() << "a mesh without triangles loaded";
    } catch (const InputError& error) {
        EXPECT_EQ(error.file(), path.string());
        EXPECT_NE(error.message().find("no triangles"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace raster
