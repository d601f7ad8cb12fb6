// The raster scene format's `render` section (docs/scene-format.md): samples and pattern, shading and its
// parameters, culling, the precision modes and the shadow maps' settings.
#include <string>

#include "raster/formats/scene_formats.h"

namespace raster {
namespace {

// render.shadows: resolution, bias, slope_bias, pcf, each optional (docs/shadows.md).
void read_shadow_settings(const Node& node, const DocumentReader& reader, ShadowSettings& shadows) {
    reader.expect_map(node, "shadows");
    reader.check_keys(node, {"resolution", "bias", "slope_bias", "pcf"});
    if (const Node& v = reader.optional(node, "resolution"); v.is_defined())
        shadows.resolution = reader.integer(v, "shadow resolution", kMinShadowResolution, kMaxShadowResolution);
    auto number = [&](const char* key, float low, float high, float& out) {
        if (const Node& v = reader.optional(node, key); v.is_defined()) {
            out = reader.finite_float(v, key);
            if (out < low || out > high)
                reader.fail(v, std::string("shadow ") + key + " must be in [" + std::to_string(int(low)) + ", " +
                                   std::to_string(int(high)) + "]");
        }
    };
    number("bias", 0.0f, 1.0f, shadows.bias);
    number("slope_bias", 0.0f, 64.0f, shadows.slope_bias);
    if (const Node& v = reader.optional(node, "pcf"); v.is_defined()) {
        shadows.pcf = reader.integer(v, "pcf", 1, 5);
        if (shadows.pcf % 2 == 0) reader.fail(v, "pcf must be 1, 3 or 5 (texels per side of the filter)");
    }
}

// render.transparency: mode, max_fragments, each optional (docs/transparency.md).
void read_transparency_settings(const Node& node, const DocumentReader& reader, TransparencySettings& transparency) {
    reader.expect_map(node, "transparency");
    reader.check_keys(node, {"mode", "max_fragments"});
    if (const Node& v = reader.optional(node, "mode"); v.is_defined()) {
        if (!parse_transparency_mode(reader.string(v, "transparency mode"), transparency.mode))
            reader.fail(v, "transparency mode must be 'sorted' or 'weighted'");
    }
    if (const Node& v = reader.optional(node, "max_fragments"); v.is_defined())
        transparency.max_fragments = reader.integer(v, "max_fragments", static_cast<int>(kMinFragments),
                                                    static_cast<int>(kMaxFragments));
}

}  // namespace

void read_raster_render(const Node& node, const DocumentReader& reader, RenderSettings& settings) {
    reader.expect_map(node, "render");
    reader.check_keys(node, {"samples", "pattern", "msaa", "shading", "cull", "snap_bits", "ambient", "edges",
                             "interpolation", "depth", "clipping", "hierarchical_z", "cel_bands", "gooch", "shadows",
                             "transparency"});
    if (const Node& v = reader.optional(node, "samples"); v.is_defined())
        settings.samples = reader.integer(v, "samples", 1, 256);
    if (const Node& v = reader.optional(node, "pattern"); v.is_defined()) {
        if (!parse_sample_pattern(reader.string(v, "pattern"), settings.pattern))
            reader.fail(v, "pattern must be 'standard' or 'grid'");
    }
    if (const Node& v = reader.optional(node, "msaa"); v.is_defined()) settings.msaa = reader.boolean(v, "msaa");
    if (const Node& v = reader.optional(node, "shading"); v.is_defined()) {
        if (!parse_shading_mode(reader.string(v, "shading"), settings.shading))
            reader.fail(v, "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch");
    }
    if (const Node& v = reader.optional(node, "cel_bands"); v.is_defined())
        settings.cel_bands = reader.integer(v, "cel_bands", 1, 64);
    if (const Node& v = reader.optional(node, "gooch"); v.is_defined()) {
        reader.expect_map(v, "gooch");
        reader.check_keys(v, {"blue", "yellow", "alpha", "beta"});
        auto tone = [&](const char* key, float& out) {
            if (const Node& t = reader.optional(v, key); t.is_defined()) {
                out = reader.finite_float(t, key);
                if (out < 0.0f || out > 1.0f) reader.fail(t, std::string("gooch ") + key + " must be in [0, 1]");
            }
        };
        tone("blue", settings.gooch.blue);
        tone("yellow", settings.gooch.yellow);
        tone("alpha", settings.gooch.alpha);
        tone("beta", settings.gooch.beta);
    }
    if (const Node& v = reader.optional(node, "cull"); v.is_defined()) {
        const std::string cull = reader.string(v, "cull");
        if (cull != "none" && cull != "back") reader.fail(v, "cull must be 'none' or 'back'");
        settings.cull_backfaces = cull == "back";
    }
    if (const Node& v = reader.optional(node, "snap_bits"); v.is_defined())
        settings.snap_bits = reader.integer(v, "snap_bits", kMinSnapBits, kMaxSnapBits);
    if (const Node& v = reader.optional(node, "ambient"); v.is_defined())
        settings.ambient_light = reader.vec3(v, "render ambient", true);
    // A precision mode: an optional key naming one of the values its parse function knows.
    auto read_mode = [&](const char* key, auto parse, auto names, auto& out) {
        if (const Node& v = reader.optional(node, key); v.is_defined()) {
            if (!parse(reader.string(v, key), out)) reader.fail(v, std::string(key) + " must be one of " + names());
        }
    };
    PrecisionModes& modes = settings.modes;
    read_mode("edges", parse_edge_arithmetic, edge_arithmetic_names, modes.edges);
    read_mode("interpolation", parse_interpolation, interpolation_names, modes.interpolation);
    read_mode("depth", parse_depth_format, depth_format_names, modes.depth);
    read_mode("clipping", parse_clipping, clipping_names, modes.clipping);
    if (const Node& v = reader.optional(node, "hierarchical_z"); v.is_defined())
        modes.hierarchical_z = reader.boolean(v, "hierarchical_z");
    if (const Node& v = reader.optional(node, "shadows"); v.is_defined()) read_shadow_settings(v, reader, settings.shadows);
    if (const Node& v = reader.optional(node, "transparency"); v.is_defined())
        read_transparency_settings(v, reader, settings.transparency);
}


}  // namespace raster
