// The differential target's cases: its limits, the precision modes it draws and what the oracle judges in each,
// extreme coordinates, validation and the filters that keep what the oracle's bounds cover.
#include "fuzz/differential_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz/fuzzed_scene.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/core/errors.h"
#include "raster/image/image.h"
#include "raster/texture/mip_chains.h"
#include "raster/texture/texture.h"
#include "raster/transform/camera_matrices.h"
#include "raster/scene/validation.h"

namespace raster::fuzz {
namespace {

// Largest projection magnification compared, on either axis (see the known limitation below).
constexpr double kMaxMagnification = 1e3;
// Largest frame compared, in samples: the comparison's cost is per sample (the oracle's ray, the classification and
// the colour bounds, all under the sanitizers), and frames up to 2^12 samples (32 x 32 at 4, 16 x 16 at 16) keep the
// target over 800 inputs a second; at 2^13 it ran about 650.
constexpr uint64_t kMaxFrameSamples = uint64_t{1} << 12;
// Extreme coordinates: at most this many vertices from raw float bits or the table of extremes.
constexpr int kMaxExtremeVertices = 3;
// A case with extreme coordinates is compared only where the oracle's bounds say something: every triangle's radius
// (snap plus float error of its vertices, precision.h section 4) under a pixel. A wider edge band covers most of a
// 32-pixel frame: every disagreement there would be excused, which measures nothing and only inflates the excused
// fraction that `differential_excuses` reports.
constexpr double kMaxExtremeRadius = 1.0;

// A precision mode drawn, by name.
struct ModeVariant {
    const char* name;
    PrecisionModes modes;
};

// The modes drawn, the defaults first (what an exhausted input, or one saved before modes were drawn, gets): the
// defaults, hierarchical Z off (it never changes a pixel), affine interpolation, float z and fixed24 depth. What the
// oracle judges in each is harness::judged_classes's rule, the one `raster compare` follows. Float edges and the
// guard band are not drawn: they leave visibility unjudged, and the only other check they would get is the
// interpolation of agreeing samples, which the default modes already exercise.
constexpr PrecisionModes kDefaults{};
constexpr PrecisionModes with_hierarchical_z_off() {
    PrecisionModes modes;
    modes.hierarchical_z = false;
    return modes;
}
constexpr PrecisionModes with_interpolation(Interpolation interpolation) {
    PrecisionModes modes;
    modes.interpolation = interpolation;
    return modes;
}
constexpr PrecisionModes with_depth(DepthFormat depth) {
    PrecisionModes modes;
    modes.depth = depth;
    return modes;
}
constexpr ModeVariant kModeVariants[] = {
    {"default", kDefaults},
    {"hierarchical z off", with_hierarchical_z_off()},
    {"affine", with_interpolation(Interpolation::affine)},
    {"depth float", with_depth(DepthFormat::float_z)},
    {"depth fixed24", with_depth(DepthFormat::fixed24)},
};

// Up to kMaxExtremeVertices vertices replaced by positions from raw float bits or the table of extremes, and the
// whole scene (eye, target, vertices, lights) moved by an offset drawn the same way; false when nothing was drawn.
bool draw_extremes(FuzzedDataProvider& input, Scene& scene) {
    std::vector<glm::vec3>& positions = mutable_data(scene.meshes.front()).positions;
    const int vertices = input.ConsumeIntegralInRange(0, kMaxExtremeVertices);
    for (int i = 0; i < vertices; ++i)
        positions[input.ConsumeIntegralInRange<size_t>(0, positions.size() - 1)] =
            fuzzed_finite_vec3(input, -10.0f, 10.0f, true);
    const bool moved = input.ConsumeBool();
    if (moved) {
        const glm::vec3 offset = fuzzed_finite_vec3(input, -1e6f, 1e6f, true);
        scene.camera.eye += offset;
        scene.camera.target += offset;
        for (glm::vec3& p : positions) p += offset;
        for (Light& light : scene.lights) light.position += offset;
    }
    return vertices > 0 || moved;
}

// An orthographic camera in place of the drawn perspective one: its view volume as high as the perspective one's
// frustum at the target, or a drawn height; near at 0 or as drawn.
void draw_orthographic(FuzzedDataProvider& input, Scene& scene) {
    Camera& camera = scene.camera;
    constexpr float kHeights[] = {0.0f, 0.5f, 4.0f, 40.0f};  // 0: the frustum's height at the target
    const double distance = glm::length(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    const double framing = 2.0 * distance * std::tan(double(camera.fov_y_degrees) * (M_PI / 360.0));
    const float drawn = input.PickValueInArray(kHeights);
    camera.ortho_height = drawn > 0.0f ? drawn : static_cast<float>(framing);
    if (input.ConsumeBool()) camera.near = 0.0f;
    camera.projection = Projection::orthographic;
}

// Directional and spot lights in place of the drawn point lights: each light's type, direction and cone drawn.
void draw_light_types(FuzzedDataProvider& input, Scene& scene) {
    for (Light& light : scene.lights) {
        constexpr LightType kTypes[] = {LightType::point, LightType::directional, LightType::spot};
        light.type = input.PickValueInArray(kTypes);
        light.direction = fuzzed_finite_vec3(input, -1.0f, 1.0f, false);
        light.outer_cone = input.ConsumeFloatingPointInRange(0.05f, 1.5707963f);
        light.inner_cone = input.ConsumeFloatingPointInRange(0.0f, light.outer_cone * 0.99f);
        if (light.type == LightType::directional) light.attenuate = false;
    }
}

// A texture whose alpha every mesh's material reads: a w x h RGBA image (1 to 4 texels a side) from the input, as a
// PNG (decoded by raster and, on its own, by the oracle), each triangle's corners' texture coordinates in [-2, 2],
// the filter (nearest, bilinear or trilinear) and wrap, and each material's opacity and cut-out or none.
void draw_alpha_texture(FuzzedDataProvider& input, Scene& scene) {
    Image image(input.ConsumeIntegralInRange(1, 4), input.ConsumeIntegralInRange(1, 4), 4);
    for (uint8_t& byte : image.pixels) byte = input.ConsumeIntegral<uint8_t>();
    const std::vector<uint8_t> png = encode_image(image, ImageFormat::png, 1);
    TextureBinding binding;
    binding.path = "fuzzed.png";
    binding.encoded = std::make_shared<const std::string>(png.begin(), png.end());
    binding.texture = std::make_shared<const Texture>(decode_texture(*binding.encoded, binding.path));
    binding.alpha_texture =
        std::make_shared<const Texture>(decode_texture(*binding.encoded, binding.path, TextureChannels::alpha));
    binding.reads_alpha = true;
    constexpr TextureFilter kFilters[] = {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear};
    constexpr TextureWrap kWraps[] = {TextureWrap::repeat, TextureWrap::clamp, TextureWrap::mirror};
    binding.filter = input.PickValueInArray(kFilters);
    binding.wrap = input.PickValueInArray(kWraps);
    for (SceneMesh& mesh : scene.meshes) {
        MeshData& data = mutable_data(mesh);
        data.corner_uvs.resize(data.triangles.size());
        for (TriangleUvs& corners : data.corner_uvs)
            for (glm::vec2& uv : corners.uv)
                uv = {input.ConsumeFloatingPointInRange(-2.0f, 2.0f), input.ConsumeFloatingPointInRange(-2.0f, 2.0f)};
        for_each_material(mesh, [&](Material& material) {
            material.texture = binding;
            material.opacity = input.ConsumeFloatingPointInRange(0.0f, 1.0f);
            if (input.ConsumeBool()) material.alpha_cutoff = input.ConsumeFloatingPointInRange(0.0f, 1.0f);
        });
    }
    build_needed_mip_chains(scene);
}

// Every triangle's radius is under kMaxExtremeRadius (the oracle's own reference geometry, as it compares with).
bool bounds_say_something(const Scene& scene) {
    const oracle::ReferenceGeometry reference(scene, oracle::oracle_scene(scene));
    for (uint32_t id = 0; id < reference.size(); ++id)
        if (!(reference.polygon(id).radius < kMaxExtremeRadius)) return false;
    return true;
}

}  // namespace

std::optional<DifferentialCase> differential_case(const uint8_t* data, size_t size) {
    FuzzedDataProvider input(data, size);
    FuzzedSceneLimits limits;
    limits.max_side = 32;
    limits.max_grid_side = 2;
    limits.max_triangles = 8;
    // Ordinary positions in the scene itself: extreme ones come after (draw_extremes), so that the inputs saved
    // before they existed still make the same scenes. The lens (fov, near, far) always takes extremes.
    limits.extreme_coordinates = false;
    // The precision modes come from kModeVariants below, not from fuzzed_scene's own draw of every mode.
    limits.precision_modes = false;
    DifferentialCase result;
    result.scene = fuzzed_scene(input, limits);
    Scene& scene = result.scene;
    // Drawn last, so that an input that runs out first keeps the defaults.
    const ModeVariant& variant = input.PickValueInArray(kModeVariants);
    scene.settings.modes = variant.modes;
    result.modes = variant.name;
    result.extreme = draw_extremes(input, scene);
    // Drawn after everything else, so that the inputs saved before orthographic cameras existed keep their scenes.
    if (input.ConsumeBool()) draw_orthographic(input, scene);
    if (input.ConsumeBool()) draw_light_types(input, scene);
    if (input.ConsumeBool()) draw_alpha_texture(input, scene);
    const RenderSettings& settings = scene.settings;
    if (uint64_t(settings.width) * uint64_t(settings.height) * uint64_t(settings.samples) > kMaxFrameSamples)
        return std::nullopt;
    try {
        validate_scene(scene);
    } catch (const InputError&) {
        return std::nullopt;
    }
    // Known limitation, skipped here: raster works in float clip space, so a projection that magnifies by more
    // than ~1e3 on either axis (a field of view under ~0.1 degree or an orthographic height under 2e-3, or a narrow
    // image, whose x scale is the focal length over the aspect) amplifies float rounding past the comparator's bounds: at 1e26 the clipped polygon's
    // corners are lost to cancellation (quarter-screen errors), at 6e5 a sliver's barycentrics drift. A non-finite
    // projection is validate_scene's to reject.
    const glm::mat4 projection = projection_matrix(scene.camera, scene.settings.width, scene.settings.height);
    const float magnification = std::max(std::fabs(projection[0][0]), std::fabs(projection[1][1]));
    if (std::isfinite(magnification) && magnification > kMaxMagnification) return std::nullopt;
    if (result.extreme && !bounds_say_something(scene)) return std::nullopt;
    return result;
}

}  // namespace raster::fuzz
