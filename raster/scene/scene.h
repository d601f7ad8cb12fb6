// The scene every loader produces and every renderer reads: camera, settings, lights, meshes and materials.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/core/conventions.h"
#include "raster/scene/material.h"
#include "raster/scene/mesh.h"
#include "raster/scene/model_transform.h"
#include "raster/scene/precision_modes.h"

namespace raster {

enum class ShadingMode {
    unlit,        // face colour or perspective-correct interpolated vertex colour; no normals, no lights
    flat,         // Blinn-Phong once per triangle, with the face normal at the centroid
    gouraud,      // Blinn-Phong per vertex, colours interpolated
    phong,        // per-sample lighting with interpolated normals, Phong's reflection-vector specular (r.v)^e
    blinn_phong,  // per-sample lighting with interpolated normals, Blinn's half-vector specular (n.h)^e
    cel,          // per-sample toon shading: n.l quantised into `cel_bands` bands, a hard-edged highlight
    gooch,        // per-sample cool-to-warm shading (Gooch et al. 1998) from the first light, with its highlight
};

enum class SamplePattern {
    standard,  // the Vulkan standard positions for 1, 2, 4, 8 and 16 samples
    grid,      // an N x N regular grid; samples must be a perfect square
};

// How the camera maps view space to clip space.
enum class Projection {
    perspective,   // rays from the eye; fov_y_degrees is the vertical field of view
    orthographic,  // rays parallel to the view direction; ortho_height is the view volume's height
};

// For an orthographic camera, the view volume is the box ortho_height high and ortho_height * aspect wide around
// the line from `eye` towards `target`, from view depth near to far; near may be 0 (docs/conventions.md).
struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_degrees = 45.0f;  // perspective: full vertical field of view
    float near = 0.1f;
    float far = 100.0f;
    Projection projection = Projection::perspective;
    float ortho_height = 2.0f;    // orthographic: the view volume's height in world units (width: height * aspect)
};

// The camera with a look-at step's eye, target and up: the step places an object as that camera's inverse view.
Camera look_at_camera(const LookAtStep& step);

enum class LightType {
    point,        // from `position` in every direction
    directional,  // along `direction` everywhere, from infinitely far: no position, never attenuated
    spot,         // a point light whose cone around `direction` fades from inner_cone to outer_cone
};

// A light; colour is linear RGB (docs/scene-format.md#lights). With `attenuate`, a point or spot light's
// contribution is divided by r^2. With `shadows`, a point or spot light casts shadows through a cube shadow map
// (docs/shadows.md); without, it lights every point it faces.
struct Light {
    glm::vec3 position{0.0f};  // point and spot
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    bool attenuate = false;
    bool shadows = false;
    LightType type = LightType::point;
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // directional and spot: where the light travels (any length but 0)
    float inner_cone = 0.0f;                 // spot: radians from the axis where the fade starts, [0, outer_cone)
    float outer_cone = 0.7853982f;           // spot: radians from the axis where it ends, (inner_cone, pi/2]
};

// A spot light's fade (KHR_lights_punctual): at angle a from the axis its light is scaled by
// clamp(cos(a) * scale + offset, 0, 1)^2, with scale = 1 / max(0.001, cos(inner) - cos(outer)) and
// offset = -cos(outer) * scale, each computed in double and rounded to float once.
struct SpotFade {
    float scale = 1.0f, offset = 0.0f;
};
SpotFade spot_fade(const Light& light);

// Mesh data to share between placements. Always made here (a MeshData, const only through the pointer), so that
// mutable_data may change data no other placement holds in place.
std::shared_ptr<const MeshData> shared_mesh_data(MeshData data);

// One mesh placed in the world: its data in object space, its model transform and its material. The data is shared
// by every placement of one mesh (instancing: a glTF mesh under many nodes, a raster scene's shape placed by many
// nodes), so a mesh placed a thousand times holds its vertices once.
struct SceneMesh {
    std::shared_ptr<const MeshData> data = shared_mesh_data({});
    ModelTransform transform;  // the steps as the file gives them; raster and the oracle each compose them
    Material material;               // every triangle's, unless `parts` gives some another
    std::vector<MaterialPart> parts;  // OBJ usemtl: by increasing first_triangle; empty when one material
    std::string source;  // the file it came from, or "inline"
};

// The mesh data of `mesh` to change in place: its own, copied first when other placements share it.
MeshData& mutable_data(SceneMesh& mesh);

// The material of the mesh's local triangle `triangle`: its part's, or the mesh's.
const Material& material_of(const SceneMesh& mesh, uint32_t triangle);

// Every material a mesh uses, its own first (for checks and loaders that treat them all alike); `Mesh` is
// SceneMesh or const SceneMesh, and the visit gets the materials as the mesh holds them.
template <typename Mesh, typename Visit>
void for_each_material(Mesh& mesh, Visit visit) {
    visit(mesh.material);
    for (auto& part : mesh.parts) visit(part.material);
}

// Gooch et al. 1998's cool-to-warm tones: k_cool = (0, 0, blue) + alpha k_d, k_warm = (yellow, yellow, 0) + beta k_d,
// where k_d is the base colour times the material's diffuse; the paper's suggested values are the defaults.
struct GoochTones {
    float blue = 0.4f;
    float yellow = 0.4f;
    float alpha = 0.2f;
    float beta = 0.6f;
};

