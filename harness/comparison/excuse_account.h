// The excuse accounting: what each allowance of the oracle's precision model excused in one comparison, in samples
// and in pixels, and the share of the frame each may excuse before the allowance, not raster, is suspect.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/comparison/scene_comparison.h"

namespace raster::harness {

// What one excuse class excused, out of how many, against its cap (a share of `of`).
struct ExcuseLine {
    std::string name;  // "edge_band", "depth_tie", "clip_boundary", "facing", "wide_interval", "shadow_edge", ...
    std::string unit;  // "samples" or "pixels"
    uint64_t count = 0, of = 0;
    double cap = 0;
    double share() const { return of ? static_cast<double>(count) / static_cast<double>(of) : 0.0; }
    bool within() const { return static_cast<double>(count) <= cap * static_cast<double>(of); }
};

// The caps, as shares of the frame's samples or pixels; excuse_account.cpp derives each beside its constant.
struct ExcuseCaps {
    double sample_share = 0, pixel_share = 0;  // each of the four sample classes (edge band, depth tie, ...)
    double wide_interval = 0;                  // pixels
    double shadow_open = 0;                    // pixels: edge + depth
    double shadow_inconsistent = 0;            // pixels: the ray and the footprint differ
    double layers_open = 0;                    // pixels: edge + depth + order
};

// The caps for one frame of the corpus (a scene of ordinary size), and for the differential fuzz corpus summed
// (32-pixel frames of up to eight random triangles: edges are a far larger share of the frame there).
extern const ExcuseCaps kFrameCaps;
extern const ExcuseCaps kFuzzCorpusCaps;

struct ExcuseAccount {
    std::vector<ExcuseLine> lines;
    // Sums another account into this one, line by line (both from account_excuses, so their lines match).
    void add(const ExcuseAccount& other);
    bool within() const;
    std::string violations() const;  // one line per class over its cap; empty when within
};

// Every excuse class of the comparison: the four sample classes in samples and in pixels (a pixel with any sample
// of the class), pixels with a colour interval wider than kWideIntervalLevels, and the pixels the shadow and the
// transparency models left open.
ExcuseAccount account_excuses(const Comparison& comparison, const ExcuseCaps& caps = kFrameCaps);

}  // namespace raster::harness
