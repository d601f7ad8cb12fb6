// Speed against accuracy: timing, the oracle comparison, colour RMSE, coverage error and the Pareto front per mode.
#include "harness/tradeoff/tradeoff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

#include "harness/comparison/decoded_image.h"
#include "harness/comparison/scene_comparison.h"
#include "oracle/reference/layer_caster.h"
#include "oracle/reference/oracle_image.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shadow_oracle.h"
#include "raster/core/conventions.h"
#include "raster/texture/mip_chains.h"
#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"
#include "raster/geometry/front_end.h"
#include "raster/rasterize/per_sample.h"
#include "raster/frame/render.h"
#include "raster/geometry/sample_pattern.h"
#include "raster/scene/validation.h"

namespace raster::harness {
namespace {


// Bytes of one sample of a visibility buffer: triangle id, barycentrics, view depth.
constexpr uint64_t sizeof_visibility_sample = sizeof(uint32_t) + sizeof(glm::vec3) + sizeof(float);

// Samples of one setup its own exact test covers, over its pixel bounding box.
uint64_t covered_samples(const TriangleSetup& t, const FixedSampleOffsets& offsets, int fixed_bits) {
    uint64_t count = 0;
    const size_t samples = offsets.x.size();
    for (int py = t.min_y; py <= t.max_y; ++py) {
        const int64_t row = int64_t{py} << fixed_bits;
        for (int px = t.min_x; px <= t.max_x; ++px) {
            const int64_t column = int64_t{px} << fixed_bits;
            for (size_t s = 0; s < samples; ++s) count += covers(t, column + offsets.x[s], row + offsets.y[s]);
        }
    }
    return count;
}

// `text` as one CSV field.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

std::vector<double> exact_triangle_areas(const Scene& scene) {
    const oracle::OracleScene geometry = oracle::oracle_scene(scene);
    const oracle::ReferenceGeometry reference(scene, geometry);
    std::vector<double> areas(reference.size(), 0.0);
    for (uint32_t id = 0; id < reference.size(); ++id) {
        if (reference.polygon(id).culled) continue;
        const auto vertices = reference.screen_vertices(id);
        double twice = 0.0;  // the shoelace formula
        for (size_t i = 0; i < vertices.size(); ++i) {
            const glm::dvec2& a = vertices[i];
            const glm::dvec2& b = vertices[(i + 1) % vertices.size()];
            twice += a.x * b.y - a.y * b.x;
        }
        areas[id] = 0.5 * std::fabs(twice);
    }
    return areas;
}

std::vector<uint64_t> covered_sample_counts(const Scene& scene, const TransformedScene& geometry, int threads) {
    const FrameParams frame =
        frame_params_for(scene, sample_offsets(scene.settings.samples, scene.settings.pattern), threads);
    const std::vector<TriangleSetup> setups = set_up_triangles(geometry, frame, scene.settings.cull_backfaces);
    const int fixed_bits = frame.fixed_bits;
    const FixedSampleOffsets& offsets = frame.fixed_offsets;
    std::vector<uint64_t> per_setup(setups.size(), 0);
    parallel_for(setups.size(), threads,
                 [&](size_t i) { per_setup[i] = covered_samples(setups[i], offsets, fixed_bits); });
    std::vector<uint64_t> per_triangle(geometry.triangles.size(), 0);
    for (size_t i = 0; i < setups.size(); ++i) per_triangle[setups[i].triangle_id] += per_setup[i];
    return per_triangle;
}

double coverage_error(const std::vector<uint64_t>& covered, int samples_per_pixel, const std::vector<double>& areas) {
    if (covered.size() != areas.size())
        throw std::invalid_argument("coverage_error: one count and one area per triangle are needed");
    double error = 0.0, total = 0.0;
    for (size_t t = 0; t < areas.size(); ++t) {
        error += std::fabs(double(covered[t]) / samples_per_pixel - areas[t]);
        total += areas[t];
    }
    if (total == 0.0) return error == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return error / total;
}

double color_rmse(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.channels < 3 || b.channels < 3)
        throw std::invalid_argument("color_rmse: the images differ in size or are not RGB");
    const size_t pixels = static_cast<size_t>(a.width) * a.height;
    if (pixels == 0) return 0.0;
    double sum = 0.0;
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[p * a.channels + c]) - double(b.pixels[p * b.channels + c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(pixels)));
}

