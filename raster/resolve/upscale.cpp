// The bilinear upscale in integers: each internal row blended horizontally, one array per output phase, the phases
// interleaved into a row of the output width; then two such rows blended per output row.
#include "raster/resolve/upscale.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "raster/core/parallel.h"
#include "raster/resolve/resolve.h"

namespace raster {
namespace {

constexpr size_t kBandRows = 16;  // rows per parallel task

// Where output coordinate `x` reads along an axis of `size` internal pixels: two clamped indices and their weights
// in units of 1 / (2 d). The centre is at (2x + 1 - d) / (2d) internal pixels.
struct Tap {
    int first, second;
    uint16_t first_weight, second_weight;
};
Tap tap(int x, int divisor, int size) {
    const int twice = 2 * divisor;
    const int numerator = 2 * x + 1 - divisor;
    const int index = numerator >= 0 ? numerator / twice : -((-numerator + twice - 1) / twice);  // floor
    const int fraction = numerator - index * twice;                                              // in [0, 2d)
    return {std::clamp(index, 0, size - 1), std::clamp(index + 1, 0, size - 1),
            static_cast<uint16_t>(twice - fraction), static_cast<uint16_t>(fraction)};
}

// Output pixel d i + p reads internal pixel i and its neighbour i + offset (offset -1 or +1), with the same weights
// for every i (units of 1 / (2d)): the taps above, by phase. Where the neighbour is outside the row it is i itself.
struct Phase {
    int offset;
    uint16_t neighbour_weight, own_weight;
};
Phase phase(int p, int divisor) {
    if (2 * p + 1 < divisor)
        return {-1, static_cast<uint16_t>(divisor - 2 * p - 1), static_cast<uint16_t>(divisor + 2 * p + 1)};
    return {+1, static_cast<uint16_t>(2 * p + 1 - divisor), static_cast<uint16_t>(3 * divisor - 2 * p - 1)};
}

// One phase of an internal row of `count` values (`step` values a pixel): every value blended with its neighbour's.
void blend_phase(const uint8_t* in, size_t count, size_t step, const Phase& phase, uint16_t* out) {
    const uint16_t own = phase.own_weight, neighbour = phase.neighbour_weight, whole = own + neighbour;
    const size_t edge = std::min(step, count);
    if (phase.offset < 0) {
        for (size_t k = 0; k < edge; ++k) out[k] = static_cast<uint16_t>(whole * in[k]);
        for (size_t k = edge; k < count; ++k) out[k] = static_cast<uint16_t>(neighbour * in[k - step] + own * in[k]);
    } else {
        for (size_t k = 0; k + step < count; ++k) out[k] = static_cast<uint16_t>(own * in[k] + neighbour * in[k + step]);
        for (size_t k = count - edge; k < count; ++k) out[k] = static_cast<uint16_t>(whole * in[k]);
    }
}

// The d phase arrays of an internal row of `pixels` pixels interleaved: pixel d i + p of `row` is pixel i of phase p.
template <int C>
void interleave(const uint16_t* phases, size_t pixels, int divisor, uint16_t* row) {
    const size_t count = pixels * C;
    for (size_t i = 0; i < pixels; ++i)
        for (int p = 0; p < divisor; ++p, row += C) std::memcpy(row, phases + p * count + i * C, C * sizeof(uint16_t));
}

// Two blended rows into an output row, rounded half up: the sum is in units of 2^-Shift of a byte. A constant
// shift keeps the loop in 16-bit lanes: at most 4 d^2 255 + half, under 2^16 for d <= 4.
template <int Shift>
void blend_rows(const uint16_t* a, const uint16_t* b, uint16_t first_weight, uint16_t second_weight, size_t count,
                uint8_t* out) {
    constexpr uint16_t kHalf = 1u << (Shift - 1);
    for (size_t k = 0; k < count; ++k)
        out[k] = static_cast<uint8_t>(static_cast<uint16_t>(first_weight * a[k] + second_weight * b[k] + kHalf) >> Shift);
}

}  // namespace

void upscale_image(const Image& internal, int divisor, int threads, std::vector<uint16_t>& rows, Image& out) {
    if (divisor != 1 && divisor != 2 && divisor != 4)
        throw std::invalid_argument("upscale_image: divisor " + std::to_string(divisor) + " is not 1, 2 or 4");
    if (internal.channels < 1 || internal.channels > 4)
        throw std::invalid_argument("upscale_image: " + std::to_string(internal.channels) + " channels, not 1 to 4");
    if (&internal == &out) throw std::invalid_argument("upscale_image: the output is the input");
    const int channels = internal.channels;
    const int width = internal.width * divisor, height = internal.height * divisor;
    size_image(out, width, height, channels);
    if (divisor == 1) {
        std::copy(internal.pixels.begin(), internal.pixels.end(), out.pixels.begin());
        return;
    }
    // Horizontal: every internal row blended to the output width, each value in units of 1 / (2d) of a byte.
    const size_t pixels = static_cast<size_t>(internal.width), count = pixels * channels;
    const size_t row_values = static_cast<size_t>(width) * channels;
    rows.resize(row_values * static_cast<size_t>(internal.height));
    const size_t bands = (static_cast<size_t>(internal.height) + kBandRows - 1) / kBandRows;
    parallel_for(bands, threads, [&](size_t band) {
        thread_local std::vector<uint16_t> phases;
        phases.resize(count * divisor);
        const size_t end = std::min(static_cast<size_t>(internal.height), (band + 1) * kBandRows);
        for (size_t r = band * kBandRows; r < end; ++r) {
            const uint8_t* in = internal.at(0, static_cast<int>(r));
            for (int p = 0; p < divisor; ++p)
                blend_phase(in, count, static_cast<size_t>(channels), phase(p, divisor), &phases[p * count]);
            uint16_t* row = &rows[r * row_values];
            switch (channels) {
                case 1: interleave<1>(phases.data(), pixels, divisor, row); break;
                case 2: interleave<2>(phases.data(), pixels, divisor, row); break;
                case 3: interleave<3>(phases.data(), pixels, divisor, row); break;
                default: interleave<4>(phases.data(), pixels, divisor, row); break;
            }
        }
    });
    // Vertical: two blended rows per output row; the sum is in units of 1 / (4 d^2), rounded half up.
    const size_t out_bands = (static_cast<size_t>(height) + kBandRows - 1) / kBandRows;
    parallel_for(out_bands, threads, [&](size_t band) {
        const size_t end = std::min(static_cast<size_t>(height), (band + 1) * kBandRows);
        for (size_t y = band * kBandRows; y < end; ++y) {
            const Tap t = tap(static_cast<int>(y), divisor, internal.height);
            const uint16_t* a = &rows[static_cast<size_t>(t.first) * row_values];
            const uint16_t* b = &rows[static_cast<size_t>(t.second) * row_values];
            uint8_t* row = out.at(0, static_cast<int>(y));
            if (divisor == 2) blend_rows<4>(a, b, t.first_weight, t.second_weight, row_values, row);  // 4 d^2 = 2^4
            else blend_rows<6>(a, b, t.first_weight, t.second_weight, row_values, row);               // d = 4: 2^6
        }
    });
}

}  // namespace raster
