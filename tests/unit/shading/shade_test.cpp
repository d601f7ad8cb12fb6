// Lighting: hand-computed Blinn-Phong and Phong values, attenuation, one-sidedness, and the shading modes.
#include "raster/shading/shade.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace raster {
namespace {

Material test_material() {
    Material m;
    m.ambient = glm::vec3(0.1f);
    m.diffuse = glm::vec3(0.5f);
    m.specular = glm::vec3(0.25f);
    m.exponent = 2.0f;
    return m;
}

TEST(Lighting, lightStraightAboveGivesFullDiffuseAndSpecular) {
    // Normal up, light and eye straight above: n.l = 1, h = n so (n.h)^e = 1.
    const Light light{{0, 4, 0}, {1, 1, 1}, 2.0f, false};
    const LightingTerms t = evaluate_lighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, test_material(), {light}, glm::vec3(1),
                                              SpecularModel::blinn, nullptr);
    EXPECT_NEAR(t.diffuse.x, 0.1f + 0.5f * 2.0f, 1e-6f);
    EXPECT_NEAR(t.specular.x, 0.25f * 2.0f, 1e-6f);
}

TEST(Lighting, attenuationDividesByTheSquaredDistance) {
    const Light light{{0, 4, 0}, {1, 1, 1}, 2.0f, true};
    const LightingTerms t = evaluate_lighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, test_material(), {light}, glm::vec3(0),
                                              SpecularModel::blinn, nullptr);
    EXPECT_NEAR(t.diffuse.x, 0.5f * 2.0f / 16.0f, 1e-6f);
}

TEST(Lighting, blinnAndPhongLobesDifferAsTheirFormulasSay) {
    // Light at 45 degrees in the x-y plane, eye straight up: n.l = cos 45.
    // Blinn: h is at 22.5 degrees from n, lobe cos 22.5. Phong: r is at -45 degrees, r.v = cos 45.
    const float c45 = std::cos(float(M_PI) / 4), c22 = std::cos(float(M_PI) / 8);
    const Light light{{1, 1, 0}, {1, 1, 1}, 1.0f, false};
    const Material m = test_material();
    const LightingTerms blinn = evaluate_lighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, m, {light}, glm::vec3(0), SpecularModel::blinn, nullptr);
    const LightingTerms phong = evaluate_lighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, m, {light}, glm::vec3(0), SpecularModel::phong, nullptr);
    EXPECT_NEAR(blinn.diffuse.x, 0.5f * c45, 1e-5f);
    EXPECT_NEAR(blinn.specular.x, 0.25f * c22 * c22, 1e-5f);
    EXPECT_NEAR(phong.specular.x, 0.25f * c45 * c45, 1e-5f);
}

TEST(Lighting, specularPowerIsWithinItsRoundingBoundOfPowForIntegerExponentsAndIsPowOtherwise) {
    for (float exponent : {0.0f, 1.0f, 2.0f, 7.0f, 32.0f, 40.0f, 60.0f, 128.0f, 255.0f})
        for (float base : {0.0f, 0.013f, 0.5f, 0.9f, 0.999f, 1.0f}) {
            const double exact = std::pow(double(base), double(exponent));
            // A rounding (relative u = 2^-24) made when the partial power is x^k is raised to the power n / k that is
            // still to come, so the relative errors add up to at most (n - 1) u, to first order (n u bounds it).
            EXPECT_NEAR(specular_power(base, exponent), exact, std::max(1.0, double(exponent)) * 0x1p-24 * exact + 1e-38)
                << base << "^" << exponent;
        }
    EXPECT_EQ(specular_power(0.5f, 2.5f), std::pow(0.5f, 2.5f));     // not an integer: std::pow itself
    EXPECT_EQ(specular_power(0.5f, 300.0f), std::pow(0.5f, 300.0f));  // beyond the squaring range: std::pow
    EXPECT_EQ(specular_power(0.5f, 0.0f), 1.0f);
}

