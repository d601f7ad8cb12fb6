// Scenes from fuzzer bytes: floats from ordinary ranges, raw bits and extremes; cameras, settings and triangles.
#include "fuzz/fuzzed_scene.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>

#include "raster/core/conventions.h"

namespace raster::fuzz {
namespace {

constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr int kSmallSide = 16;

// Values at the edges of float and of the conventions: signed zeros, the smallest normal and subnormal, the
// largest finite, where integer spacing changes (2^23, 2^24), near = 1e-6 and far = 1e9, and the non-finite.
constexpr float kExtremes[] = {
    0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 2.0f, 1e-6f, -1e-6f, 1e9f, -1e9f, 1e30f, -1e30f, 1e-30f, 3e38f,
    kFloatMax, -kFloatMax, std::numeric_limits<float>::min(), -std::numeric_limits<float>::min(),
    std::numeric_limits<float>::denorm_min(), 16777216.0f, 8388607.5f, 0.1f, 100.0f,
    std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
    std::numeric_limits<float>::quiet_NaN()};

Camera fuzzed_camera(FuzzedDataProvider& input, bool extreme_coordinates) {
    Camera camera;
    camera.eye = fuzzed_finite_vec3(input, -10.0f, 10.0f, extreme_coordinates);
    camera.target =
        input.ConsumeBool() ? glm::vec3(0.0f) : fuzzed_finite_vec3(input, -10.0f, 10.0f, extreme_coordinates);
    if (input.ConsumeBool()) camera.up = fuzzed_finite_vec3(input, -1.0f, 1.0f, extreme_coordinates);
    camera.fov_y_degrees = input.ConsumeBool() ? input.ConsumeFloatingPointInRange(0.5f, 179.5f)
                                               : fuzzed_float(input, 0.0f, 180.0f, true);
    constexpr float kNears[] = {1e-6f, 1e-3f, 0.1f, 1.0f};
    constexpr float kFars[] = {10.0f, 100.0f, 1e4f, 1e9f};
    camera.near = input.ConsumeBool() ? input.PickValueInArray(kNears) : fuzzed_float(input, 1e-6f, 10.0f, true);
    camera.far = input.ConsumeBool() ? input.PickValueInArray(kFars) : fuzzed_float(input, 10.0f, 1e4f, true);
    return camera;
}

RenderSettings fuzzed_settings(FuzzedDataProvider& input, const FuzzedSceneLimits& limits) {
    RenderSettings settings;
    // Half the sides are at most 16 pixels: small frames keep the fuzzer fast, and edge cases live there too.
    settings.width = input.ConsumeIntegralInRange(1, input.ConsumeBool() ? kSmallSide : limits.max_side);
    settings.height = input.ConsumeIntegralInRange(1, input.ConsumeBool() ? kSmallSide : limits.max_side);
    if (input.ConsumeBool()) {
        settings.pattern = SamplePattern::grid;
        const int side = input.ConsumeIntegralInRange(1, limits.max_grid_side);
        settings.samples = side * side;
    } else {
        settings.pattern = SamplePattern::standard;
        constexpr int kStandardCounts[] = {1, 2, 4, 8, 16};
        settings.samples = input.PickValueInArray(kStandardCounts);
    }
    settings.msaa = input.ConsumeBool();
    constexpr ShadingMode kModes[] = {ShadingMode::unlit, ShadingMode::flat, ShadingMode::gouraud, ShadingMode::phong,
                                      ShadingMode::blinn_phong};
    settings.shading = input.PickValueInArray(kModes);
    settings.cull_backfaces = input.ConsumeBool();
    settings.snap_bits = input.ConsumeIntegralInRange(kMinSnapBits, kMaxSnapBits);
    return settings;
}

SceneMesh fuzzed_triangles(FuzzedDataProvider& input, const FuzzedSceneLimits& limits) {
    SceneMesh mesh;
    mesh.source = "fuzzed triangles";
    const int count = input.ConsumeIntegralInRange(1, limits.max_triangles);
    for (int t = 0; t < count; ++t) {
        for (int corner = 0; corner < 3; ++corner)
            mutable_data(mesh).positions.push_back(fuzzed_finite_vec3(input, -10.0f, 10.0f, limits.extreme_coordinates));
        const auto first = static_cast<uint32_t>(3 * t);
        mutable_data(mesh).triangles.push_back({{first, first + 1, first + 2}});
    }
    return mesh;
}

}  // namespace

float fuzzed_float(FuzzedDataProvider& input, float low, float high, bool extreme_floats) {
    switch (extreme_floats ? input.ConsumeIntegralInRange(0, 2) : 2) {
        case 0: return input.PickValueInArray(kExtremes);
        case 1: return std::bit_cast<float>(input.ConsumeIntegral<uint32_t>());
        default: return input.ConsumeFloatingPointInRange(low, high);
    }
}

float fuzzed_finite_float(FuzzedDataProvider& input, float low, float high, bool extreme_floats) {
    const float value = fuzzed_float(input, low, high, extreme_floats);
    return std::isfinite(value) ? value : std::copysign(kFloatMax, value);
}

glm::vec3 fuzzed_finite_vec3(FuzzedDataProvider& input, float low, float high, bool extreme_floats) {
    const float x = fuzzed_finite_float(input, low, high, extreme_floats);
    const float y = fuzzed_finite_float(input, low, high, extreme_floats);
    return {x, y, fuzzed_finite_float(input, low, high, extreme_floats)};
}

Scene fuzzed_scene(FuzzedDataProvider& input, const FuzzedSceneLimits& limits) {
    Scene scene;
    scene.path = "fuzzed scene";
    scene.settings = fuzzed_settings(input, limits);
    scene.camera = fuzzed_camera(input, limits.extreme_coordinates);
    const int lights = input.ConsumeIntegralInRange(0, 2);
    for (int i = 0; i < lights; ++i) {
        Light light;
        light.position = fuzzed_finite_vec3(input, -10.0f, 10.0f, limits.extreme_coordinates);
        light.attenuate = input.ConsumeBool();
        scene.lights.push_back(light);
    }
    scene.meshes.push_back(fuzzed_triangles(input, limits));
    if (limits.precision_modes) {
        // The first entry of each table is the default, what an exhausted input picks.
        PrecisionModes& modes = scene.settings.modes;
        modes.edges = input.PickValueInArray({EdgeArithmetic::fixed, EdgeArithmetic::float32});
        modes.interpolation = input.PickValueInArray({Interpolation::perspective, Interpolation::affine});
        modes.depth = input.PickValueInArray({DepthFormat::reversed_z, DepthFormat::float_z, DepthFormat::fixed24});
        modes.clipping = input.PickValueInArray({Clipping::full, Clipping::guard_band});
        modes.hierarchical_z = !input.ConsumeBool();
    }
    return scene;
}

std::string describe_scene(const Scene& scene) {
    std::string text;
    char line[512];
    auto vec = [](const glm::vec3& v) {
        char buffer[128];
        std::snprintf(buffer, sizeof buffer, "[%a, %a, %a]", double(v.x), double(v.y), double(v.z));
        return std::string(buffer);
    };
    const RenderSettings& s = scene.settings;
    std::snprintf(line, sizeof line,
                  "  image %dx%d, %d samples (%s), %s, msaa %d, cull %d, snap bits %d, edges %s, %s, depth %s, "
                  "clipping %s, hierarchical z %d\n",
                  s.width, s.height, s.samples, to_string(s.pattern), to_string(s.shading), int{s.msaa},
                  int{s.cull_backfaces}, s.snap_bits, to_string(s.modes.edges), to_string(s.modes.interpolation),
                  to_string(s.modes.depth), to_string(s.modes.clipping), int{s.modes.hierarchical_z});
    text += line;
    const Camera& c = scene.camera;
    text += "  camera eye " + vec(c.eye) + " target " + vec(c.target) + " up " + vec(c.up);
    if (c.projection == Projection::orthographic)
        std::snprintf(line, sizeof line, " orthographic height %a near %a far %a\n", double(c.ortho_height),
                      double(c.near), double(c.far));
    else
        std::snprintf(line, sizeof line, " fov %a near %a far %a\n", double(c.fov_y_degrees), double(c.near),
                      double(c.far));
    text += line;
    for (const Light& light : scene.lights) {
        if (light.type != LightType::directional) text += "  light at " + vec(light.position);
        if (light.type != LightType::point) text += "  light along " + vec(light.direction);
        if (light.type == LightType::spot) {
            std::snprintf(line, sizeof line, " cone %a to %a", double(light.inner_cone), double(light.outer_cone));
            text += line;
        }
        text += "\n";
    }
    for (const SceneMesh& mesh : scene.meshes) {
        const Material& m = mesh.material;
        std::snprintf(line, sizeof line, "  mesh '%s': opacity %a", mesh.source.c_str(), double(m.opacity));
        text += line;
        if (m.alpha_cutoff) {
            std::snprintf(line, sizeof line, ", cut-off %a", double(*m.alpha_cutoff));
            text += line;
        }
        if (m.texture) {
            std::snprintf(line, sizeof line, ", texture %s %s %s%s", m.texture->path.c_str(), to_string(m.texture->filter),
                          to_string(m.texture->wrap), m.texture->reads_alpha ? " with alpha" : "");
            text += line;
        }
        text += "\n";
        for (size_t i = 0; i < mesh.data->triangles.size(); ++i) {
            const TriangleIndices& t = mesh.data->triangles[i];
            text += "    " + vec(mesh.data->positions[t.v[0]]) + " " + vec(mesh.data->positions[t.v[1]]) + " " +
                    vec(mesh.data->positions[t.v[2]]);
            if (i < mesh.data->corner_uvs.size())
                for (const glm::vec2& uv : mesh.data->corner_uvs[i].uv) {
                    std::snprintf(line, sizeof line, " (%a, %a)", double(uv.x), double(uv.y));
                    text += line;
                }
            text += "\n";
        }
    }
    return text;
}

}  // namespace raster::fuzz