// The shadow maps of the lights that cast shadows (docs/shadows.md): a cube of six resolution x resolution faces
// per light, holding the view depth of the nearest opaque surface at each texel centre. A point is lit by the
// light where its depth along the face's axis, less the bias, is at most the map's depth:
//   bias = bias * depth + slope_bias * (how far the receiver's plane comes towards the light across the filter's
//          reach of pcf / 2 texels), the second term at most the depth itself;
// pcf x pcf texels around the point's are tested and the fraction that pass is the light's visibility.
struct ShadowSettings {
    int resolution = 1024;    // texels per side of each face, kMinShadowResolution..kMaxShadowResolution
    float bias = 1e-3f;       // constant bias, a fraction of the receiver's depth from the light, in [0, 1]
    float slope_bias = 1.5f;  // scales the receiver plane's depth change across the filter, in [0, 64]
    int pcf = 1;              // percentage-closer filtering: 1 (one texel), 3 (3 x 3) or 5 (5 x 5)
};
inline constexpr int kMinShadowResolution = 16;
inline constexpr int kMaxShadowResolution = 8192;

// How transparent surfaces are composited (docs/transparency.md): `sorted` keeps every fragment of a sample in an
// A-buffer, sorts them by depth and composites front to back (exact, with a memory cap); `weighted` accumulates
// them in any order into a weighted average (Bavoil and Myers 2008): no lists and no sort, exact for one layer and
// for layers of one colour, approximate otherwise.
enum class TransparencyMode { sorted, weighted };
struct TransparencySettings {
    TransparencyMode mode = TransparencyMode::sorted;
    int64_t max_fragments = int64_t{1} << 24;  // sorted: the A-buffer's cap, kMinFragments..kMaxFragments
};
inline constexpr int64_t kMinFragments = 1;
inline constexpr int64_t kMaxFragments = int64_t{1} << 27;
inline constexpr int kFragmentBytes = 24;  // an A-buffer entry: triangle, barycentrics, depth, next

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
    int cel_bands = 4;              // cel: bands of n.l, in [1, 64]
    GoochTones gooch;               // gooch: the tones
    PrecisionModes modes;           // edge arithmetic, interpolation, depth format, clipping, hierarchical Z
    // When set, every textured material's filter (--filter, the trade-off's filter modes); the mip chains it needs
    // must be built (build_needed_mip_chains) before rendering.
    std::optional<TextureFilter> texture_filter;
    ShadowSettings shadows;  // read only when a light casts shadows
    TransparencySettings transparency;  // read only when a material is blended (is_blended)
    // 1: the frame is rendered at width x height. 2 or 4: at width/d x height/d (which d must divide), every stage
    // at that internal resolution, then the image is stretched back bilinearly (resolve/upscale.h): the
    // trade-off's cheapest mode. Not in the scene formats: --resolution-divisor and `raster tradeoff` set it.
    int resolution_divisor = 1;
};

// The resolution divisors a frame may use: 1 (native), 2 and 4.
bool valid_resolution_divisor(int divisor);
// The settings of the frame a reduced-resolution render draws: width/d x height/d at divisor 1 (`settings` itself
// at divisor 1).
RenderSettings internal_frame_settings(RenderSettings settings);

struct SceneAnimation;  // raster/scene/animation.h

struct Scene {
    std::string path;  // the scene file, for messages
    RenderSettings settings;
    Camera camera;
    std::vector<Light> lights;
    std::vector<SceneMesh> meshes;
    // What moves over time, for an animated scene (raster/transform/scene_pose.h poses it); null for a static one.
    std::shared_ptr<const SceneAnimation> animation;
    float posed_at = 0.0f;  // the instant, in seconds, the animation was last posed at (the oracle poses it too)
};

// Whether any mesh has a textured material: the only scenes that read texture coordinates.
bool has_textures(const Scene& scene);

// Whether any light casts shadows: the only scenes that build shadow maps.
bool has_shadows(const Scene& scene);

// Whether any material is blended (is_blended: an opacity below 1 or a texture's alpha read): the only scenes with
// a transparency pass.
bool has_transparency(const Scene& scene);

// Every point and spot light casts shadows (`on`) or none does; a directional light never does (it has no position
// to centre a cube shadow map on). What --shadows and the viewer's switch do.
void set_shadow_casting(Scene& scene, bool on);
// Whether some light could cast shadows: a point or spot light.
bool can_cast_shadows(const Scene& scene);
// Every material drawn opaque: its opacity 1 and its texture's alpha not read (the viewer's "opaque" switch).
void draw_every_material_opaque(Scene& scene);

const char* to_string(TransparencyMode mode);
bool parse_transparency_mode(const std::string& name, TransparencyMode& out);

const char* to_string(ShadingMode mode);
const char* to_string(SamplePattern pattern);
// Parse a shading or pattern name as the CLI and the scene files spell it; false when unknown.
bool parse_shading_mode(const std::string& name, ShadingMode& out);
bool parse_sample_pattern(const std::string& name, SamplePattern& out);

// Total triangles over all meshes: the scene's triangle ids run from 0 to this, mesh by mesh, in order.
size_t triangle_count(const Scene& scene);

}  // namespace raster
