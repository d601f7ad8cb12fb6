// The oracle shows which bugs of the catalogue it catches: each faulty stage variant below gives genuine
// disagreements on a corpus scene on which the correct rasterizer gives none. Prints the table.
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "harness/comparison/scene_comparison.h"
#include "raster/formats/scene_loader.h"
#include "mutants/catalogue.h"
#include "tests/support/oracle_test_scenes.h"

namespace raster::oracle {
namespace {

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

struct Caught {
    const char* mutant;
    const char* scene;
    float near = 0.0f;  // when > 0, the scene's near plane is moved there so that the bug's effect is on screen
    bool cull = false;  // back-face culling on
};

// The bugs the oracle must catch, each with a corpus scene that shows it (compared at 1 sample per pixel).
const Caught kCaught[] = {
    // Without near clipping the side planes still cut everything behind the eye (x in [-w, w] is empty for
    // w < 0); what remains is the floor between the eye and the near plane, on screen once near is 2, not 0.1.
    {"no near clipping", "near_crossing.yaml", 2.0f},
    {"w <= 0 dropped instead of clipped", "near_crossing.yaml"},
    {"sub-pixel triangles discarded", "teapot.yaml"},
    {"y not flipped", "single_triangle.yaml"},
    {"affine instead of perspective-correct", "perspective_quad.yaml"},
    {"depth buffer initialised with numeric_limits<float>::min()", "flat_cube.yaml"},
    {"wrong sample positions", "single_triangle.yaml"},
    {"integer-divided aspect ratio", "perspective_quad.yaml"},
    {"front faces culled (winding inverted)", "teapot.yaml", 0.0f, true},
};

// The scene of `c` compared with the oracle, rendered by `stages` on `path` (a mutant's, or the real ones).
harness::Comparison compare_corpus(const Caught& c, const PipelineStages& stages, RasterPath path = RasterPath::tiled) {
    Scene scene = load_scene(kCorpus + c.scene);
    scene.settings.samples = 1;
    if (c.near > 0.0f) scene.camera.near = c.near;
    scene.settings.cull_backfaces = c.cull;
    harness::ComparisonOptions options;
    options.raster_path = path;
    return harness::compare_scene(scene, options, stages);
}

TEST(OracleCatchesMutants, eachListedBugGivesGenuineDisagreementsWhereTheCorrectRasterizerGivesNone) {
    std::map<std::string, uint64_t> correct;  // per scene (and near plane)
    std::string table = "\n  mutant                                                      scene                  "
                        "genuine  (correct)  reasons\n";
    for (const Caught& c : kCaught) {
        const std::string scene = std::string(c.scene) + (c.near > 0 ? ", near " + std::to_string(int(c.near)) : "") +
                                  (c.cull ? ", culled" : "");
        if (!correct.count(scene)) correct[scene] = compare_corpus(c, PipelineStages{}).genuine_total();
        EXPECT_EQ(correct[scene], 0u) << scene;
        const mutants::Mutant& mutant = mutants::mutant(c.mutant);
        const harness::Comparison faulty = compare_corpus(c, mutant.stages, mutant.path);
        const uint64_t genuine = faulty.genuine_total();
        EXPECT_GT(genuine, 0u) << c.mutant << " on " << scene;
        char line[512];
        std::snprintf(line, sizeof line, "  %-60s %-22s %7llu  %9llu  %s\n", c.mutant, scene.c_str(),
                      static_cast<unsigned long long>(genuine), static_cast<unsigned long long>(correct[scene]),
                      harness::genuine_reasons(faulty).c_str());
        table += line;
    }
    std::printf("%s", table.c_str());
    RecordProperty("table", table);
}

TEST(OracleCatchesMutants, missingAttenuationIsAColourDisagreement) {
    // No corpus scene has an attenuating light, so this one is built here: a lit quad under a light at distance ~2.
    Scene scene = testing::scene_with_triangles({{{{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}}}}, testing::camera_at_origin(), 64, 64);
    scene.settings.shading = ShadingMode::blinn_phong;
    Light light;
    light.position = glm::vec3(0.0f, 0.0f, -1.0f);
    light.attenuate = true;
    scene.lights.push_back(light);
    const harness::Comparison correct = harness::compare_scene(scene, harness::ComparisonOptions{});
    EXPECT_EQ(correct.genuine_total(), 0u);
    const harness::Comparison faulty =
        harness::compare_scene(scene, harness::ComparisonOptions{}, mutants::mutant("1/r^2 attenuation missing").stages);
    EXPECT_GT(faulty.colour_genuine_pixels, 0u);
    EXPECT_EQ(faulty.visibility.counts.genuine_total(), 0u);  // only the colour is wrong
}

}  // namespace
}  // namespace raster::oracle
