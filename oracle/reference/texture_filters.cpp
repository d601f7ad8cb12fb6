// The oracle's texture filters over boxes (texture_filters.h), from docs/textures.md, with texture_precision.h's
// roundings.
#include "oracle/reference/texture_filters.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "oracle/reference/precision.h"
#include "oracle/reference/texture_precision.h"

namespace raster::oracle {

namespace {

// Past this many texels along an axis a box is bounded by the level's range instead; past 2 cells (a box over more
// than the 3 x 3 texels around a point) bilinear is bounded by the hull of the texels it spans, which holds every
// convex combination of them.
constexpr long long kMostSpanned = 32;
constexpr long long kMostCornerCells = 2;

Interval3 texel_hull(const OracleTextureLevel& level, long long x0, long long x1, long long y0, long long y1,
                     TextureWrap wrap, double& magnitude);

Interval3 level_range(const OracleTextureLevel& level) {
    return {Interval(level.min.x, level.max.x), Interval(level.min.y, level.max.y), Interval(level.min.z, level.max.z)};
}

Interval3 point(const glm::dvec3& v) { return Interval3(v); }

double largest(const glm::dvec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

// The box of texel-space coordinates x = u w, y = (1 - v) h that raster computes from float u and v.
struct TexelBox {
    Interval x, y;
};
TexelBox texel_box(const OracleTextureLevel& level, const UvBox& uv) {
    const Interval x = uv.u * Interval(level.width);
    const Interval y = (Interval(1.0) - uv.v) * Interval(level.height);
    return {x.widened(double_gamma(2) * x.magnitude()), y.widened(double_gamma(2) * y.magnitude())};
}

bool finite(const Interval& i) { return std::isfinite(i.lo) && std::isfinite(i.hi); }

const glm::dvec3& wrapped(const OracleTextureLevel& level, long long x, long long y, TextureWrap wrap) {
    return level.texel(static_cast<int>(oracle_wrap(x, level.width, wrap)), static_cast<int>(oracle_wrap(y, level.height, wrap)));
}

Interval3 texel_hull(const OracleTextureLevel& level, long long x0, long long x1, long long y0, long long y1,
                     TextureWrap wrap, double& magnitude) {
    Interval3 out;
    magnitude = 0.0;
    bool first = true;
    for (long long y = y0; y <= y1; ++y) {
        for (long long x = x0; x <= x1; ++x) {
            const glm::dvec3& t = wrapped(level, x, y, wrap);
            out = first ? point(t) : hull(out, point(t));
            magnitude = std::max(magnitude, largest(t));
            first = false;
        }
    }
    return out;
}

}  // namespace

long long oracle_wrap(long long i, int n, TextureWrap wrap) {
    if (wrap == TextureWrap::clamp) return i < 0 ? 0 : i >= n ? n - 1 : i;
    const long long period = wrap == TextureWrap::repeat ? n : 2LL * n;
    const long long m = ((i % period) + period) % period;
    return m < n ? m : period - 1 - m;
}

Interval3 nearest_over(const OracleTextureLevel& level, int level_index, const UvBox& uv, TextureWrap wrap) {
    const TexelBox box = texel_box(level, uv);
    if (!finite(box.x) || !finite(box.y)) return level_range(level).widened(texel_error(level_index, largest(level.max)));
    const long long x0 = static_cast<long long>(std::floor(box.x.lo)), x1 = static_cast<long long>(std::floor(box.x.hi));
    const long long y0 = static_cast<long long>(std::floor(box.y.lo)), y1 = static_cast<long long>(std::floor(box.y.hi));
    double magnitude = largest(level.max);
    const Interval3 out = x1 - x0 >= kMostSpanned || y1 - y0 >= kMostSpanned
                              ? level_range(level)
                              : texel_hull(level, x0, x1, y0, y1, wrap, magnitude);
    return out.widened(texel_error(level_index, magnitude));
}

Interval3 bilinear_over(const OracleTextureLevel& level, int level_index, const UvBox& uv, TextureWrap wrap) {
    const TexelBox box = texel_box(level, uv);
    if (!finite(box.x) || !finite(box.y)) return level_range(level).widened(texel_error(level_index, largest(level.max)));
    const Interval px = box.x - Interval(0.5), py = box.y - Interval(0.5);
    const long long cx0 = static_cast<long long>(std::floor(px.lo)), cx1 = static_cast<long long>(std::floor(px.hi));
    const long long cy0 = static_cast<long long>(std::floor(py.lo)), cy1 = static_cast<long long>(std::floor(py.hi));
    if (cx1 - cx0 >= kMostSpanned || cy1 - cy0 >= kMostSpanned) {
        const double magnitude = largest(level.max);
        return level_range(level).widened(float_gamma(kBilinearRoundings) * magnitude + texel_error(level_index, magnitude));
    }
    if (cx1 - cx0 >= kMostCornerCells || cy1 - cy0 >= kMostCornerCells) {
        double magnitude = 0.0;
        const Interval3 out = texel_hull(level, cx0, cx1 + 1, cy0, cy1 + 1, wrap, magnitude);
        return out.widened(float_gamma(kBilinearRoundings) * magnitude + texel_error(level_index, magnitude));
    }
    // Bilinear interpolation is linear in each fraction, so over a cell's sub-box its extremes are at the corners.
    Interval3 out;
    bool first = true;
    for (long long cy = cy0; cy <= cy1; ++cy) {
        for (long long cx = cx0; cx <= cx1; ++cx) {
            const glm::dvec3 &a = wrapped(level, cx, cy, wrap), &b = wrapped(level, cx + 1, cy, wrap),
                             &c = wrapped(level, cx, cy + 1, wrap), &d = wrapped(level, cx + 1, cy + 1, wrap);
            const double magnitude = std::max({largest(a), largest(b), largest(c), largest(d)});
            const double fx[2] = {std::max(px.lo, double(cx)) - cx, std::min(px.hi, double(cx + 1)) - cx};
            const double fy[2] = {std::max(py.lo, double(cy)) - cy, std::min(py.hi, double(cy + 1)) - cy};
            for (double tx : fx) {
                for (double ty : fy) {
                    const glm::dvec3 value = (1 - ty) * ((1 - tx) * a + tx * b) + ty * ((1 - tx) * c + tx * d);
                    const Interval3 corner = point(value).widened(float_gamma(kBilinearRoundings) * magnitude +
                                                                  texel_error(level_index, magnitude));
                    out = first ? corner : hull(out, corner);
                    first = false;
                }
            }
        }
    }
    return out;
}

Interval3 trilinear_over(const OracleTexture& texture, const UvBox& uv, Interval lod, TextureWrap wrap) {
    const int last = static_cast<int>(texture.levels.size()) - 1;
    auto level = [&](int d) { return bilinear_over(texture.levels[d], d, uv, wrap); };
    Interval3 out;
    bool first = true;
    auto add = [&](const Interval3& v) {
        out = first ? v : hull(out, v);
        first = false;
    };
    // At or below 0 (or NaN) level 0; at or past the last level, the last.
    if (!(lod.lo > 0.0)) add(level(0));
    if (lod.hi >= last) add(level(last));
    const double lo = std::max(lod.lo, 0.0), hi = std::min(lod.hi, static_cast<double>(last));
    for (int d = static_cast<int>(std::floor(lo)); d < last && d <= hi; ++d) {
        // Inside [d, d + 1) the value is (1 - f) B_d + f B_(d+1), linear in f: its extremes are at the ends.
        const double f_lo = std::max(lo, double(d)) - d, f_hi = std::min(hi, double(d + 1)) - d;
        const Interval3 fine = level(d), coarse = level(d + 1);
        const double magnitude = std::max(fine.magnitude(), coarse.magnitude());
        for (double f : {f_lo, f_hi}) add((Interval(1.0 - f) * fine + Interval(f) * coarse)
                                              .widened(float_gamma(kLevelBlendRoundings) * magnitude));
    }
    return out;
}

namespace {

// rho = |d * size| over a box of derivatives, with raster's roundings.
Interval rho_of(const UvBox& d, const OracleTextureLevel& level0) {
    const Interval r = sqrt(square(d.u * Interval(level0.width)) + square(d.v * Interval(level0.height)));
    return r.widened(float_gamma(kRhoRoundings) * r.magnitude());
}

Interval log2_of(Interval x) {
    const Interval l(x.lo > 0.0 ? std::log2(x.lo) : -INFINITY, x.hi > 0.0 ? std::log2(x.hi) : -INFINITY);
    return l.widened(float_gamma(kLodRoundings) * std::max(1.0, l.magnitude()));
}

}  // namespace

Interval3 filtered_over(const OracleTexture& texture, const SamplerState& binding, const TextureFootprintBox& box) {
    const OracleTextureLevel& level0 = texture.levels[0];
    switch (binding.filter) {
        case TextureFilter::nearest: return nearest_over(level0, 0, box.uv, binding.wrap);
        case TextureFilter::bilinear: return bilinear_over(level0, 0, box.uv, binding.wrap);
        case TextureFilter::trilinear:
        case TextureFilter::anisotropic: break;
    }
    const Interval rho_x = rho_of(box.d_dx, level0), rho_y = rho_of(box.d_dy, level0);
    const Interval rho_max(std::max(rho_x.lo, rho_y.lo), std::max(rho_x.hi, rho_y.hi));
    if (!std::isfinite(rho_max.hi)) return trilinear_over(texture, box.uv, Interval::everything(), binding.wrap);
    if (binding.filter == TextureFilter::trilinear) return trilinear_over(texture, box.uv, log2_of(rho_max), binding.wrap);
    // Anisotropic: every tap count and major axis the boxes allow.
    const Interval rho_min(std::min(rho_x.lo, rho_y.lo), std::min(rho_x.hi, rho_y.hi));
    const Interval ratio = rho_min.lo > 0.0 ? (rho_max / rho_min).widened(float_gamma(1) * (rho_max.hi / rho_min.lo))
                                            : Interval(rho_min.hi > 0.0 ? rho_max.lo / rho_min.hi : INFINITY, INFINITY);
    const int most = binding.max_anisotropy;
    const int taps_lo = std::clamp(static_cast<int>(std::min(std::ceil(ratio.lo), double(most))), 1, most);
    const int taps_hi = std::clamp(static_cast<int>(std::min(std::ceil(ratio.hi), double(most))), 1, most);
    std::vector<const UvBox*> axes;
    if (rho_x.hi >= rho_y.lo) axes.push_back(&box.d_dx);  // raster takes dx when rho_x >= rho_y
    if (rho_x.lo < rho_y.hi) axes.push_back(&box.d_dy);
    if (!(rho_max.hi > 0.0) || taps_hi - taps_lo > 3) {
        // No footprint (level 0), or too many tap counts to list: every level the lod can reach, whole.
        const Interval lod = rho_max.hi > 0.0 ? log2_of(Interval(rho_max.lo / most, rho_max.hi)) : Interval(-INFINITY);
        if (!(rho_max.hi > 0.0)) return trilinear_over(texture, box.uv, lod, binding.wrap);
        Interval3 out = level_range(texture.levels[0]);
        for (const OracleTextureLevel& level : texture.levels) out = hull(out, level_range(level));
        return out.widened(float_gamma(kBilinearRoundings + kLevelBlendRoundings) * out.magnitude());
    }
    Interval3 out;
    bool first = true;
    for (int taps = taps_lo; taps <= taps_hi; ++taps) {
        const Interval lod = log2_of((rho_max / Interval(taps)).widened(float_gamma(1) * rho_max.hi / taps));
        if (taps == 1) {
            const Interval3 v = trilinear_over(texture, box.uv, lod, binding.wrap);
            out = first ? v : hull(out, v);
            first = false;
            continue;
        }
        for (const UvBox* axis : axes) {
            Interval3 sum(glm::dvec3(0.0));
            double magnitude = 0.0;
            for (int k = 0; k < taps; ++k) {
                const double offset = (k + 0.5) / taps - 0.5;
                UvBox tap{box.uv.u + Interval(offset) * axis->u, box.uv.v + Interval(offset) * axis->v};
                tap.u = tap.u.widened(float_gamma(kTapCoordinateRoundings) * tap.u.magnitude());
                tap.v = tap.v.widened(float_gamma(kTapCoordinateRoundings) * tap.v.magnitude());
                const Interval3 v = trilinear_over(texture, tap, lod, binding.wrap);
                sum = sum + v;
                magnitude += v.magnitude();
            }
            const Interval3 mean = (Interval(1.0 / taps) * sum).widened(float_gamma(taps + 1) * magnitude / taps);
            out = first ? mean : hull(out, mean);
            first = false;
        }
    }
    return out;
}

}  // namespace raster::oracle
