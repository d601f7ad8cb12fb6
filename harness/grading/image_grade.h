// Grading an image any rasterizer wrote: the oracle's frame of the scene, each sample decided or open under the
// precision the rasterizer promises (oracle/compare/sample_openness.h), each pixel whose samples are all decided
// judged against the colour interval the oracle derives, and each pixel outside it told apart as missing (the
// background where the scene is covered), unexpected (something drawn where nothing is) or a wrong colour.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/ray_caster.h"
#include "raster/image/image.h"
#include "raster/scene/scene.h"

namespace raster::harness {

enum class PixelGrade : uint8_t {
    pass,          // every sample decided, the colour inside its interval
    open,          // some sample may be drawn otherwise by a correct rasterizer: not judged
    missing,       // covered in the scene, the background's colour in the image
    unexpected,    // nothing there in the scene, something in the image
    wrong_colour,  // outside the interval otherwise
};
inline constexpr int kPixelGradeCount = 5;
const char* to_string(PixelGrade grade);  // "pass", "open", "missing", "unexpected", "wrong_colour"
inline bool is_failing(PixelGrade grade) { return grade >= PixelGrade::missing; }

struct GradeOptions {
    oracle::OracleMode mode = oracle::OracleMode::robust;
    int threads = 0;
    int colour_levels = 0;     // how many levels a channel may be off past the derived interval (colour precision)
    uint64_t budget = 0;       // failing pixels allowed (a weak mode, as dEQP's); 0: strict
};

struct ImageGrade {
    std::string scene;
    int width = 0, height = 0, samples = 0;
    std::vector<PixelGrade> pixels;                  // per pixel, row by row from the top
    std::array<uint64_t, kPixelGradeCount> counts{};  // pixels per grade
    oracle::ComparisonCounts sample_counts;          // samples: decided (agree) or open, by the allowance
    int widest_interval = 0;                         // the widest judged interval, in levels
    uint64_t budget = 0;
    double oracle_ms = 0, grade_ms = 0;

    uint64_t count(PixelGrade grade) const { return counts[static_cast<size_t>(grade)]; }
    uint64_t failing() const {
        return count(PixelGrade::missing) + count(PixelGrade::unexpected) + count(PixelGrade::wrong_colour);
    }
    bool pass() const { return failing() <= budget; }
};

// Grades `image` (RGB, the scene's size: else std::invalid_argument) against the valid `scene`, whose settings
// carry what the rasterizer promises: samples per pixel and their pattern, MSAA, sub-pixel bits.
ImageGrade grade_image(const Scene& scene, const Image& image, const GradeOptions& options);

// {scene, width, height, samples, verdict, failing, budget, pixels: {pass, open, missing, unexpected, wrong_colour},
//  samples_decided, samples_open: {edge_band, depth_tie, clip_boundary, facing}, widest_interval, oracle_ms, grade_ms}
nlohmann::json grade_json(const ImageGrade& grade);

// The error mask: per pixel, black where it passes, grey where it is open, blue where the scene's surface is
// missing, yellow where something unexpected was drawn, red where the colour is wrong.
Image grade_mask(const ImageGrade& grade);

}  // namespace raster::harness
