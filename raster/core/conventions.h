// The conventions every module shares, written down once: spaces, image rows, fixed point, fill rule, depth.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster {

// World and view space: right-handed, y up; the camera looks down -z (OpenGL). View depth = -z_view > 0.
//
// Clip space: OpenGL-style x, y in [-w, w]; the depth row is reversed-Z (see below), so after the divide the
// visible volume is x, y in [-1, 1] and depth in [0, 1] with the near plane at 1 and the far plane at 0.
//
// Screen space: x to the right, y DOWN, in pixels. Pixel (x, y) covers [x, x+1) x [y, y+1); its centre is
// (x + 0.5, y + 0.5). Row 0 is the top row of the output image, and images are written top row first (PNG and
// PPM order). NDC (-1, +1) maps to screen (0, 0), NDC (+1, -1) to (width, height).
//
// Sub-pixel precision: vertices are snapped to 1/2^snap_bits of a pixel (default 8 bits, as llvmpipe's
// FIXED_ORDER and the Vulkan Roadmap 2026 minimum): floor(x * 2^snap_bits + 0.5), round half up.
// Sample positions live on a grid of 1/2^fixed_bits, fixed_bits = max(snap_bits, 4), fine enough for every
// standard pattern (multiples of 1/16). Edge functions are evaluated exactly in 64-bit integers on that grid.
//
// Fill rule: top-left. With the edge function E_ab(P) = cross(b - a, P - a) (screen space, y down) and the
// triangle wound so that E > 0 inside, a sample with E == 0 belongs to the triangle only when the edge is a
// "top" edge (horizontal, dx > 0) or a "left" edge (dy < 0). So a sample on an edge shared by two triangles is
// covered by exactly one of them, and a sample on a shared vertex by exactly one triangle of the fan.
//
// Front faces: counter-clockwise in NDC (y up), as OpenGL's default; that is E_ab(c) < 0 in screen space (y down).
//
// Depth: the z-buffer holds reversed-Z float depth d = a + b / w_view with d(near) = 1 and d(far) = 0, so
// larger is nearer and the buffer is cleared to 0. Reversed-Z keeps ~1e-7 relative error at every distance
// even at near = 1e-6, far = 1e9, where OpenGL's [-1, 1] mapping collapses ((f+n)/(f-n) rounds to 1.0f).
// The visibility buffer reports view depth (distance along -z), not d.

// Overflow argument for the 64-bit edge functions. Images are at most kMaxImageDimension = 2^14 pixels on a
// side and fixed_bits <= 16, so after clipping to the viewport every snapped coordinate X lies in
// [0, 2^30] (vertices are clamped there). Differences of two coordinates are < 2^31 in magnitude, each product
// in E = dx * (Py - ay) - dy * (Px - ax) is < 2^62, and the difference of two such products is < 2^63:
// no int64 overflow is possible. Incremental stepping adds at most one such value per sample.
//
// Guard band (Clipping::guard_band): the side planes move out to x, y = +-g w, so snapped coordinates lie in
// [-(g-1)/2 E, (g+1)/2 E] for an extent E (pixels << fixed_bits). With R = g E the range of differences and
// M = (g+1)/2 E the largest magnitude, |c| <= 2 R M and |a X| + |b Y| <= 2 R M, so E < 2^63 needs R M <= 2^60:
// g (g+1)/2 E^2 <= 2^60. guard_band_factor gives the largest g <= kGuardBand that satisfies it (at g = 1 it is
// the argument above), so large images at 16 fixed bits fall back towards full clipping.
inline constexpr int kMaxImageDimension = 1 << 14;
inline constexpr double kGuardBand = 4.0;
inline constexpr int kMinSnapBits = 1;
inline constexpr int kMaxSnapBits = 16;
inline constexpr int kDefaultSnapBits = 8;
inline constexpr int kMinFixedBits = 4;

inline constexpr int fixed_bits_for(int snap_bits) { return snap_bits > kMinFixedBits ? snap_bits : kMinFixedBits; }

// The guard band factor g in [1, kGuardBand] for an image of this size at these fixed bits (see above).
inline double guard_band_factor(int width, int height, int fixed_bits) {
    const double extent = static_cast<double>(width > height ? width : height) * static_cast<double>(int64_t{1} << fixed_bits);
    const double limit = 0x1p60 / (extent * extent);  // g (g + 1) / 2 <= limit
    double g = kGuardBand;
    while (g > 1.0 && g * (g + 1.0) * 0.5 > limit) g -= 0.25;
    return g < 1.0 ? 1.0 : g;
}

// A sample that no triangle covers has this triangle id.
inline constexpr uint32_t kNoTriangle = 0xFFFFFFFFu;

// Per-sample buffers (raster's visibility buffer, the oracle's) store samples pixel by pixel, row by row from the
// top, `samples` consecutive entries per pixel: sample s of pixel (x, y) is at this index.
inline constexpr size_t sample_index(int x, int y, int s, int width, int samples) {
    return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * static_cast<size_t>(samples) +
           static_cast<size_t>(s);
}

}  // namespace raster
