// Scene validation: the limits and the camera checks every renderer relies on, whatever format the scene came from.
#include "raster/scene/validation.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include <glm/geometric.hpp>

#include "raster/core/errors.h"
#include "raster/scene/sample_counts.h"

namespace raster {

uint64_t frame_bytes(const RenderSettings& settings) {
    // Per sample: visibility buffer (4 id + 12 barycentrics + 4 depth) + z-buffer 4 + winner 4.
    // Per pixel: up to 4 bytes of output image.
    const uint64_t pixels = uint64_t(std::max(settings.width, 0)) * uint64_t(std::max(settings.height, 0));
    return pixels * uint64_t(std::max(settings.samples, 0)) * 28u + pixels * 4u;
}

uint64_t shadow_map_bytes(const Scene& scene) {
    const uint64_t side = uint64_t(std::max(scene.settings.shadows.resolution, 0));
    uint64_t lights = 0;
    for (const Light& light : scene.lights) lights += light.shadows;
    return lights * 6u * side * side * sizeof(float);
}

namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool fits_float(double value) { return std::isfinite(static_cast<float>(value)); }

// What is wrong with the projection raster stores in float (a reversed-Z perspective, docs/conventions.md "Depth"):
// its scale terms focal / aspect and focal, with focal = 1 / tan(fov / 2), overflow for a field of
// view too narrow, and its depth terms n / (f - n) and n f / (f - n) for a near and far too close for their size.
// Empty when every term is a finite float. The scene checks only that the numbers fit; the matrix itself is built
// in raster/transform, which the scene does not see.
std::string projection_problem(const Camera& camera, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    char text[64];
    if (camera.projection == Projection::orthographic) {
        // Its scale terms 2 / (height aspect) and 2 / height, and depth terms 1 / (f - n) and f / (f - n).
        const double scale = 2.0 / static_cast<double>(camera.ortho_height);
        if (!fits_float(scale) || !fits_float(scale / aspect)) {
            std::snprintf(text, sizeof text, "%g", double(camera.ortho_height));
            return std::string("orthographic camera height ") + text + " is too small: its projection overflows float";
        }
        const double n = camera.near, f = camera.far;
        if (!fits_float(1.0 / (f - n)) || !fits_float(f / (f - n))) {
            std::snprintf(text, sizeof text, "%.9g and %.9g", n, f);
            return std::string("camera near and far (") + text +
                   ") are too close for their size: the projection's depth terms overflow float";
        }
        return "";
    }
    const double focal = 1.0 / std::tan(static_cast<double>(camera.fov_y_degrees) * (M_PI / 360.0));
    if (!fits_float(focal) || !fits_float(focal / aspect)) {
        std::snprintf(text, sizeof text, "%g", double(camera.fov_y_degrees));
        return std::string("camera field of view ") + text + " degrees is too narrow: its projection overflows float";
    }
    const double n = camera.near, f = camera.far;
    if (!fits_float(n / (f - n)) || !fits_float(n * f / (f - n))) {
        std::snprintf(text, sizeof text, "%.9g and %.9g", n, f);
        return std::string("camera near and far (") + text +
               ") are too close for their size: the projection's depth terms overflow float";
    }
    return "";
}

}  // namespace

std::string settings_problem(const RenderSettings& s) {
    if (s.width < 1 || s.height < 1 || s.width > kMaxImageDimension || s.height > kMaxImageDimension)
        return "image size " + std::to_string(s.width) + "x" + std::to_string(s.height) + " is outside 1.." +
               std::to_string(kMaxImageDimension) + " per side";
    if (std::string error = sample_count_error(s.samples, s.pattern); !error.empty()) return error;
    if (!valid_resolution_divisor(s.resolution_divisor))
        return "resolution divisor must be 1, 2 or 4, got " + std::to_string(s.resolution_divisor);
    if (s.width % s.resolution_divisor != 0 || s.height % s.resolution_divisor != 0)
        return "resolution divisor " + std::to_string(s.resolution_divisor) + " must divide the image size " +
               std::to_string(s.width) + "x" + std::to_string(s.height);
    if (frame_bytes(s) > kMaxFrameBytes)
        return "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " image with " +
               std::to_string(s.samples) + " samples needs " + std::to_string(frame_bytes(s) >> 20) +
               " MiB of frame buffers, over the " + std::to_string(kMaxFrameBytes >> 20) + " MiB cap";
    if (s.snap_bits < kMinSnapBits || s.snap_bits > kMaxSnapBits)
        return "snap bits must be " + std::to_string(kMinSnapBits) + ".." + std::to_string(kMaxSnapBits);
    if (!finite3(s.background) || !finite3(s.ambient_light)) return "background and ambient light must be finite";
    if (s.transparency.max_fragments < kMinFragments || s.transparency.max_fragments > kMaxFragments)
        return "transparency max_fragments must be " + std::to_string(kMinFragments) + ".." +
               std::to_string(kMaxFragments) + ", got " + std::to_string(s.transparency.max_fragments);
    return shadow_settings_problem(s.shadows);
}

