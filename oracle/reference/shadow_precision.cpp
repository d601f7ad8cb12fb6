// Part 10 of the precision model: the faces, footprint and reference depth of raster's shadow lookup, in interval
// arithmetic with raster's float roundings.
#include "oracle/reference/shadow_precision.h"

#include <algorithm>
#include <cmath>

#include "oracle/reference/precision.h"
#include "oracle/reference/shadow_faces.h"

namespace raster::oracle {
namespace {

Interval widened_by(Interval value, int roundings, double magnitude) {
    return value.widened(float_gamma(roundings) * magnitude);
}

Interval dot_exact_axis(const glm::dvec3& axis, const Interval3& d) {
    Interval out(0.0);
    for (int i = 0; i < 3; ++i)
        if (axis[i] != 0.0) out = out + Interval(axis[i]) * d[i];
    return out;
}

// n . v with raster's 3 roundings relative to |n| |v|.
Interval float_dot(const Interval3& n, const Interval3& v) {
    double magnitude = 0.0;
    for (int i = 0; i < 3; ++i) magnitude += n[i].magnitude() * v[i].magnitude();
    return widened_by(dot(n, v), kShadowDotRoundings, magnitude);
}

// Along one axis, for a pixel coordinate in `position`: the centres of the texels the filter may read (tap_from,
// tap_to), and those texels whole joined with the position itself (from, to).
void taps_along(Interval position, int resolution, int radius, double& tap_from, double& tap_to, double& from,
                double& to) {
    const double last = resolution - 1;
    const double first_texel = std::clamp(std::floor(position.lo), 0.0, last);
    const double last_texel = std::clamp(std::floor(position.hi), 0.0, last);
    const double first_tap = std::max(first_texel - radius, 0.0), last_tap = std::min(last_texel + radius, last);
    tap_from = first_tap + 0.5;
    tap_to = last_tap + 0.5;
    from = std::min(first_tap, position.lo);
    to = std::max(last_tap + 1.0, position.hi);
}

}  // namespace

std::vector<ShadowLookup> shadow_lookups(const ShadowSettings& settings, const glm::dvec3& light,
                                         const Interval3& position, const Interval3& normal) {
    Interval3 d;
    for (int i = 0; i < 3; ++i)
        d[i] = widened_by(position[i] - Interval(light[i]), kShadowDifferenceRoundings,
                          position[i].magnitude() + std::fabs(light[i]));
    const double n = settings.resolution, half = 0.5 * n;
    const double reach = static_cast<double>(settings.pcf) / n;  // pcf / 2 texels, in face coordinates
    std::vector<ShadowLookup> lookups;
    for (int face : possible_faces(d)) {
        const ShadowFace& f = shadow_face(face);
        ShadowLookup lookup;
        lookup.face = face;
        lookup.depth = dot_exact_axis(f.axis, d);
        if (!(lookup.depth.lo > 0.0)) return {};
        const Interval s = widened_by(dot_exact_axis(f.right, d) / lookup.depth, kShadowFaceCoordinateRoundings, 1.0);
        const Interval t = widened_by(dot_exact_axis(f.up, d) / lookup.depth, kShadowFaceCoordinateRoundings, 1.0);
        const Interval x = widened_by((s + Interval(1.0)) * Interval(half), kShadowTexelRoundings,
                                      (s.magnitude() + 1.0) * half);
        const Interval y = widened_by((Interval(1.0) - t) * Interval(half), kShadowTexelRoundings,
                                      (t.magnitude() + 1.0) * half);
        lookup.x = x;
        lookup.y = y;
        const int radius = settings.pcf / 2;
        taps_along(x, settings.resolution, radius, lookup.taps.x0, lookup.taps.x1, lookup.footprint.x0,
                   lookup.footprint.x1);
        taps_along(y, settings.resolution, radius, lookup.taps.y0, lookup.taps.y1, lookup.footprint.y0,
                   lookup.footprint.y1);

        // The bias: the receiver plane's drop over the filter's square, capped at the depth.
        const Interval plane = float_dot(normal, d);
        const Interval depth = lookup.depth;
        bool cap_certain = false, cap_possible = false;
        Interval drop(0.0);
        for (int corner = 0; corner < 4; ++corner) {
            const Interval cs = widened_by(s + Interval(corner & 1 ? reach : -reach), kShadowCornerRoundings,
                                           s.magnitude() + reach);
            const Interval ct = widened_by(t + Interval(corner & 2 ? reach : -reach), kShadowCornerRoundings,
                                           t.magnitude() + reach);
            Interval3 v;
            for (int i = 0; i < 3; ++i) v[i] = Interval(f.axis[i]) + cs * Interval(f.right[i]) + ct * Interval(f.up[i]);
            const Interval denominator = float_dot(normal, v);
            const Interval sign = denominator * plane;
            cap_certain = cap_certain || sign.hi <= 0.0;
            cap_possible = cap_possible || sign.lo <= 0.0;
            const Interval exact_ratio = plane / denominator;
            const Interval ratio = widened_by(exact_ratio, 1, exact_ratio.magnitude());
            const Interval corner_drop = widened_by(depth - ratio, 1, depth.magnitude() + ratio.magnitude());
            drop = Interval(std::max(drop.lo, corner_drop.lo), std::max(drop.hi, corner_drop.hi));
        }
        drop = Interval(std::min(drop.lo, depth.lo), std::min(drop.hi, depth.hi));
        if (cap_certain) drop = depth;
        else if (cap_possible) drop = hull(drop, depth);
        const Interval constant = Interval(settings.bias) * depth, slope = Interval(settings.slope_bias) * drop;
        const Interval bias = widened_by(constant + slope, kShadowBiasRoundings, constant.magnitude() + slope.magnitude());
        lookup.reference = widened_by(depth - bias, 1, depth.magnitude() + bias.magnitude());
        lookups.push_back(lookup);
    }
    return lookups;
}

}  // namespace raster::oracle