std::string reference_problem(const RenderSettings& settings, int grid) {
    const uint64_t pixels = uint64_t(std::max(settings.width, 0)) * uint64_t(std::max(settings.height, 0));
    const uint64_t samples = uint64_t(std::max(grid, 0)) * uint64_t(std::max(grid, 0));
    const uint64_t bytes = pixels * samples * sizeof_visibility_sample + pixels * 3;
    if (bytes <= kMaxFrameBytes) return "";
    const std::string side = std::to_string(grid);
    return "the " + side + "x" + side + "-sample reference image of a " + std::to_string(settings.width) + "x" +
           std::to_string(settings.height) + " scene needs " + std::to_string(bytes >> 20) + " MiB, over the " +
           std::to_string(kMaxFrameBytes >> 20) + " MiB cap (try a smaller --reference-grid)";
}

Image reference_image(const Scene& scene, int grid, const TradeoffOptions& options) {
    Scene reference = scene;
    reference.settings.samples = grid * grid;
    reference.settings.pattern = SamplePattern::grid;
    reference.settings.msaa = false;
    reference.settings.snap_bits = kMaxSnapBits;  // sample positions as exact as the fixed-point grid allows
    // Textures reconstructed bilinearly from level 0 and integrated over the pixel by the grid's samples: the
    // texture's own signal, box-filtered, rather than a mip level's pre-blurred one.
    reference.settings.texture_filter = TextureFilter::bilinear;
    const oracle::OracleScene geometry = oracle::oracle_scene(reference);
    oracle::SampleBuffer visibility;
    oracle::OracleOptions oracle_options;
    oracle_options.mode = options.oracle_mode;
    oracle_options.threads = options.threads;
    oracle::render_oracle(reference, geometry, oracle_options, visibility);
    // Shadows ray traced: the exact answer at every sample.
    std::unique_ptr<oracle::ShadowOracle> shadows;
    if (has_shadows(reference) && reference.settings.shading != ShadingMode::unlit)
        shadows = std::make_unique<oracle::ShadowOracle>(reference, geometry, options.threads);
    const oracle::OracleShader shader(reference, geometry, shadows.get(), oracle::ShadowAnswer::exact);
    const oracle::ResolveSettings resolve{reference.settings.samples, false, false,
                                          glm::dvec3(reference.settings.background)};
    const oracle::SampleLayers layers = oracle::trace_layers(reference, geometry, oracle_options);
    return image_of(oracle::render_image(shader, visibility, resolve, options.threads,
                                         layers.first.empty() ? nullptr : &layers, TransparencyMode::sorted));  // exact, whatever the mode
}

std::vector<bool> pareto_front(const std::vector<std::pair<double, double>>& points) {
    std::vector<bool> front(points.size(), false);
    for (size_t i = 0; i < points.size(); ++i) {
        const auto [time, error] = points[i];
        if (std::isnan(time) || std::isnan(error)) continue;
        bool dominated = false;
        for (size_t j = 0; j < points.size() && !dominated; ++j) {
            const auto [other_time, other_error] = points[j];
            dominated =
                j != i && other_time <= time && other_error <= error && (other_time < time || other_error < error);
        }
        front[i] = !dominated;
    }
    return front;
}

size_t measure_steps(size_t modes, const TradeoffOptions& options) {
    return 1 + modes + 1 + static_cast<size_t>(std::max(options.runs, 0));
}