std::string light_problem(const Light& light) {
    if (!finite3(light.position) || !finite3(light.color) || !std::isfinite(light.intensity))
        return "light position, colour and intensity must be finite";
    if (light.type == LightType::point) return "";
    // Raster normalises the direction in float: its squared length must be a finite normal float.
    const float length_squared = glm::dot(light.direction, light.direction);
    if (!finite3(light.direction) || !(length_squared >= std::numeric_limits<float>::min()) || !std::isfinite(length_squared))
        return "light direction must be finite, not zero, and its squared length a normal float";
    if (light.type == LightType::directional && light.attenuate)
        return "a directional light is never attenuated (it is infinitely far: no distance to divide by)";
    if (light.type == LightType::directional && light.shadows)
        return "a directional light casts no shadows (raster's shadow maps are cubes around a light's position)";
    constexpr float kRightAngle = 1.5707964f;  // pi / 2 rounded up to float
    if (light.type == LightType::spot &&
        !(light.inner_cone >= 0.0f && light.inner_cone < light.outer_cone && light.outer_cone <= kRightAngle))
        return "a spot light's cone angles must be 0 <= inner_cone < outer_cone <= 90 degrees";
    return "";
}

std::string shadow_settings_problem(const ShadowSettings& s) {
    if (s.resolution < kMinShadowResolution || s.resolution > kMaxShadowResolution)
        return "shadow map resolution must be " + std::to_string(kMinShadowResolution) + ".." +
               std::to_string(kMaxShadowResolution) + ", got " + std::to_string(s.resolution);
    if (!(s.bias >= 0.0f && s.bias <= 1.0f)) return "shadow bias must be in [0, 1], got " + std::to_string(s.bias);
    if (!(s.slope_bias >= 0.0f && s.slope_bias <= 64.0f))
        return "shadow slope bias must be in [0, 64], got " + std::to_string(s.slope_bias);
    if (s.pcf != 1 && s.pcf != 3 && s.pcf != 5)
        return "shadow pcf must be 1, 3 or 5 (texels per side of the filter), got " + std::to_string(s.pcf);
    return "";
}

std::optional<CameraProblem> camera_problem(const Camera& c) {
    if (!finite3(c.eye) || !finite3(c.target) || !finite3(c.up))
        return CameraProblem{!finite3(c.eye) ? CameraField::eye : !finite3(c.target) ? CameraField::target : CameraField::up,
                             "camera eye, target and up must be finite"};
    const bool orthographic = c.projection == Projection::orthographic;
    // An orthographic camera's w is 1 and its near plane a plane of z: near may be 0.
    if (orthographic && !(c.near >= 0.0f && std::isfinite(c.near)))
        return CameraProblem{CameraField::near, "orthographic camera near must be >= 0, got " + std::to_string(c.near)};
    if (!orthographic && (!(c.near > 0.0f) || !std::isfinite(c.near)))
        return CameraProblem{CameraField::near, "camera near must be > 0, got " + std::to_string(c.near)};
    // Setup stores 1 / w in float, and w goes down to near: a subnormal near would make it infinite.
    if (!orthographic && c.near < std::numeric_limits<float>::min()) {
        char near[32];
        std::snprintf(near, sizeof near, "%g", double(c.near));
        return CameraProblem{CameraField::near,
                             std::string("camera near must be > 0 and a normal float (at least 1.17549e-38), got ") + near};
    }
    if (!(c.far > c.near) || !std::isfinite(c.far))
        return CameraProblem{CameraField::far, "camera far (" + std::to_string(c.far) +
                                                   ") must be finite and greater than near (" + std::to_string(c.near) + ")"};
    // And w goes up to far: past 2^126, 1 / far is a subnormal float, whose lost bits can carry a view depth at the
    // far plane past the largest float (the raster fuzz target found infinite view depths there).
    if (c.far > 0x1p126f) {
        char far[32];
        std::snprintf(far, sizeof far, "%g", double(c.far));
        return CameraProblem{CameraField::far, std::string("camera far must be at most 8.50706e+37 (1 / far a normal "
                                                           "float), got ") + far};
    }
    if (orthographic && !(c.ortho_height > 0.0f && std::isfinite(c.ortho_height)))
        return CameraProblem{CameraField::ortho_height,
                             "orthographic camera height must be finite and > 0, got " + std::to_string(c.ortho_height)};
    if (!orthographic && !(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
        return CameraProblem{CameraField::fov,
                             "camera field of view must be in (0, 180) degrees, got " + std::to_string(c.fov_y_degrees)};
    const glm::vec3 view = c.target - c.eye;
    if (!(glm::length(view) > 0.0f)) return CameraProblem{CameraField::target, "camera eye and target are the same point"};
    const glm::vec3 side = glm::cross(glm::normalize(view), c.up);
    if (!(glm::length(side) > 1e-6f * glm::length(c.up)) || !(glm::length(c.up) > 0.0f))
        return CameraProblem{CameraField::up, "camera up is parallel to the view direction (or zero)"};
    return std::nullopt;
}

namespace {

std::optional<std::string> step_problem(const TransformStep& step) {
    return std::visit(
        [&](const auto& s) -> std::optional<std::string> {
            using Step = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<Step, TranslateStep>) {
                if (!finite3(s.offset)) return "a translate step is not finite";
            } else if constexpr (std::is_same_v<Step, ScaleStep>) {
                if (!finite3(s.factors)) return "a scale step is not finite";
            } else if constexpr (std::is_same_v<Step, RotateStep>) {
                if (!std::isfinite(s.degrees) || !finite3(s.axis)) return "a rotate step is not finite";
                if (!(glm::length(glm::dvec3(s.axis)) > 0.0)) return "a rotate step's axis is zero";
            } else if constexpr (std::is_same_v<Step, QuaternionStep>) {
                const glm::dvec4 q(s.wxyz);
                if (!std::isfinite(glm::dot(q, q))) return "a quaternion step is not finite";
                if (!(glm::dot(q, q) > 0.0)) return "a quaternion step is zero";
            } else if constexpr (std::is_same_v<Step, LookAtStep>) {
                if (const auto problem = camera_problem(look_at_camera(s)))
                    return "a lookat step: " + problem->message.substr(problem->message.find(' ') + 1);
            } else {
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r)
                        if (!std::isfinite(s.matrix[c][r])) return "a matrix step is not finite";
            }
            return std::nullopt;
        },
        step);
}


}  // namespace

