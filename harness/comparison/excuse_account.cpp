// The excuse accounting: each class's samples and pixels from the comparison's per-sample classes and open pixels.
#include "harness/comparison/excuse_account.h"

#include <array>
#include <cstdio>

namespace raster::harness {

// One frame of the corpus. A sample can flip only within the radius r of an edge (edge band), where two surfaces meet
// (depth tie), where a surface crosses the near or far plane (clip boundary) or on a triangle seen edge-on (facing):
// each is a band along a line. At 8 snap bits r is about 2^-8 px with the float error; a mesh of 8-pixel triangles
// has about 0.25 px of edge per pixel, so a band is 2 r 0.25 = 0.2% of the frame, and a sample in it flips with
// probability at most 1/2: 0.1% of the samples per class. A pixel holds N samples, so a band reaches up to N times
// more pixels than samples; at 16 samples that is 1.6%, and the cap is 1%.
constexpr double kFrameSampleShare = 0.001;
constexpr double kFramePixelShare = 0.01;
// The colour check must judge most of the frame to mean anything: wide intervals may take at most a tenth of it.
constexpr double kFrameWideShare = 0.10;
// The shadow model leaves open the pixels where an occluder's edge crosses the filter footprint or a receiver is
// within the bias: bands along shadow edges and contact lines, a few pixels wide (the PCF footprint), 2% of a frame;
// the transparent layers' edges and their meetings with surfaces are bands one pixel wide: 1%.
constexpr double kFrameShadowShare = 0.02;
constexpr double kFrameLayerShare = 0.01;

const ExcuseCaps kFrameCaps = [] {
    ExcuseCaps caps;
    caps.sample_share = kFrameSampleShare;
    caps.pixel_share = kFramePixelShare;
    caps.wide_interval = kFrameWideShare;
    caps.shadow_open = kFrameShadowShare;
    caps.shadow_inconsistent = 0;  // the ray and the exact footprint never disagree
    caps.layers_open = kFrameLayerShare;
    return caps;
}();

// The differential fuzz corpus, summed: frames of at most 32 pixels a side holding up to eight random triangles
// whose sides are the frame's (about 0.75 px of edge per pixel), lenses at their extremes, and extreme coordinates
// whose radius may reach a pixel (differential_scene.cpp's kMaxExtremeRadius): the bands are about ten times the
// corpus's share, so 1% of samples and 10% of pixels per class; extreme lenses and slivers make steep colours,
// so wide intervals may take a fifth of the pixels. The transparent layers' bands run along the same random
// triangles' edges (every mesh becomes a layer when the target draws texture alpha), so they scale alike: 10%.
const ExcuseCaps kFuzzCorpusCaps = [] {
    ExcuseCaps caps = kFrameCaps;
    caps.sample_share = 10 * kFrameSampleShare;
    caps.pixel_share = 10 * kFramePixelShare;
    caps.layers_open = 10 * kFrameLayerShare;
    caps.wide_interval = 2 * kFrameWideShare;
    return caps;
}();

void ExcuseAccount::add(const ExcuseAccount& other) {
    if (lines.empty()) {
        lines = other.lines;
        return;
    }
    for (size_t i = 0; i < lines.size() && i < other.lines.size(); ++i) {
        lines[i].count += other.lines[i].count;
        lines[i].of += other.lines[i].of;
    }
}

bool ExcuseAccount::within() const {
    for (const ExcuseLine& line : lines)
        if (!line.within()) return false;
    return true;
}

std::string ExcuseAccount::violations() const {
    std::string text;
    for (const ExcuseLine& line : lines) {
        if (line.within()) continue;
        char row[256];
        std::snprintf(row, sizeof row, "%s excused %llu of %llu %s (%.4f%%), over its cap of %.4f%%\n",
                      line.name.c_str(), static_cast<unsigned long long>(line.count),
                      static_cast<unsigned long long>(line.of), line.unit.c_str(), 100.0 * line.share(),
                      100.0 * line.cap);
        text += row;
    }
    return text;
}

ExcuseAccount account_excuses(const Comparison& c, const ExcuseCaps& caps) {
    using oracle::SampleClass;
    constexpr std::array<SampleClass, 4> kClasses = {SampleClass::edge_band, SampleClass::depth_tie,
                                                     SampleClass::clip_boundary, SampleClass::facing};
    const uint64_t pixels = uint64_t(c.width) * uint64_t(c.height);
    const size_t samples = static_cast<size_t>(c.samples > 0 ? c.samples : 1);
    // Per class, the pixels with at least one sample of it.
    std::array<uint64_t, 4> class_pixels{};
    const std::vector<SampleClass>& classes = c.visibility.classes;
    for (size_t first = 0; first + samples <= classes.size(); first += samples) {
        std::array<bool, 4> seen{};
        for (size_t s = first; s < first + samples; ++s)
            for (size_t k = 0; k < kClasses.size(); ++k) seen[k] = seen[k] || classes[s] == kClasses[k];
        for (size_t k = 0; k < kClasses.size(); ++k) class_pixels[k] += seen[k];
    }
    ExcuseAccount account;
    for (size_t k = 0; k < kClasses.size(); ++k) {
        const std::string name = oracle::to_string(kClasses[k]);
        account.lines.push_back(
            {name, "samples", c.visibility.counts.count(kClasses[k]), classes.size(), caps.sample_share});
        account.lines.push_back({name, "pixels", class_pixels[k], pixels, caps.pixel_share});
    }
    // The colour check's wide intervals: the PNG's and the PPM's bounds are the same, so the PNG's count stands for
    // both (a frame without a colour image has none).
    account.lines.push_back({"wide_interval", "pixels", c.colour.png.wide, pixels, caps.wide_interval});
    account.lines.push_back(
        {"shadow_open", "pixels", c.shadows.edge_pixels + c.shadows.depth_pixels, pixels, caps.shadow_open});
    account.lines.push_back(
        {"shadow_inconsistent", "pixels", c.shadows.inconsistent_pixels, pixels, caps.shadow_inconsistent});
    account.lines.push_back({"layers_open", "pixels",
                             c.transparency.edge_pixels + c.transparency.depth_pixels + c.transparency.order_pixels,
                             pixels, caps.layers_open});
    return account;
}

}  // namespace raster::harness
