// The speed/accuracy modes `raster tradeoff` sweeps: each a stable short name for one change to a scene's render
// settings (sub-pixel bits, edge arithmetic, samples and pattern, MSAA, interpolation, depth format, clipping,
// hierarchical Z, lighting rate, resolution, texture filter, shadow map resolution, bias and filter, transparency), or a named
// preset that sets all of them. A cheap setting is a mode only when it is faster: 4 sub-pixel bits, float edges,
// affine interpolation, float or fixed24 depth and the guard band measure no faster than their accurate values, so
// they remain render settings (for the accuracy they lose) but not trade-off modes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/scene/scene.h"

namespace raster::harness {

// What a scene must have for a mode to change anything: a texture filter needs textures, a shadow map setting a
// light that casts shadows, a transparency mode a blended material (is_blended), a lighting rate Phong or
// Blinn-Phong shading.
enum class ModeNeeds { nothing, textures, shadows, transparency, per_sample_lighting };

struct TradeoffMode {
    std::string name;         // e.g. "baseline", "snap12", "grid8x8", "shading-gouraud", "fastest"
    std::string description;  // one line, for --list-modes and the JSON
    std::function<void(RenderSettings&)> apply;  // the change, made to the scene's own settings
    ModeNeeds needs = ModeNeeds::nothing;        // only swept on scenes that have it
};

// What a scene has that modes may need.
struct SceneFeatures {
    bool textures = false;
    bool shadows = false;
    bool transparency = false;
    bool per_sample_lighting = false;  // Phong or Blinn-Phong
};
SceneFeatures scene_features(const Scene& scene);

// Every mode, in the default sweep's order: "baseline" (the scene's own settings), then the one-axis variations
// grouped by axis, then the presets "fastest", "balanced" and "exact".
const std::vector<TradeoffMode>& tradeoff_modes();

// The mode called `name`, or nullptr.
const TradeoffMode* find_tradeoff_mode(const std::string& name);

// Every name, comma-separated, for messages.
std::string tradeoff_mode_names();

// `baseline` with the mode applied.
RenderSettings apply_mode(const TradeoffMode& mode, RenderSettings baseline);

// True when a and b agree on every field a mode can change (shading, snap bits, samples, pattern, MSAA,
// PrecisionModes, texture filter, shadow settings, transparency, resolution divisor).
bool same_mode_settings(const RenderSettings& a, const RenderSettings& b);

// The default sweep for a scene: every mode in catalogue order, leaving out each whose settings equal those of a
// mode already in the list (snap8 when the scene already snaps to 8 bits, samples1 when it has 1 sample, ...), so
// every point of the plot is a distinct configuration.
std::vector<const TradeoffMode*> default_sweep(const RenderSettings& baseline, const SceneFeatures& features = {});

// {shading, snap_bits, edges, samples, pattern, msaa, interpolation, depth, clipping, hierarchical_z, texture_filter,
//  shadows: {resolution, bias, slope_bias, pcf}, transparency, resolution_divisor}
nlohmann::json mode_settings_json(const RenderSettings& settings);

}  // namespace raster::harness
