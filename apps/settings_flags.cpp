// The settings flags: registration with CLI11 and their application to a scene.
#include "apps/settings_flags.h"

#include <cmath>

#include "raster/core/errors.h"
#include "raster/transform/scene_pose.h"
#include "raster/scene/validation.h"
#include "raster/texture/mip_chains.h"

namespace raster::cli {

void register_settings_flags(CLI::App& command, SettingsFlags& flags) {
    command.add_option("--samples", flags.samples, "Samples per pixel: 1, 2, 4, 8, 16 (standard) or N*N (grid)");
    command.add_option("--pattern", flags.pattern, "Sample pattern: standard (Vulkan positions) or grid (N x N)")
        ->check(CLI::IsMember({"standard", "grid"}));
    command.add_flag("--msaa", flags.msaa, "Shade once per pixel per triangle (MSAA) instead of every sample (SSAA)");
    command.add_option("--shading", flags.shading, "Shading: unlit, flat, gouraud, phong, blinn-phong, cel or gooch")
        ->check(CLI::IsMember({"unlit", "flat", "gouraud", "phong", "blinn-phong", "cel", "gooch"}));
    command.add_option("--cel-bands", flags.cel_bands, "Cel shading: bands of n.l, 1..64 (default 4)")
        ->check(CLI::Range(1, 64));
    command.add_option("--filter", flags.filter,
                       "Texture filter for every textured material: nearest, bilinear, trilinear or anisotropic")
        ->check(CLI::IsMember({"nearest", "bilinear", "trilinear", "anisotropic"}));
    command.add_option("--snap-bits", flags.snap_bits, "Sub-pixel bits for vertex snapping, 1..16 (default 8)");
    command.add_option("--cull", flags.cull, "Back-face culling: none or back")->check(CLI::IsMember({"none", "back"}));
    command.add_option("--edges", flags.edges,
                       "Edge arithmetic: fixed (64-bit, watertight; default) or float (compare leaves its visibility "
                       "unjudged)")
        ->check(CLI::IsMember({"fixed", "float"}));
    command.add_option("--interpolation", flags.interpolation,
                       "perspective (default) or affine (compare leaves its barycentrics, depth and colour unjudged)")
        ->check(CLI::IsMember({"perspective", "affine"}));
    command.add_option("--depth-format", flags.depth_format,
                       "Depth test on reversed-z float (default), float z/w, or fixed24 (24-bit z/w; compare leaves the "
                       "visibility of float and fixed24 unjudged)")
        ->check(CLI::IsMember({"reversed-z", "float", "fixed24"}));
    command.add_option("--clipping", flags.clipping,
                       "full (default) or guard-band (side planes only beyond 4x the view; compare leaves its "
                       "visibility unjudged)")
        ->check(CLI::IsMember({"full", "guard-band"}));
    command.add_option("--hierarchical-z", flags.hierarchical_z,
                       "Hierarchical-Z occlusion culling: on (default) or off; never changes a pixel")
        ->check(CLI::IsMember({"on", "off"}));
    command.add_option("--resolution-divisor", flags.resolution_divisor,
                       "Render at width/N x height/N and stretch the image back bilinearly: 1 (default), 2 or 4 (N "
                       "must divide the image size; no depth image; compare refuses it, the trade-off measures it)")
        ->check(CLI::IsMember({1, 2, 4}));
    command.add_flag("--shadows", flags.shadows, "Every point and spot light casts shadows (through a cube shadow map; directional lights cast none)");
    command.add_option("--shadow-resolution", flags.shadow_resolution,
                       "Shadow map texels per side of each cube face, 16..8192 (default 1024)")
        ->check(CLI::Range(kMinShadowResolution, kMaxShadowResolution));
    command.add_option("--shadow-bias", flags.shadow_bias,
                       "Constant shadow bias, a fraction of the receiver's depth from the light, 0..1 (default 0.001)")
        ->check(CLI::Range(0.0f, 1.0f));
    command.add_option("--shadow-slope-bias", flags.shadow_slope_bias,
                       "Slope-scaled shadow bias: times the receiver plane's depth change across the filter, 0..64 "
                       "(default 1.5)")
        ->check(CLI::Range(0.0f, 64.0f));
    command.add_option("--pcf", flags.pcf, "Percentage-closer filtering: 1, 3 or 5 texels per side (default 1)")
        ->check(CLI::IsMember({1, 3, 5}));
    command.add_option("--transparency", flags.transparency,
                       "Transparent surfaces: sorted (an A-buffer, sorted per sample; default) or weighted (a weighted "
                       "average, no sort: faster, approximate where layers of different colours overlap)")
        ->check(CLI::IsMember({"sorted", "weighted"}));
    command.add_option("--max-fragments", flags.max_fragments,
                       "sorted transparency: the A-buffer's cap on transparent fragments in the frame, 1..134217728, "
                       "24 bytes each (default 16777216)")
        ->check(CLI::Range(static_cast<int>(kMinFragments), static_cast<int>(kMaxFragments)));
    command.add_option("--time", flags.time,
                       "An animated scene at this instant, in seconds (default 0; docs/animation.md)");
    command.add_option("--camera", flags.camera,
                       "glTF: draw from the file's camera N, counting its camera nodes depth first (default 0, the "
                       "first; docs/gltf.md)")
        ->check(CLI::Range(0, 1 << 16));
    command.add_flag("--strict", flags.strict,
                     "Refuse an OBJ whose material library or texture cannot be read, or whose MTL has a nameless "
                     "newmtl (default: draw it with a warning, as viewers do)");
    command.add_flag("--alpha", flags.alpha, "Write RGBA with alpha = fraction of the pixel's samples covered");
    command.add_option("--threads", flags.threads, "Worker threads, 0 = all cores (the output is the same for any count)")
        ->check(CLI::Range(0, 256));
}

void apply_settings_flags(const SettingsFlags& flags, Scene& scene) {
    if (flags.time) {
        if (!scene.animation) throw InputError(scene.path, 0, 0, "--time: the scene has no animation to pose");
        if (!std::isfinite(*flags.time)) throw InputError("", 0, 0, "--time must be a finite number of seconds");
        pose_scene(scene, *flags.time);
    }
    RenderSettings& settings = scene.settings;
    if (flags.samples) settings.samples = *flags.samples;
    if (flags.pattern) parse_sample_pattern(*flags.pattern, settings.pattern);
    if (flags.msaa) settings.msaa = true;
    if (flags.shading) parse_shading_mode(*flags.shading, settings.shading);
    if (flags.cel_bands) settings.cel_bands = *flags.cel_bands;
    if (flags.filter) {
        TextureFilter filter = TextureFilter::trilinear;
        parse_texture_filter(*flags.filter, filter);
        settings.texture_filter = filter;
        build_needed_mip_chains(scene);
    }
    if (flags.snap_bits) settings.snap_bits = *flags.snap_bits;
    if (flags.cull) settings.cull_backfaces = *flags.cull == "back";
    if (flags.edges) parse_edge_arithmetic(*flags.edges, settings.modes.edges);
    if (flags.interpolation) parse_interpolation(*flags.interpolation, settings.modes.interpolation);
    if (flags.depth_format) parse_depth_format(*flags.depth_format, settings.modes.depth);
    if (flags.clipping) parse_clipping(*flags.clipping, settings.modes.clipping);
    if (flags.hierarchical_z) settings.modes.hierarchical_z = *flags.hierarchical_z == "on";
    if (flags.resolution_divisor) settings.resolution_divisor = *flags.resolution_divisor;
    if (flags.shadows) set_shadow_casting(scene, true);
    if (flags.shadow_resolution) settings.shadows.resolution = *flags.shadow_resolution;
    if (flags.shadow_bias) settings.shadows.bias = *flags.shadow_bias;
    if (flags.shadow_slope_bias) settings.shadows.slope_bias = *flags.shadow_slope_bias;
    if (flags.pcf) settings.shadows.pcf = *flags.pcf;
    if (flags.transparency) parse_transparency_mode(*flags.transparency, settings.transparency.mode);
    if (flags.max_fragments) settings.transparency.max_fragments = *flags.max_fragments;
    if (std::string problem = settings_problem(settings); !problem.empty()) throw InputError("", 0, 0, problem);
    validate_scene(scene);  // the shadow maps' memory, which depends on the lights
}

SceneFile load_scene_with_flags(const std::string& path, const SettingsFlags& flags) {
    SceneFile file = load_scene_file(path, load_options(flags));
    try {
        apply_settings_flags(flags, file.scene);
    } catch (const InputError& error) {  // a setting the flags made invalid: name the scene it is for
        throw InputError(path, 0, 0, error.message());
    }
    return file;
}

void add_fast_oracle_flag(CLI::App& command, bool& fast_oracle) {
    command.add_flag("--fast-oracle", fast_oracle,
                     "Embree without RTC_SCENE_FLAG_ROBUST (faster, less careful; verdicts need the default)");
}

}  // namespace raster::cli