TEST(Lighting, lightBehindTheSurfaceAddsNothing) {
    const Light light{{0, -3, 0}, {1, 1, 1}, 1.0f, false};
    const LightingTerms t = evaluate_lighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, test_material(), {light}, glm::vec3(1),
                                              SpecularModel::blinn, nullptr);
    EXPECT_NEAR(t.diffuse.x, 0.1f, 1e-6f);  // ambient only
    EXPECT_EQ(t.specular.x, 0.0f);
}

// A one-triangle scene in the z = 0 plane facing +z, its vertices coloured red, green, blue.
Scene triangle_scene(ShadingMode mode) {
    Scene scene;
    scene.settings.shading = mode;
    scene.camera.eye = {0, 0, 5};
    SceneMesh mesh;
    mutable_data(mesh).positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    mutable_data(mesh).colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mutable_data(mesh).triangles = {{{0, 1, 2}}};
    mesh.material = test_material();
    scene.meshes.push_back(mesh);
    scene.lights.push_back({{0, 0, 3}, {1, 1, 1}, 1.0f, false});
    return scene;
}

TEST(Shader, unlitInterpolatesVertexColours) {
    const Scene scene = triangle_scene(ShadingMode::unlit);
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(ShadingMode::unlit));
    const Shader shader(scene, geometry);
    const glm::vec3 c = shader.shade(0, {0.2f, 0.3f, 0.5f});
    EXPECT_NEAR(c.x, 0.2f, 1e-6f);
    EXPECT_NEAR(c.y, 0.3f, 1e-6f);
    EXPECT_NEAR(c.z, 0.5f, 1e-6f);
    EXPECT_TRUE(geometry.world_normal.empty());  // unlit computes no normals
}

TEST(Shader, flatIsConstantOverTheTriangle) {
    const Scene scene = triangle_scene(ShadingMode::flat);
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(ShadingMode::flat));
    const Shader shader(scene, geometry);
    EXPECT_EQ(shader.shade(0, {1, 0, 0}), shader.shade(0, {0.1f, 0.1f, 0.8f}));
}

TEST(Shader, gouraudAtAVertexEqualsLightingAtThatVertex) {
    const Scene scene = triangle_scene(ShadingMode::gouraud);
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(ShadingMode::gouraud));
    const Shader shader(scene, geometry);
    // Vertex 0 at (-1,-1,0), normal +z, light at (0,0,3), eye at (0,0,5), base colour red.
    const glm::vec3 p(-1, -1, 0), n(0, 0, 1);
    const LightingTerms t = evaluate_lighting(p, n, glm::normalize(scene.camera.eye - p), scene.meshes[0].material,
                                              scene.lights, glm::vec3(1), SpecularModel::blinn, nullptr);
    const glm::vec3 expected = glm::vec3(1, 0, 0) * t.diffuse + t.specular;
    const glm::vec3 c = shader.shade(0, {1, 0, 0});
    EXPECT_NEAR(c.x, expected.x, 1e-5f);
    EXPECT_NEAR(c.y, expected.y, 1e-5f);
}

TEST(Shader, phongUsesTheInterpolatedPointAndNormal) {
    const Scene scene = triangle_scene(ShadingMode::blinn_phong);
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(ShadingMode::blinn_phong));
    const Shader shader(scene, geometry);
    const glm::vec3 bary(0.25f, 0.25f, 0.5f);
    const glm::vec3 p = 0.25f * glm::vec3(-1, -1, 0) + 0.25f * glm::vec3(1, -1, 0) + 0.5f * glm::vec3(0, 1, 0);
    const LightingTerms t = evaluate_lighting(p, {0, 0, 1}, glm::normalize(scene.camera.eye - p), scene.meshes[0].material,
                                              scene.lights, glm::vec3(1), SpecularModel::blinn, nullptr);
    const glm::vec3 base(0.25f, 0.25f, 0.5f);
    const glm::vec3 c = shader.shade(0, bary);
    EXPECT_NEAR(c.z, (base * t.diffuse + t.specular).z, 1e-5f);
}

}  // namespace
}  // namespace raster
