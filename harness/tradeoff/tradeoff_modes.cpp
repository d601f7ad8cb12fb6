// The catalogue of speed/accuracy modes: one-axis variations of a scene's settings and three presets.
#include "harness/tradeoff/tradeoff_modes.h"

#include <utility>

namespace raster::harness {
namespace {

TradeoffMode snap(int bits) {
    return {"snap" + std::to_string(bits),
            "vertices snapped to 1/" + std::to_string(1 << bits) + " px (" + std::to_string(bits) + " sub-pixel bits)",
            [bits](RenderSettings& s) { s.snap_bits = bits; }};
}

TradeoffMode standard_samples(int samples) {
    return {
        "samples" + std::to_string(samples),
        std::to_string(samples) + " sample" + (samples > 1 ? "s" : "") + " per pixel at the Vulkan standard positions",
        [samples](RenderSettings& s) {
            s.samples = samples;
            s.pattern = SamplePattern::standard;
        }};
}

// Phong and Blinn-Phong light every sample; the lighting axis trades that for Blinn-Phong once per vertex
// (Gouraud) or once per triangle (flat). Other shading modes are left as they are: unlit has no lighting to move,
// and cel and Gooch are looks of their own, not approximations of a per-sample model.
bool lit_per_sample(ShadingMode mode) { return mode == ShadingMode::phong || mode == ShadingMode::blinn_phong; }

TradeoffMode lighting_rate(ShadingMode cheaper, std::string name, std::string description) {
    return {std::move(name), std::move(description),
            [cheaper](RenderSettings& s) {
                if (lit_per_sample(s.shading)) s.shading = cheaper;
            },
            ModeNeeds::per_sample_lighting};
}

// The divisor where it divides the image size, else native resolution (a mode never makes a scene invalid).
void set_resolution_divisor(RenderSettings& s, int divisor) {
    s.resolution_divisor = s.width % divisor == 0 && s.height % divisor == 0 ? divisor : 1;
}

// A preset: every axis set at once, whatever the scene asked for (shadow maps: resolution and filter; the bias is
// the scene's; transparency: the mode).
TradeoffMode preset(std::string name, std::string description, int snap_bits, int samples, SamplePattern pattern,
                    bool msaa, PrecisionModes precision, int shadow_resolution, int pcf, TransparencyMode transparency,
                    bool lit_per_vertex = false, int resolution_divisor = 1) {
    return {std::move(name), std::move(description), [=](RenderSettings& s) {
                if (lit_per_vertex && lit_per_sample(s.shading)) s.shading = ShadingMode::gouraud;
                set_resolution_divisor(s, resolution_divisor);
                s.snap_bits = snap_bits;
                s.samples = samples;
                s.pattern = pattern;
                s.msaa = msaa;
                s.modes = precision;
                s.shadows.resolution = shadow_resolution;
                s.shadows.pcf = pcf;
                s.transparency.mode = transparency;
            }};
}

TradeoffMode grid(int side) {
    const std::string n = std::to_string(side);
    return {"grid" + n + "x" + n, n + "x" + n + " regular grid of samples per pixel", [side](RenderSettings& s) {
                s.samples = side * side;
                s.pattern = SamplePattern::grid;
            }};
}

TradeoffMode filter(TextureFilter f, const char* description) {
    return {std::string("filter-") + to_string(f), description, [f](RenderSettings& s) { s.texture_filter = f; },
            ModeNeeds::textures};
}

TradeoffMode shadow_resolution(int resolution) {
    return {"shadow" + std::to_string(resolution),
            "shadow maps of " + std::to_string(resolution) + " x " + std::to_string(resolution) + " texels per face",
            [resolution](RenderSettings& s) { s.shadows.resolution = resolution; }, ModeNeeds::shadows};
}

TradeoffMode pcf(int taps) {
    const std::string n = std::to_string(taps);
    return {"pcf" + n, taps == 1 ? "one shadow map texel per lookup" : n + " x " + n + " percentage-closer filtering",
            [taps](RenderSettings& s) { s.shadows.pcf = taps; }, ModeNeeds::shadows};
}

TradeoffMode shadow_bias(std::string name, std::string description, float bias, float slope_bias) {
    return {std::move(name), std::move(description),
            [=](RenderSettings& s) {
                s.shadows.bias = bias;
                s.shadows.slope_bias = slope_bias;
            },
            ModeNeeds::shadows};
}

TradeoffMode msaa(int samples) {
    return {"msaa" + std::to_string(samples),
            std::to_string(samples) + " standard samples, shaded once per pixel per triangle (MSAA)",
            [samples](RenderSettings& s) {
                s.samples = samples;
                s.pattern = SamplePattern::standard;
                s.msaa = true;
            }};
}

std::vector<TradeoffMode> make_catalogue() {
    std::vector<TradeoffMode> modes;
    modes.push_back({"baseline", "the scene's own settings", [](RenderSettings&) {}});
    for (int bits : {8, 12, 16}) modes.push_back(snap(bits));
    modes.push_back({"edges-fixed", "exact 64-bit fixed-point edge functions (watertight)",
                     [](RenderSettings& s) { s.modes.edges = EdgeArithmetic::fixed; }});
    for (int samples : {1, 4, 8, 16}) modes.push_back(standard_samples(samples));
    for (int side : {4, 8}) modes.push_back(grid(side));
    for (int samples : {4, 16}) modes.push_back(msaa(samples));
    modes.push_back({"perspective", "perspective-correct interpolation",
                     [](RenderSettings& s) { s.modes.interpolation = Interpolation::perspective; }});
    modes.push_back({"depth-reversed-z", "reversed-Z float depth",
                     [](RenderSettings& s) { s.modes.depth = DepthFormat::reversed_z; }});
    modes.push_back(
        {"clip-full", "clipping against every plane", [](RenderSettings& s) { s.modes.clipping = Clipping::full; }});
    modes.push_back({"hiz-on", "hierarchical-Z culling on", [](RenderSettings& s) { s.modes.hierarchical_z = true; }});
    modes.push_back(
        {"hiz-off", "hierarchical-Z culling off", [](RenderSettings& s) { s.modes.hierarchical_z = false; }});
    modes.push_back(lighting_rate(ShadingMode::gouraud, "shading-gouraud",
                                  "Phong and Blinn-Phong lit once per vertex, the colours interpolated (Gouraud)"));
    modes.push_back(lighting_rate(ShadingMode::flat, "shading-flat",
                                  "Phong and Blinn-Phong lit once per triangle, at its centroid (flat)"));
    modes.push_back({"half-resolution",
                     "rendered at half the width and height, the image stretched back bilinearly (when 2 divides "
                     "the size)",
                     [](RenderSettings& s) { set_resolution_divisor(s, 2); }});
    modes.push_back(filter(TextureFilter::nearest, "every texture nearest-sampled at level 0 (no mipmaps)"));
    modes.push_back(filter(TextureFilter::bilinear, "every texture bilinear at level 0 (no mipmaps)"));
    modes.push_back(filter(TextureFilter::trilinear, "every texture trilinear: bilinear in two mip levels, blended"));
    modes.push_back(filter(TextureFilter::anisotropic, "every texture anisotropic: trilinear taps along the footprint"));
    for (int resolution : {512, 1024, 2048, 4096}) modes.push_back(shadow_resolution(resolution));
    for (int taps : {1, 3, 5}) modes.push_back(pcf(taps));
    modes.push_back(shadow_bias("shadow-bias-low", "shadow bias 1e-4 of the depth, slope bias 1", 1e-4f, 1.0f));
    modes.push_back(shadow_bias("shadow-bias-high", "shadow bias 1e-2 of the depth, slope bias 4", 1e-2f, 4.0f));
    modes.push_back({"transparency-sorted", "transparent fragments sorted per sample and composited nearest first",
                     [](RenderSettings& s) { s.transparency.mode = TransparencyMode::sorted; }, ModeNeeds::transparency});
    modes.push_back({"transparency-weighted", "transparent fragments averaged by opacity, in any order (no sort)",
                     [](RenderSettings& s) { s.transparency.mode = TransparencyMode::weighted; },
                     ModeNeeds::transparency});
    // Only choices that buy time: the precision axes a cheap setting of which is no faster here (4 sub-pixel bits,
    // float edges, affine interpolation, fixed24 or float depth, the guard band) stay at their accurate values.
    modes.push_back(preset("fastest",
                           "half resolution, 1 sample, Gouraud lighting, 512 shadow texels, no PCF, weighted "
                           "transparency; 8 bits, fixed edges, perspective, reversed-Z, full clipping",
                           8, 1, SamplePattern::standard, false,
                           {EdgeArithmetic::fixed, Interpolation::perspective, DepthFormat::reversed_z,
                            Clipping::full, true},
                           512, 1, TransparencyMode::weighted, /*lit_per_vertex=*/true, /*resolution_divisor=*/2));
    modes.push_back(preset("balanced",
                           "8 bits, fixed edges, 4 samples MSAA, perspective, reversed-Z, full clipping, 1024 "
                           "shadow texels, 3x3 PCF",
                           8, 4, SamplePattern::standard, true,
                           {EdgeArithmetic::fixed, Interpolation::perspective, DepthFormat::reversed_z,
                            Clipping::full, true},
                           1024, 3, TransparencyMode::sorted));
    modes.push_back(preset("exact",
                           "16 bits, fixed edges, 8x8 grid SSAA, perspective, reversed-Z, full clipping, 4096 shadow "
                           "texels, no PCF",
                           16, 64, SamplePattern::grid, false,
                           {EdgeArithmetic::fixed, Interpolation::perspective, DepthFormat::reversed_z,
                            Clipping::full, true},
                           4096, 1, TransparencyMode::sorted));
    return modes;
}

}  // namespace

const std::vector<TradeoffMode>& tradeoff_modes() {
    static const std::vector<TradeoffMode> catalogue = make_catalogue();
    return catalogue;
}

const TradeoffMode* find_tradeoff_mode(const std::string& name) {
    for (const TradeoffMode& mode : tradeoff_modes())
        if (mode.name == name) return &mode;
    return nullptr;
}

std::string tradeoff_mode_names() {
    std::string names;
    for (const TradeoffMode& mode : tradeoff_modes()) names += (names.empty() ? "" : ", ") + mode.name;
    return names;
}

RenderSettings apply_mode(const TradeoffMode& mode, RenderSettings baseline) {
    mode.apply(baseline);
    return baseline;
}

bool same_mode_settings(const RenderSettings& a, const RenderSettings& b) {
    return a.snap_bits == b.snap_bits && a.samples == b.samples && a.pattern == b.pattern && a.msaa == b.msaa &&
           a.texture_filter == b.texture_filter && a.shadows.resolution == b.shadows.resolution &&
           a.shadows.bias == b.shadows.bias && a.shadows.slope_bias == b.shadows.slope_bias &&
           a.shadows.pcf == b.shadows.pcf && a.transparency.mode == b.transparency.mode &&
           a.modes.edges == b.modes.edges && a.modes.interpolation == b.modes.interpolation &&
           a.modes.depth == b.modes.depth && a.modes.clipping == b.modes.clipping &&
           a.modes.hierarchical_z == b.modes.hierarchical_z && a.shading == b.shading &&
           a.resolution_divisor == b.resolution_divisor;
}

SceneFeatures scene_features(const Scene& scene) {
    return {has_textures(scene), has_shadows(scene) && scene.settings.shading != ShadingMode::unlit,
            has_transparency(scene), lit_per_sample(scene.settings.shading)};
}

std::vector<const TradeoffMode*> default_sweep(const RenderSettings& baseline, const SceneFeatures& features) {
    std::vector<const TradeoffMode*> sweep;
    std::vector<RenderSettings> seen;
    for (const TradeoffMode& mode : tradeoff_modes()) {
        if (mode.needs == ModeNeeds::textures && !features.textures) continue;
        if (mode.needs == ModeNeeds::shadows && !features.shadows) continue;
        if (mode.needs == ModeNeeds::transparency && !features.transparency) continue;
        if (mode.needs == ModeNeeds::per_sample_lighting && !features.per_sample_lighting) continue;
        const RenderSettings settings = apply_mode(mode, baseline);
        bool duplicate = false;
        for (const RenderSettings& other : seen) duplicate = duplicate || same_mode_settings(settings, other);
        if (duplicate) continue;
        sweep.push_back(&mode);
        seen.push_back(settings);
    }
    return sweep;
}

nlohmann::json mode_settings_json(const RenderSettings& s) {
    return {{"shading", to_string(s.shading)},
            {"snap_bits", s.snap_bits},
            {"edges", to_string(s.modes.edges)},
            {"samples", s.samples},
            {"pattern", to_string(s.pattern)},
            {"msaa", s.msaa},
            {"interpolation", to_string(s.modes.interpolation)},
            {"depth", to_string(s.modes.depth)},
            {"clipping", to_string(s.modes.clipping)},
            {"hierarchical_z", s.modes.hierarchical_z},
            {"texture_filter", s.texture_filter ? to_string(*s.texture_filter) : "the materials'"},
            {"shadows",
             {{"resolution", s.shadows.resolution},
              {"bias", s.shadows.bias},
              {"slope_bias", s.shadows.slope_bias},
              {"pcf", s.shadows.pcf}}},
            {"transparency", to_string(s.transparency.mode)},
            {"resolution_divisor", s.resolution_divisor}};
}

}  // namespace raster::harness