std::optional<std::string> model_transform_problem(const ModelTransform& transform) {
    for (const auto* chain : {&transform.steps, &transform.then_inverse_of})
        for (const TransformStep& step : *chain)
            if (auto problem = step_problem(step)) return problem;
    for (const auto* chain : {&transform.steps, &transform.then_inverse_of})
        if (const double bound = model_magnitude_bound(*chain); !(bound <= kMaxModelMagnitude)) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "the model transform's steps multiply to a matrix whose entries may reach %g, beyond the "
                          "%g that float arithmetic can carry through the frame",
                          bound, kMaxModelMagnitude);
            return std::string(text);
        }
    return std::nullopt;
}


void validate_scene(const Scene& scene) {
    auto fail = [&](const std::string& message) { throw InputError(scene.path, 0, 0, message); };
    if (std::string problem = settings_problem(scene.settings); !problem.empty()) fail(problem);
    if (const auto problem = camera_problem(scene.camera)) fail(problem->message);
    // An infinite projection draws nothing, and camera rays (the oracle's) would be NaN.
    if (std::string problem = projection_problem(scene.camera, scene.settings.width, scene.settings.height);
        !problem.empty())
        fail(problem);
    if (triangle_count(scene) > kMaxSceneTriangles)
        fail("too many triangles: " + std::to_string(triangle_count(scene)) + " (limit " +
             std::to_string(kMaxSceneTriangles) + ")");
    if (frame_bytes(scene.settings) + shadow_map_bytes(scene) > kMaxFrameBytes)
        fail("the frame buffers (" + std::to_string(frame_bytes(scene.settings) >> 20) + " MiB) and the shadow maps (" +
             std::to_string(shadow_map_bytes(scene) >> 20) + " MiB) need more than the " +
             std::to_string(kMaxFrameBytes >> 20) + " MiB cap (lower the shadow map resolution)");

    for (const Light& light : scene.lights)
        if (std::string problem = light_problem(light); !problem.empty()) fail(problem);
    for (const SceneMesh& mesh : scene.meshes) {
        const MeshData& m = *mesh.data;
        for (const glm::vec3& p : m.positions)
            if (!finite3(p)) fail(mesh.source + ": vertex coordinates must be finite");
        for (size_t t = 0; t < m.triangles.size(); ++t)
            for (uint32_t v : m.triangles[t].v)
                if (v >= m.positions.size())
                    fail(mesh.source + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                         " but there are only " + std::to_string(m.positions.size()));
        if (!m.normals.empty() && m.normals.size() != m.positions.size()) fail(mesh.source + ": normals count mismatch");
        if (!m.colors.empty() && m.colors.size() != m.positions.size()) fail(mesh.source + ": colour count mismatch");
        if (!m.face_colors.empty() && m.face_colors.size() != m.triangles.size())
            fail(mesh.source + ": face colour count mismatch");
        if (const auto problem = model_transform_problem(mesh.transform)) fail(mesh.source + ": " + *problem);
        if (!std::isfinite(mesh.material.exponent) || !finite3(mesh.material.ambient) ||
            !finite3(mesh.material.diffuse) || !finite3(mesh.material.specular) || !finite3(mesh.material.color))
            fail(mesh.source + ": material values must be finite");
        for_each_material(mesh, [&](const Material& material) {
            if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
                fail(mesh.source + ": material opacity must be in [0, 1], got " + std::to_string(material.opacity));
            if (material.alpha_cutoff && !(std::isfinite(*material.alpha_cutoff) && *material.alpha_cutoff >= 0.0f))
                fail(mesh.source + ": material alpha cut-off must be finite and at least 0");
            if (material.texture && material.texture->reads_alpha && !material.texture->alpha_texture)
                fail(mesh.source + ": a texture that reads alpha needs its alpha decoded");
        });
    }
}

}  // namespace raster
