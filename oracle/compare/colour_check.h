// The colour check: per pixel, the bytes a correct raster may write there (the oracle's own shading over each
// sample's barycentric tolerance, resolved as docs/oracle.md defines it, its float error included), and raster's image,
// decoded from the bytes it wrote, against them. A pixel whose samples do not all agree is not judged here: its
// samples' own classes say why.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "oracle/compare/layer_check.h"
#include "oracle/compare/raster_output.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/layer_resolve.h"
#include "oracle/reference/oracle_image.h"
#include "oracle/reference/pixel_resolve.h"
#include "oracle/reference/shading_precision.h"

namespace raster::oracle {

enum class PixelState : uint8_t {
    judged,     // every sample agrees: the colour is checked against `ranges`
    ambiguous,  // some sample is ambiguous (and none genuine)
    genuine,    // some sample disagrees genuinely
};

struct PixelBounds {
    int width = 0, height = 0, channels = 3;
    std::vector<PixelState> state;  // per pixel
    std::vector<ByteRange> ranges;  // per pixel and channel, for judged pixels
    // With shadows (an open_shader given): per pixel the shadow verdicts its shading met (ShadowTally), and, where a
    // light with shadows reaches it, the bytes allowed whatever the shadow maps said (ShadowAnswer::open), so that a
    // pixel outside `ranges` but inside these is told apart as a shadow disagreement. Empty without shadows.
    std::vector<uint8_t> shadow_seen;
    std::vector<ByteRange> open_ranges;  // per pixel and channel; {0, 255} where no light with shadows reaches
    // With transparency (layers given): per pixel, 1 where raster must composite some layer there, and why the
    // layers leave the pixel open (LayerOpen, none where they do not; such a pixel is ambiguous). Empty without.
    std::vector<uint8_t> layered;
    std::vector<LayerOpen> layer_open;
};

struct ColourInputs {
    const SampleBuffer* oracle = nullptr;
    const std::vector<SampleClass>* classes = nullptr;  // compare_visibility's
    const ReferenceGeometry* reference = nullptr;
    const OracleShader* shader = nullptr;       // ShadowAnswer::allowed
    const OracleShader* open_shader = nullptr;  // ShadowAnswer::open, when a light casts shadows; else null
    ResolveSettings resolve;
    std::vector<glm::dvec2> offsets;  // the sample positions inside a pixel
    int threads = 0;
    // With transparency: the oracle's layers and their verdicts, and raster's compositing mode.
    const SampleLayers* layers = nullptr;
    const LayerVerdicts* layer_verdicts = nullptr;
    TransparencyMode transparency = TransparencyMode::sorted;
};

// For every pixel whose samples all agree, the bytes raster may write. Deterministic for any thread count.
PixelBounds pixel_bounds(const ColourInputs& inputs);

// A pixel of raster's image outside its range, with what the report shows on hover.
struct ColourDisagreement {
    int x = 0, y = 0, channels = 3;
    std::array<int, 4> raster{}, oracle{};
    std::array<ByteRange, 4> allowed{};
};
inline constexpr size_t kListedColourDisagreements = 200;

// How wide the colour intervals of the judged pixels are: per pixel the widest channel's hi - lo, counted in bins
// 0, 1, 2-3, 4-7, ..., 128-255 levels. The oracle judges a pixel only as sharply as its interval: a wide one excuses
// much, so it is counted, shown, and capped.
inline constexpr int kIntervalWidthBins = 9;
struct IntervalWidths {
    std::array<uint64_t, kIntervalWidthBins> pixels{};
    int widest = 0;
    static int bin(int width);         // 0 -> 0, 1 -> 1, 2..3 -> 2, ..., 128..255 -> 8
    static const char* label(int bin);  // "0", "1", "2-3", ..., "128-255"
};
// A pixel whose interval is wider than this many levels (an eighth of the range) is counted as ambiguous, not
// judged: its bytes are still checked against the interval (a byte outside it is genuine), but it tells too little
// to count as agreement. Correct frames meet such intervals where the oracle's tolerance meets a steep colour:
// texture minification near a horizon, a shadow's edge inside the filter footprint.
inline constexpr int kWideIntervalLevels = 32;

struct ColourCheck {
    uint64_t judged = 0, ambiguous = 0, genuine = 0;  // pixels (ambiguous: by their samples, or a wide interval)
    uint64_t wide = 0;                                // of the ambiguous: wider than kWideIntervalLevels
    IntervalWidths widths;                            // over the pixels whose samples all agree
    uint64_t genuine_shadow = 0;                // of the genuine ones: inside the bounds once shadows are left open
    std::vector<uint8_t> shadow_pixels;         // per pixel: 1 where genuine and explained by a shadow test
    int max_difference = 0;                     // largest |raster - oracle| byte difference over judged pixels
    std::vector<uint8_t> genuine_pixels;        // per pixel: 1 where the colour is outside its range
    std::vector<ColourDisagreement> first;      // the first kListedColourDisagreements, row by row
};

// Checks `image` (a PPM has no alpha, so only the channels both have are compared; an image of another size than
// the bounds is genuine at every pixel); `oracle` is the oracle's own image, of the bounds' size, for the
// differences and the disagreements' listing.
ColourCheck check_colours(const PixelBounds& bounds, const RasterPixels& image, const OracleImage& oracle);

}  // namespace raster::oracle
