// The scene every loader produces and every renderer reads: camera, settings, lights, meshes and materials.
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/core/conventions.h"
#include "raster/scene/mesh.h"
#include "raster/scene/precision_modes.h"

namespace raster {

enum class ShadingMode {
    unlit,        // face colour or perspective-correct interpolated vertex colour; no normals, no lights
    flat,         // Blinn-Phong once per triangle, with the face normal at the centroid
    gouraud,      // Blinn-Phong per vertex, colours interpolated
    phong,        // per-sample lighting with interpolated normals, Phong's reflection-vector specular (r.v)^e
    blinn_phong,  // per-sample lighting with interpolated normals, Blinn's half-vector specular (n.h)^e
};

enum class SamplePattern {
    standard,  // the Vulkan standard positions for 1, 2, 4, 8 and 16 samples
    grid,      // an N x N regular grid; samples must be a perfect square
};

// How the camera maps view space to clip space.
struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_degrees = 45.0f;  // full vertical field of view
    float near = 0.1f;
    float far = 100.0f;
};

// Point light; colour is linear RGB. With `attenuate`, the light's contribution is divided by r^2.
struct Light {
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    bool attenuate = false;
};

// Blinn-Phong coefficients, each RGB. The base colour multiplies ambient and diffuse; specular is the highlight's
// own colour. The base colour is the mesh's face colour, else its interpolated vertex colour, else `color`.
struct Material {
    glm::vec3 color{1.0f};
    glm::vec3 ambient{0.1f};
    glm::vec3 diffuse{0.7f};
    glm::vec3 specular{0.2f};
    float exponent = 32.0f;
};

// One mesh placed in the world: its data in object space, the model matrix and its material.
struct SceneMesh {
    MeshData data;
    glm::mat4 model{1.0f};
    Material material;
    std::string source;  // the file it came from, or "inline"
};

// How to render: everything a command-line flag can override.
struct RenderSettings {
    int width = 640;
    int height = 480;
    glm::vec3 background{0.0f};
    int samples = 1;
    SamplePattern pattern = SamplePattern::standard;
    bool msaa = false;  // shade once per pixel per triangle instead of once per sample
    ShadingMode shading = ShadingMode::blinn_phong;
    bool cull_backfaces = false;
    int snap_bits = kDefaultSnapBits;
    glm::vec3 ambient_light{1.0f};  // multiplies every material's ambient term
    PrecisionModes modes;           // edge arithmetic, interpolation, depth format, clipping, hierarchical Z
};

struct Scene {
    std::string path;  // the scene file, for messages
    RenderSettings settings;
    Camera camera;
    std::vector<Light> lights;
    std::vector<SceneMesh> meshes;
};

const char* to_string(ShadingMode mode);
const char* to_string(SamplePattern pattern);
// Parse a shading or pattern name as the CLI and the scene files spell it; false when unknown.
bool parse_shading_mode(const std::string& name, ShadingMode& out);
bool parse_sample_pattern(const std::string& name, SamplePattern& out);

// Total triangles over all meshes: the scene's triangle ids run from 0 to this, mesh by mesh, in order.
size_t triangle_count(const Scene& scene);

}  // namespace raster
