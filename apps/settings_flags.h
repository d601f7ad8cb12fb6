// The flags that override a scene's render settings, shared by `raster render` and `raster compare`, so that a
// comparison runs exactly what the same render command line renders.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "raster/compat/scene_loader.h"
#include "raster/scene/scene.h"

namespace raster::cli {

struct SettingsFlags {
    std::optional<int> samples;
    std::optional<std::string> pattern;
    bool msaa = false;
    std::optional<std::string> shading;
    std::optional<int> cel_bands;
    std::optional<std::string> filter;  // every textured material's
    std::optional<int> snap_bits;
    std::optional<std::string> cull;
    std::optional<std::string> edges, interpolation, depth_format, clipping, hierarchical_z;
    std::optional<int> resolution_divisor;  // 1, 2 or 4
    bool shadows = false;  // every light casts shadows
    std::optional<int> shadow_resolution, pcf;
    std::optional<float> shadow_bias, shadow_slope_bias;
    std::optional<std::string> transparency;  // sorted | weighted
    std::optional<int> max_fragments;
    std::optional<float> time;  // an animated scene's instant
    bool strict = false;        // read when loading the scene (scene_loader.h SceneLoadOptions)
    int camera = 0;             // likewise: a glTF file's camera to draw from
    bool alpha = false;
    int threads = 0;
};

// Adds --samples, --pattern, --msaa, --shading, --cel-bands, --filter, --snap-bits, --cull, the precision modes, the
// shadow and transparency flags, --time, --camera, --strict, --alpha and --threads.
void register_settings_flags(CLI::App& command, SettingsFlags& flags);

// Poses an animated scene at --time, applies the flags given to the scene's settings; throws InputError when the
// scene has no animation to pose or the result is not a valid frame.
void apply_settings_flags(const SettingsFlags& flags, Scene& scene);

// How the flags ask for the scene file to be read: --strict and --camera.
inline SceneLoadOptions load_options(const SettingsFlags& flags) { return {flags.strict, flags.camera}; }

// The scene file at `path` read as the flags ask, the flags applied to its scene. Throws InputError naming the file,
// for what is wrong in it and for a setting the flags make invalid.
SceneFile load_scene_with_flags(const std::string& path, const SettingsFlags& flags);

// --fast-oracle, for the commands that run the oracle: Embree without its robust flag.
void add_fast_oracle_flag(CLI::App& command, bool& fast_oracle);

}  // namespace raster::cli
