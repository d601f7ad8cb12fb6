// A comparison run: raster, then the oracle, then the classifier and the colour check, each timed.
#include "harness/comparison/scene_comparison.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "harness/comparison/decoded_image.h"
#include "oracle/compare/diff_map.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shader.h"
#include "oracle/reference/layer_caster.h"
#include "oracle/reference/shadow_oracle.h"
#include "raster/core/stopwatch.h"
#include "raster/scene/validation.h"

namespace raster::harness {
namespace {

oracle::RasterPixels pixels_of(const Image& image) {
    return {image.width, image.height, image.channels, image.pixels.data()};
}

}  // namespace

uint64_t comparison_bytes(const RenderSettings& settings) {
    const uint64_t pixels = uint64_t(std::max(settings.width, 0)) * uint64_t(std::max(settings.height, 0));
    return frame_bytes(settings) + pixels * uint64_t(std::max(settings.samples, 0)) * 21u + pixels * 50u;
}

std::string comparison_problem(const Scene& scene) {
    const RenderSettings& settings = scene.settings;
    const uint64_t bytes = comparison_bytes(settings);
    if (bytes <= kMaxFrameBytes) return "";
    return "comparing a " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " image with " +
           std::to_string(settings.samples) + " samples needs " + std::to_string(bytes >> 20) + " MiB, over the " +
           std::to_string(kMaxFrameBytes >> 20) + " MiB cap";
}

Comparison compare_scene(const Scene& scene, const ComparisonOptions& options) {
    Comparison out;
    out.scene = scene.path;
    out.width = scene.settings.width;
    out.height = scene.settings.height;
    out.samples = scene.settings.samples;
    out.mode = options.mode;

    RenderOptions render_options;
    render_options.threads = options.threads;
    render_options.path = options.raster_path;
    render_options.alpha = options.alpha;
    render_options.keep_visibility = true;
    out.raster = render(scene, render_options);
    out.raster_ms = out.raster.stats.ms_total;
    // The colours are judged on the frame `raster render` writes, which keeps no visibility buffer and so shades
    // through its batched path; the visibility buffer above is only for the per-sample visibility check.
    RenderOptions image_options = render_options;
    image_options.keep_visibility = false;
    out.raster.image = render(scene, image_options).image;

    auto start = Clock::now();
    const oracle::OracleScene geometry = oracle::oracle_scene(scene);
    oracle::OracleOptions oracle_options;
    oracle_options.mode = options.mode;
    oracle_options.threads = options.threads;
    oracle::render_oracle(scene, geometry, oracle_options, out.oracle_visibility);
    std::unique_ptr<oracle::ShadowOracle> shadows;
    if (has_shadows(scene) && scene.settings.shading != ShadingMode::unlit)
        shadows = std::make_unique<oracle::ShadowOracle>(scene, geometry, options.threads);
    const oracle::OracleShader shader(scene, geometry, shadows.get(), oracle::ShadowAnswer::exact);
    const oracle::ResolveSettings resolve{scene.settings.samples, scene.settings.msaa, options.alpha,
                                          glm::dvec3(scene.settings.background)};
    const oracle::SampleLayers layers = oracle::trace_layers(scene, geometry, oracle_options);
    const bool transparent = !layers.first.empty();
    const TransparencyMode transparency = scene.settings.transparency.mode;
    const oracle::OracleImage oracle_image = oracle::render_image(shader, out.oracle_visibility, resolve, options.threads,
                                                                  transparent ? &layers : nullptr, transparency);
    out.oracle_image = image_of(oracle_image);
    out.oracle_ms = milliseconds_since(start);

    start = Clock::now();
    const oracle::ReferenceGeometry reference(scene, geometry);
    const std::vector<glm::dvec2> offsets =
        oracle::sample_offsets_on_grid(scene.settings.samples, scene.settings.pattern, scene.settings.snap_bits);
    const VisibilityBuffer& visibility = out.raster.visibility;
    oracle::CompareInputs inputs;
    inputs.raster = {visibility.width, visibility.height, visibility.samples, visibility.triangle.data(),
                     visibility.bary.data(), visibility.view_depth.data()};
    inputs.oracle = &out.oracle_visibility;
    inputs.reference = &reference;
    inputs.offsets = offsets;
    inputs.threads = options.threads;
    out.visibility = oracle::compare_visibility(inputs);

    oracle::ColourInputs colour;
    colour.oracle = &out.oracle_visibility;
    colour.classes = &out.visibility.classes;
    colour.reference = &reference;
    const oracle::OracleShader allowed(scene, geometry, shadows.get(), oracle::ShadowAnswer::allowed);
    std::unique_ptr<oracle::OracleShader> open;
    if (shadows) open = std::make_unique<oracle::OracleShader>(scene, geometry, shadows.get(), oracle::ShadowAnswer::open);
    colour.shader = &allowed;
    colour.open_shader = open.get();
    colour.resolve = resolve;
    colour.offsets = offsets;
    colour.threads = options.threads;
    oracle::LayerVerdicts layer_verdicts;
    if (transparent) {
        oracle::LayerCheckInputs layer_inputs;
        layer_inputs.scene = &scene;
        layer_inputs.layers = &layers;
        layer_inputs.oracle = &out.oracle_visibility;
        layer_inputs.reference = &reference;
        for (uint32_t id = 0; id < geometry.triangles.size(); ++id)  // culled ones too: their facing may be uncertain
            if (oracle::triangle_material(scene, geometry.triangles[id]).opacity < 1.0f) layer_inputs.transparent.push_back(id);
        layer_inputs.offsets = offsets;
        layer_inputs.threads = options.threads;
        layer_verdicts = oracle::check_layers(layer_inputs);
        colour.layers = &layers;
        colour.layer_verdicts = &layer_verdicts;
        colour.transparency = transparency;
    }
    const oracle::PixelBounds bounds = oracle::pixel_bounds(colour);
    const Image png = encoded_and_decoded(out.raster.image, ImageFormat::png);
    const Image ppm = encoded_and_decoded(out.raster.image, ImageFormat::ppm);
    out.png = oracle::check_colours(bounds, pixels_of(png), oracle_image);
    out.ppm = oracle::check_colours(bounds, pixels_of(ppm), oracle_image);
    out.colour_genuine.resize(out.png.genuine_pixels.size());
    out.shadow_genuine.resize(out.png.genuine_pixels.size());
    for (size_t i = 0; i < out.colour_genuine.size(); ++i) {
        out.colour_genuine[i] = out.png.genuine_pixels[i] | out.ppm.genuine_pixels[i];
        out.colour_genuine_pixels += out.colour_genuine[i];
        // A shadow disagreement when every file that is off is off only by its shadows.
        const bool png_other = out.png.genuine_pixels[i] && !out.png.shadow_pixels[i];
        const bool ppm_other = out.ppm.genuine_pixels[i] && !out.ppm.shadow_pixels[i];
        // A pixel with transparent layers is a transparency disagreement first: its layers' shading includes the
        // shadows, so leaving shadows open there would excuse a wrong blend as well.
        const bool layered = !bounds.layered.empty() && bounds.layered[i];
        out.transparency_genuine_pixels += out.colour_genuine[i] && layered;
        out.shadow_genuine[i] = out.colour_genuine[i] && !layered && !png_other && !ppm_other;
        out.shadow_genuine_pixels += out.shadow_genuine[i];
    }
    for (size_t pixel = 0; pixel < bounds.layer_open.size(); ++pixel) {
        // Counted where the layers are what leaves the pixel open (not where a sample is genuine anyway).
        const oracle::LayerOpen open = bounds.state[pixel] == oracle::PixelState::ambiguous ? bounds.layer_open[pixel]
                                                                                           : oracle::LayerOpen::none;
        out.layers_open.push_back(open != oracle::LayerOpen::none);
        out.transparency_edge_pixels += open == oracle::LayerOpen::edge;
        out.transparency_depth_pixels += open == oracle::LayerOpen::depth;
        out.transparency_order_pixels += open == oracle::LayerOpen::order;
    }
    using oracle::ShadowVerdict;
    out.shadow_seen = bounds.shadow_seen;
    for (uint8_t seen : bounds.shadow_seen) {
        out.shadow_edge_pixels += (seen >> static_cast<int>(ShadowVerdict::open_edge)) & 1u;
        out.shadow_depth_pixels += (seen >> static_cast<int>(ShadowVerdict::open_depth)) & 1u;
        out.shadow_inconsistent_pixels += (seen >> static_cast<int>(ShadowVerdict::inconsistent)) & 1u;
    }
    out.compare_ms = milliseconds_since(start);
    return out;
}

namespace {

nlohmann::json disagreements_json(const oracle::ColourCheck& check, const char* format) {
    nlohmann::json list = nlohmann::json::array();
    for (const oracle::ColourDisagreement& d : check.first) {
        nlohmann::json raster = nlohmann::json::array(), oracle = nlohmann::json::array(),
                       allowed = nlohmann::json::array();
        for (int c = 0; c < d.channels; ++c) {
            raster.push_back(d.raster[c]);
            oracle.push_back(d.oracle[c]);
            allowed.push_back({d.allowed[c].lo, d.allowed[c].hi});
        }
        list.push_back({{"x", d.x}, {"y", d.y}, {"file", format}, {"raster", raster}, {"oracle", oracle},
                        {"allowed", allowed}});
    }
    return list;
}

}  // namespace

nlohmann::json comparison_json(const Comparison& c) {
    using oracle::SampleClass;
    const oracle::ComparisonCounts& counts = c.visibility.counts;
    auto count = [&](SampleClass k) { return counts.count(k); };
    const double total = std::max<double>(1.0, static_cast<double>(c.visibility.classes.size()));
    auto fraction = [&](SampleClass k) { return static_cast<double>(count(k)) / total; };
    nlohmann::json disagreements = disagreements_json(c.png, "png");
    for (const nlohmann::json& d : disagreements_json(c.ppm, "ppm")) disagreements.push_back(d);
    return {{"scene", c.scene},
            {"width", c.width},
            {"height", c.height},
            {"samples", c.samples},
            {"oracle_mode", oracle::to_string(c.mode)},
            {"agree", count(SampleClass::agree)},
            {"ambiguous",
             {{"edge_band", count(SampleClass::edge_band)},
              {"depth_tie", count(SampleClass::depth_tie)},
              {"clip_boundary", count(SampleClass::clip_boundary)},
              {"facing", count(SampleClass::facing)}}},
            {"ambiguous_total", counts.ambiguous_total()},
            {"ambiguous_fraction",
             {{"edge_band", fraction(SampleClass::edge_band)},
              {"depth_tie", fraction(SampleClass::depth_tie)},
              {"clip_boundary", fraction(SampleClass::clip_boundary)},
              {"facing", fraction(SampleClass::facing)},
              {"total", static_cast<double>(counts.ambiguous_total()) / total}}},
            {"genuine",
             {{"visibility", count(SampleClass::visibility)},
              {"barycentrics", count(SampleClass::barycentrics)},
              {"depth", count(SampleClass::depth)},
              {"color", c.colour_genuine_pixels - c.shadow_genuine_pixels - c.transparency_genuine_pixels},
              {"shadow", c.shadow_genuine_pixels},
              {"transparency", c.transparency_genuine_pixels}}},
            {"genuine_total", c.genuine_total()},
            {"shadows",
             {{"edge", c.shadow_edge_pixels},
              {"depth", c.shadow_depth_pixels},
              {"inconsistent", c.shadow_inconsistent_pixels}}},
            {"transparency",
             {{"edge", c.transparency_edge_pixels},
              {"depth", c.transparency_depth_pixels},
              {"order", c.transparency_order_pixels}}},
            {"pixels",
             {{"judged", c.png.judged},
              {"ambiguous", c.png.ambiguous},
              {"color_png", c.png.genuine},
              {"color_ppm", c.ppm.genuine}}},
            {"max_color_error", std::max(c.png.max_difference, c.ppm.max_difference)},
            {"color_disagreements", disagreements},
            {"raster_ms", c.raster_ms},
            {"oracle_ms", c.oracle_ms},
            {"compare_ms", c.compare_ms}};
}

std::string comparison_summary(const Comparison& c) {
    using oracle::SampleClass;
    const oracle::ComparisonCounts& counts = c.visibility.counts;
    auto count = [&](SampleClass k) { return static_cast<unsigned long long>(counts.count(k)); };
    const double total = std::max<double>(1.0, static_cast<double>(c.visibility.classes.size()));
    char text[1536];
    std::snprintf(text, sizeof text,
                  "%s: %dx%d, %d samples per pixel, oracle %s\n"
                  "  samples agree      %llu\n"
                  "  samples ambiguous  %llu = %.4f%% (edge band %llu, depth tie %llu, clip boundary %llu, facing %llu)\n"
                  "  samples genuine    %llu (visibility %llu, barycentrics %llu, depth %llu)\n"
                  "  pixels judged      %llu, ambiguous %llu, colour genuine %llu (png %llu, ppm %llu), of them shadow %llu\n"
                  "  shadow model open  %llu pixels by an edge, %llu by depth, %llu inconsistent\n"
                  "  layers open        %llu pixels by an edge, %llu by depth, %llu by order; transparency genuine %llu\n"
                  "  genuine total      %llu\n"
                  "  max colour difference from the oracle's image %d/255 on judged pixels\n"
                  "  raster %.1f ms, oracle %.1f ms, compare %.1f ms\n",
                  c.scene.c_str(), c.width, c.height, c.samples, oracle::to_string(c.mode), count(SampleClass::agree),
                  static_cast<unsigned long long>(counts.ambiguous_total()), 100.0 * counts.ambiguous_total() / total,
                  count(SampleClass::edge_band), count(SampleClass::depth_tie), count(SampleClass::clip_boundary),
                  count(SampleClass::facing), static_cast<unsigned long long>(counts.genuine_total()),
                  count(SampleClass::visibility), count(SampleClass::barycentrics), count(SampleClass::depth),
                  static_cast<unsigned long long>(c.png.judged), static_cast<unsigned long long>(c.png.ambiguous),
                  static_cast<unsigned long long>(c.colour_genuine_pixels), static_cast<unsigned long long>(c.png.genuine),
                  static_cast<unsigned long long>(c.ppm.genuine), static_cast<unsigned long long>(c.shadow_genuine_pixels),
                  static_cast<unsigned long long>(c.shadow_edge_pixels),
                  static_cast<unsigned long long>(c.shadow_depth_pixels),
                  static_cast<unsigned long long>(c.shadow_inconsistent_pixels),
                  static_cast<unsigned long long>(c.transparency_edge_pixels),
                  static_cast<unsigned long long>(c.transparency_depth_pixels),
                  static_cast<unsigned long long>(c.transparency_order_pixels),
                  static_cast<unsigned long long>(c.transparency_genuine_pixels),
                  static_cast<unsigned long long>(c.genuine_total()),
                  std::max(c.png.max_difference, c.ppm.max_difference), c.raster_ms, c.oracle_ms, c.compare_ms);
    return text;
}

std::string genuine_reasons(const Comparison& c) {
    std::string text;
    auto add = [&](const char* reason, uint64_t count) {
        if (count) text += std::string(text.empty() ? "" : ", ") + reason + " " + std::to_string(count);
    };
    for (oracle::SampleClass k : {oracle::SampleClass::visibility, oracle::SampleClass::barycentrics, oracle::SampleClass::depth})
        add(oracle::to_string(k), c.visibility.counts.count(k));
    add("color", c.colour_genuine_pixels - c.shadow_genuine_pixels - c.transparency_genuine_pixels);
    add("shadow", c.shadow_genuine_pixels);
    add("transparency", c.transparency_genuine_pixels);
    return text.empty() ? "-" : text;
}

std::string genuine_details(const Comparison& c, int shown) {
    std::string text;
    int listed = 0;
    const auto& classes = c.visibility.classes;
    const VisibilityBuffer& raster = c.raster.visibility;
    const oracle::SampleBuffer& oracle = c.oracle_visibility;
    for (size_t i = 0; i < classes.size() && listed < shown; ++i) {
        if (!oracle::is_genuine(classes[i])) continue;
        const size_t samples = static_cast<size_t>(c.samples), width = static_cast<size_t>(c.width);
        const glm::vec3 &a = raster.bary[i], &b = oracle.bary[i];
        char line[512];
        std::snprintf(line, sizeof line,
                      "  %s at pixel (%zu, %zu) sample %zu:\n    raster triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n"
                      "    oracle triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n",
                      oracle::to_string(classes[i]), (i / samples) % width, i / samples / width, i % samples,
                      int(raster.triangle[i]), double(raster.view_depth[i]), double(a.x), double(a.y), double(a.z),
                      int(oracle.triangle[i]), double(oracle.view_depth[i]), double(b.x), double(b.y), double(b.z));
        text += line;
        ++listed;
    }
    for (const auto* check : {&c.png, &c.ppm})
        for (const oracle::ColourDisagreement& d : check->first) {
            if (listed >= 2 * shown) break;
            // snprintf rather than string concatenation: g++ 12's -O3 -Wrestrict misreads the latter here.
            char line[128];
            std::snprintf(line, sizeof line, "  colour (%s) at pixel (%d, %d):", check == &c.png ? "png" : "ppm", d.x,
                          d.y);
            text += line;
            for (int ch = 0; ch < d.channels; ++ch) {
                std::snprintf(line, sizeof line, " %d not in [%d, %d] (oracle %d)", d.raster[ch], d.allowed[ch].lo,
                              d.allowed[ch].hi, d.oracle[ch]);
                text += line;
            }
            text += "\n";
            ++listed;
        }
    return text;
}

Image diff_map(const Comparison& c) {
    return oracle::diff_map(c.visibility.classes, c.samples, c.colour_genuine, pixels_of(c.raster.image),
                            {&c.shadow_genuine, &c.shadow_seen, &c.layers_open});
}

}  // namespace raster::harness