SceneTradeoff measure_scene(const Scene& scene, const std::vector<const TradeoffMode*>& modes,
                            const TradeoffOptions& options, const std::function<void(const std::string&)>& progress) {
    SceneTradeoff out;
    out.scene = scene.path;
    out.name = std::filesystem::path(scene.path).stem().string();
    out.width = scene.settings.width;
    out.height = scene.settings.height;
    out.triangles = triangle_count(scene);
    auto report = [&](const std::string& step) {
        if (progress) progress(out.name + ": " + step);
    };

    report("reference oracle image");
    auto start = Clock::now();
    const Image reference = reference_image(scene, options.reference_grid, options);
    out.reference_ms = milliseconds_since(start);
    const std::vector<double> areas = exact_triangle_areas(scene);
    for (double area : areas) out.exact_area += area;

    // Accuracy, one mode at a time (each comparison holds two full visibility buffers).
    Scene work = scene;
    ComparisonOptions compare_options;
    compare_options.mode = options.oracle_mode;
    compare_options.threads = options.threads;
    std::vector<std::vector<uint8_t>> images(modes.size());
    for (size_t i = 0; i < modes.size(); ++i) {
        report(modes[i]->name);
        work.settings = apply_mode(*modes[i], scene.settings);
        build_needed_mip_chains(work);  // a filter mode's chains, once per texture
        ModeResult result;
        result.mode = modes[i]->name;
        result.description = modes[i]->description;
        result.settings = work.settings;
        if (work.settings.resolution_divisor == 1) {
            Comparison comparison = compare_scene(work, compare_options);
            result.samples = uint64_t(comparison.width) * uint64_t(comparison.height) * uint64_t(comparison.samples);
            result.genuine = comparison.disagreements_total();
            result.ambiguous = comparison.visibility.counts.ambiguous_total();
            result.color_rmse = color_rmse(comparison.raster.image, reference);
            images[i] = std::move(comparison.raster.image.pixels);
        } else {  // not comparable sample by sample (comparison_problem): the image alone
            RenderOptions render_options;
            render_options.threads = options.threads;
            render_options.keep_visibility = false;
            RenderResult frame = render(work, render_options);
            result.compared = false;
            result.samples = frame.stats.samples;
            result.color_rmse = color_rmse(frame.image, reference);
            images[i] = std::move(frame.image.pixels);
        }
        // Coverage at the resolution the frame rasterizes at: each internal sample stands for d^2 output ones.
        Scene internal = work;
        internal.settings = internal_frame_settings(work.settings);
        const TransformedScene geometry = run_vertex_stage(internal, vertex_stage_needs(internal.settings.shading));
        std::vector<uint64_t> covered = covered_sample_counts(internal, geometry, options.threads);
        const uint64_t area_per_sample = uint64_t(work.settings.resolution_divisor) * work.settings.resolution_divisor;
        for (uint64_t& count : covered) count *= area_per_sample;
        result.coverage_error = coverage_error(covered, work.settings.samples, areas);
        out.modes.push_back(std::move(result));
    }

    // Time: render_into, as `raster render` runs it but without a full-frame visibility buffer (the tiled path
    // skips it), its buffers reused from frame to frame. Rounds are interleaved (one frame of every mode per round,
    // after a warm-up round) so that drift in the machine's speed (clock boost, other processes) spreads over every
    // mode alike instead of favouring the last ones.
    RenderOptions render_options;
    render_options.threads = options.threads;
    render_options.keep_visibility = false;
    RenderResult frame;
    report("timing warm-up");
    for (size_t i = 0; i < modes.size(); ++i) {
        work.settings = out.modes[i].settings;
        render_into(work, render_options, frame);
        out.modes[i].timed_image_matches = frame.image.pixels == images[i];
        std::vector<uint8_t>().swap(images[i]);
    }
    for (int run = 0; run < options.runs; ++run) {
        report("timing round " + std::to_string(run + 1) + "/" + std::to_string(options.runs));
        for (ModeResult& result : out.modes) {
            work.settings = result.settings;
            start = Clock::now();
            render_into(work, render_options, frame);
            result.times_ms.push_back(milliseconds_since(start));
        }
    }
    for (ModeResult& result : out.modes) result.median_ms = median(result.times_ms);

    std::vector<std::pair<double, double>> points;
    for (const ModeResult& m : out.modes) points.emplace_back(m.median_ms, m.color_rmse);
    const std::vector<bool> front = pareto_front(points);
    for (size_t i = 0; i < out.modes.size(); ++i) out.modes[i].on_front = front[i];
    return out;
}

