// Grading an image any rasterizer wrote (image_grade.h).
#include "harness/grading/image_grade.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "harness/comparison/oracle_run.h"
#include "oracle/compare/sample_openness.h"
#include "oracle/reference/sample_positions.h"
#include "raster/core/stopwatch.h"

namespace raster::harness {
namespace {

// Widens every judged pixel's interval by `levels` (the colour precision the rasterizer promises).
void widen(oracle::PixelBounds& bounds, int levels) {
    if (levels <= 0) return;
    for (oracle::ByteRange& range : bounds.ranges) {
        range.lo = std::max(0, range.lo - levels);
        range.hi = std::min(255, range.hi + levels);
    }
}

// Whether the pixel's bytes are the background's (`background`, per channel), within `levels`.
bool is_background(const uint8_t* bytes, const std::array<oracle::ByteRange, 3>& background, int levels) {
    for (int k = 0; k < 3; ++k)
        if (bytes[k] + levels < background[k].lo || bytes[k] > background[k].hi + levels) return false;
    return true;
}

}  // namespace

const char* to_string(PixelGrade grade) {
    switch (grade) {
        case PixelGrade::pass: return "pass";
        case PixelGrade::open: return "open";
        case PixelGrade::missing: return "missing";
        case PixelGrade::unexpected: return "unexpected";
        case PixelGrade::wrong_colour: return "wrong_colour";
    }
    return "?";
}

ImageGrade grade_image(const Scene& scene, const Image& image, const GradeOptions& options) {
    const RenderSettings& settings = scene.settings;
    if (image.width != settings.width || image.height != settings.height || image.channels != 3)
        throw std::invalid_argument("grade_image: the image is " + std::to_string(image.width) + " x " +
                                    std::to_string(image.height) + " with " + std::to_string(image.channels) +
                                    " channels, the scene " + std::to_string(settings.width) + " x " +
                                    std::to_string(settings.height) + " RGB");
    ImageGrade grade;
    grade.scene = scene.path;
    grade.width = settings.width;
    grade.height = settings.height;
    grade.samples = settings.samples;
    grade.budget = options.budget;

    Clock::time_point start = Clock::now();
    oracle::SampleBuffer visibility;
    const OracleRun run = run_oracle(scene, {options.mode, options.threads, false}, visibility);
    grade.oracle_ms = milliseconds_since(start);

    start = Clock::now();
    const oracle::ReferenceGeometry reference(scene, run.geometry);
    oracle::OpennessInputs openness;
    openness.oracle = &visibility;
    openness.reference = &reference;
    openness.offsets = oracle::sample_offsets_on_grid(settings.samples, settings.pattern, settings.snap_bits);
    openness.threads = options.threads;
    for (uint32_t id = 0; id < run.geometry.triangles.size(); ++id)
        openness.transparent.push_back(
            oracle::layered_material(oracle::triangle_material(scene, run.geometry.triangles[id])) ? 1 : 0);
    const oracle::SampleOpenness open = oracle::open_samples(openness);
    grade.sample_counts = open.counts;

    oracle::PixelBounds bounds =
        colour_bounds(scene, run, reference, openness.offsets, visibility, open.classes, options.threads);
    widen(bounds, options.colour_levels);
    const oracle::ColourCheck check =
        oracle::check_colours(bounds, {image.width, image.height, image.channels, image.pixels.data()}, run.image);
    grade.widest_interval = check.widths.widest;

    std::array<oracle::ByteRange, 3> background;
    for (int k = 0; k < 3; ++k) background[k] = oracle::byte_range(oracle::Interval(settings.background[k]));
    const size_t pixels = size_t(grade.width) * size_t(grade.height), samples = size_t(grade.samples);
    grade.pixels.assign(pixels, PixelGrade::pass);
    for (size_t pixel = 0; pixel < pixels; ++pixel) {
        PixelGrade& g = grade.pixels[pixel];
        if (check.genuine_pixels[pixel]) {
            bool covered = true, empty = true;
            for (size_t s = 0; s < samples; ++s) {
                const bool hit = visibility.triangle[pixel * samples + s] != kNoTriangle;
                covered &= hit;
                empty &= !hit;
            }
            const uint8_t* bytes = &image.pixels[pixel * 3];
            g = empty ? PixelGrade::unexpected
                : covered && is_background(bytes, background, options.colour_levels) ? PixelGrade::missing
                                                                                : PixelGrade::wrong_colour;
        } else if (bounds.state[pixel] != oracle::PixelState::judged) {
            g = PixelGrade::open;
        }
        ++grade.counts[static_cast<size_t>(g)];
    }
    grade.grade_ms = milliseconds_since(start);
    return grade;
}

nlohmann::json grade_json(const ImageGrade& grade) {
    nlohmann::json pixels = nlohmann::json::object();
    for (int g = 0; g < kPixelGradeCount; ++g) pixels[to_string(PixelGrade(g))] = grade.counts[size_t(g)];
    using oracle::SampleClass;
    const auto& c = grade.sample_counts;
    return {{"scene", grade.scene},
            {"width", grade.width},
            {"height", grade.height},
            {"samples", grade.samples},
            {"verdict", grade.pass() ? "pass" : "fail"},
            {"failing", grade.failing()},
            {"budget", grade.budget},
            {"pixels", pixels},
            {"samples_decided", c.count(SampleClass::agree)},
            {"samples_open",
             {{"edge_band", c.count(SampleClass::edge_band)},
              {"depth_tie", c.count(SampleClass::depth_tie)},
              {"clip_boundary", c.count(SampleClass::clip_boundary)},
              {"facing", c.count(SampleClass::facing)}}},
            {"widest_interval", grade.widest_interval},
            {"oracle_ms", grade.oracle_ms},
            {"grade_ms", grade.grade_ms}};
}

Image grade_mask(const ImageGrade& grade) {
    static constexpr uint8_t kColours[kPixelGradeCount][3] = {
        {0, 0, 0}, {90, 90, 90}, {40, 110, 255}, {250, 210, 0}, {230, 20, 20}};
    Image mask(grade.width, grade.height, 3);
    for (size_t pixel = 0; pixel < grade.pixels.size(); ++pixel)
        std::copy_n(kColours[static_cast<size_t>(grade.pixels[pixel])], 3, &mask.pixels[pixel * 3]);
    return mask;
}

}  // namespace raster::harness
