// Seed 000 (EECS 498 homework 1) YAML configs: the five tasks, the document's own matrices, and the scene each renders.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/formats/document_reader.h"
#include "raster/formats/scene_formats.h"
#include "raster/scene/scene.h"

namespace raster {

enum class Seed000Task { triangle, transform, transform_test, shading_depth, shading };
const char* to_string(Seed000Task task);

// The document's camera (its section 2.1). width and height are the extents of the view volume on the near plane
// (the l, r, b, t of its orthographic step); nearClip and farClip are positive distances.
struct Seed000Camera {
    glm::vec3 pos{0.0f};
    glm::vec3 look_at{0.0f, 0.0f, -1.0f};  // a point the camera looks at, not a direction
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float width = 0.0f;
    float height = 0.0f;
    float near_clip = 0.0f;
    float far_clip = 0.0f;
};

// One object's model transform: M = T * R * S (scale, then rotate about the object's origin, then translate).
struct Seed000Transform {
    glm::vec4 rotation_wxyz{1.0f, 0.0f, 0.0f, 0.0f};  // quaternion w, x, y, z; normalised when used
    glm::vec3 translation{0.0f};
    glm::vec3 scale{1.0f};
};

// A light as the document writes it: colour in 0..255, intensity divided by r^2.
struct Seed000Light {
    glm::vec3 pos{0.0f};
    float intensity = 1.0f;
    glm::vec3 color_255{255.0f};
    bool shadows = false;  // raster's extension (docs/seeds.md "Seed 000"): the document's shadow-map extra
};

// Everything a config says, read and checked; paths are resolved against the config file's folder.
struct Seed000Config {
    Seed000Task task = Seed000Task::triangle;
    int width = 0;
    int height = 0;
    int samples = 1;                 // 1 with `antialias: none` or no antialias key
    std::filesystem::path obj;       // `obj` + ".obj"; empty when a transform-test names none
    std::filesystem::path output;    // `output` + ".png" (default name "output")
    std::optional<Seed000Camera> camera;           // required by every task except triangle
    std::vector<Seed000Transform> transforms;      // one per object of the OBJ, in order
    float exponent = 1.0f;                         // shading only
    glm::vec3 ambient_255{0.0f};                   // shading only
    std::vector<Seed000Light> lights;              // shading only
    glm::dvec3 input{0.0};                         // transform-test only
    glm::dvec4 expected{0.0};                      // transform-test only
};

// The config a parsed document holds (task, output, camera, transforms, lights, transform-test values), and the scene
// its task draws (`root` for the nodes a problem is blamed on). Internal to the scene loader.
Seed000Config read_seed000_config(const Node& root, const DocumentReader& reader);
void read_seed000_scene(const Node& root, const DocumentReader& reader, const Seed000Config& config,
                        const MeshFileLoader& load_mesh, Scene& scene);

// Reads and checks a config file. Throws InputError with file, line and column.
Seed000Config load_seed000_config(const std::filesystem::path& path);

// The document's matrices, in double. The projection is the one its section 2.2.3 derives, with the near and far
// planes at z = -nearClip and z = -farClip: after the divide, x and y span [-1, 1] on the near-plane rectangle
// and z is +1 on the near plane and -1 on the far plane (nearer is larger; it is OpenGL's NDC z negated).
glm::dmat4 seed000_model_matrix(const Seed000Transform& transform);
glm::dmat4 seed000_view_matrix(const Seed000Camera& camera);
glm::dmat4 seed000_projection_matrix(const Seed000Camera& camera);
// Canonical x, y in [-1, 1] to pixels with the origin at the lower left (eq. (1)); z is kept (scale 1).
glm::dmat4 seed000_screen_matrix(int width, int height);

// transform-test: `input` through screen * projection * view * model (the first transform, or identity when the
// config has none), divided by w, so w is 1. Matches when every component is within
// kSeed000TestAbsoluteTolerance + kSeed000TestRelativeTolerance * |expected|.
inline constexpr double kSeed000TestAbsoluteTolerance = 1e-3;  // the document prints 3 decimals: 5e-4 rounding
inline constexpr double kSeed000TestRelativeTolerance = 1e-5;  // float inputs at pixel scale
struct Seed000TestResult {
    glm::dvec4 transformed{0.0};
    glm::dvec4 expected{0.0};
    bool match = false;
};
Seed000TestResult run_seed000_transform_test(const Seed000Config& config);
// The lines `raster render` prints for a transform-test: transformed, expected, and the verdict.
std::string format_seed000_test_result(const Seed000TestResult& result);

}  // namespace raster