nlohmann::json tradeoff_json(const std::vector<SceneTradeoff>& scenes, const TradeoffOptions& options) {
    nlohmann::json scene_list = nlohmann::json::array();
    for (const SceneTradeoff& scene : scenes) {
        nlohmann::json modes = nlohmann::json::array();
        std::vector<const ModeResult*> front;
        for (const ModeResult& m : scene.modes) {
            modes.push_back({{"mode", m.mode},
                             {"description", m.description},
                             {"settings", mode_settings_json(m.settings)},
                             {"median_ms", m.median_ms},
                             {"times_ms", m.times_ms},
                             {"samples", m.samples},
                             {"genuine", m.compared ? nlohmann::json(m.genuine) : nlohmann::json(nullptr)},
                             {"ambiguous", m.compared ? nlohmann::json(m.ambiguous) : nlohmann::json(nullptr)},
                             {"color_rmse", m.color_rmse},
                             {"coverage_error", std::isfinite(m.coverage_error) ? nlohmann::json(m.coverage_error)
                                                                                : nlohmann::json(nullptr)},
                             {"timed_image_matches", m.timed_image_matches},
                             {"on_front", m.on_front}});
            if (m.on_front) front.push_back(&m);
        }
        std::stable_sort(front.begin(), front.end(),
                         [](const ModeResult* a, const ModeResult* b) { return a->median_ms < b->median_ms; });
        nlohmann::json front_names = nlohmann::json::array();
        for (const ModeResult* m : front) front_names.push_back(m->mode);
        scene_list.push_back({{"name", scene.name},
                              {"scene", scene.scene},
                              {"width", scene.width},
                              {"height", scene.height},
                              {"triangles", scene.triangles},
                              {"exact_area", scene.exact_area},
                              {"reference_ms", scene.reference_ms},
                              {"front", front_names},
                              {"modes", modes}});
    }
    return {{"runs", options.runs},
            {"threads", options.threads},
            {"reference",
             {{"grid", options.reference_grid},
              {"samples_per_pixel", options.reference_grid * options.reference_grid},
              {"oracle_mode", oracle::to_string(options.oracle_mode)}}},
            {"scenes", scene_list}};
}

std::string tradeoff_csv(const std::vector<SceneTradeoff>& scenes) {
    std::string csv =
        "scene,mode,shading,snap_bits,edges,samples_per_pixel,pattern,msaa,interpolation,depth,clipping,"
        "hierarchical_z,resolution_divisor,median_ms,samples,genuine,ambiguous,color_rmse,coverage_error,on_front\n";
    for (const SceneTradeoff& scene : scenes)
        for (const ModeResult& m : scene.modes) {
            const RenderSettings& s = m.settings;
            csv += csv_field(scene.name) + "," + csv_field(m.mode) + "," + to_string(s.shading) + "," +
                   std::to_string(s.snap_bits) + "," + to_string(s.modes.edges) + "," + std::to_string(s.samples) +
                   "," + to_string(s.pattern) + "," + (s.msaa ? "1" : "0") + "," + to_string(s.modes.interpolation) + "," + to_string(s.modes.depth) +
                   "," + to_string(s.modes.clipping) + "," + (s.modes.hierarchical_z ? "1" : "0") + "," +
                   std::to_string(s.resolution_divisor) + "," + format("%.3f", m.median_ms) + "," +
                   std::to_string(m.samples) + "," + (m.compared ? std::to_string(m.genuine) : "") + "," +
                   (m.compared ? std::to_string(m.ambiguous) : "") + "," + format("%.4f", m.color_rmse) + "," +
                   format("%.6f", m.coverage_error) + "," + (m.on_front ? "1" : "0") + "\n";
        }
    return csv;
}

}  // namespace raster::harness
