// Oracle checks: corpus scenes rendered by the implementation's stages and by the oracle, compared sample by sample.
#include "properties/mutants_oracle_checks.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "harness/comparison/scene_comparison.h"
#include "raster/formats/scene_loader.h"

namespace raster::properties {
namespace {

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";
constexpr const char* kMovedNear = "near_crossing_with_near_2";
constexpr const char* kAttenuation = "attenuating_light";
constexpr const char* kCulledCube = "flat_cube_with_back_faces_culled";

Scene scene_of(const std::string& name) {
    if (name == kAttenuation) {
        // A lit triangle 3 units in front of the camera under a light 1 unit in front of it, attenuated.
        Scene scene;
        scene.path = kAttenuation;
        scene.settings.width = scene.settings.height = 64;
        scene.settings.shading = ShadingMode::blinn_phong;
        scene.camera.eye = glm::vec3(0.0f);
        scene.camera.target = {0.0f, 0.0f, -1.0f};
        SceneMesh mesh;
        mesh.source = "inline";
        mesh.data.positions = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
        mesh.data.triangles = {{{0, 1, 2}}};
        scene.meshes.push_back(mesh);
        Light light;
        light.position = {0.0f, 0.0f, -1.0f};
        light.attenuate = true;
        scene.lights.push_back(light);
        return scene;
    }
    const std::string file = name == kMovedNear ? "near_crossing" : name == kCulledCube ? "flat_cube" : name;
    Scene scene = load_scene(kCorpus + file + ".yaml");
    scene.settings.samples = 1;
    if (name == kMovedNear) scene.camera.near = 2.0f;
    if (name == kCulledCube) scene.settings.cull_backfaces = true;
    return scene;
}

uint64_t genuine(const std::string& name, const PipelineStages& stages, RasterPath path, int threads,
                 std::string* reasons = nullptr) {
    harness::ComparisonOptions options;
    options.threads = threads;
    options.raster_path = path;
    const harness::Comparison c = harness::compare_scene(scene_of(name), options, stages);
    if (reasons) *reasons = harness::genuine_reasons(c);
    return c.genuine_total();
}

}  // namespace

std::vector<std::string> oracle_checks() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kCorpus))
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    names.push_back(kMovedNear);
    names.push_back(kAttenuation);
    names.push_back(kCulledCube);
    for (std::string& name : names) name = "Oracle." + name;
    return names;
}

std::string run_oracle_check(const std::string& check, const Implementation& impl) {
    const std::string scene = check.substr(7);
    static std::map<std::string, uint64_t> baselines;
    if (!baselines.count(scene)) baselines[scene] = genuine(scene, PipelineStages{}, RasterPath::tiled, 1);
    std::string reasons;
    const uint64_t found = genuine(scene, impl.stages, impl.backend.path, 1, &reasons);
    if (found <= baselines[scene]) return "";
    return std::to_string(found) + " genuine disagreements with the oracle (" + reasons + "); the real pipeline has " +
           std::to_string(baselines[scene]);
}

}  // namespace raster::properties
