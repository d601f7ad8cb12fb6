// Keyframe animation's properties on raster's own sampling (raster/scene/animation.h), against references in double
// written here: slerp stays unit length and turns at a constant angular speed the short way round; a track sampled
// exactly at a key gives that key's value; between keys a track follows its interpolation (step holds the earlier
// key, linear is the straight line, a rotation the arc, a cubic spline glTF's Hermite basis). nlerp in place of
// slerp, the long way round, step sampled as linear or a key early, or unscaled spline tangents each break one.
//
// Rotations are measured by the arc between unit quaternions on the 4-sphere, arc(p, q) = 2 atan2(|p - q|, |p + q|)
// with q's sign taken to face p (q and -q are one rotation), accurate at every angle. Bounds use u = 2^-24.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"

namespace raster::properties {
namespace {

const double u = std::ldexp(1.0, -24);

// raster blends rotations closer than this arc (cosine 0.9995, animation.cpp) along the straight chord, normalised:
// the documented trade where sin(arc) would be too small to divide by. The bound allows the chord's own departure
// from the arc there, computed below, and nowhere else.
const double kChordArc = std::acos(0.9995);

glm::dvec4 unit_double(const glm::vec4& q) { return glm::normalize(glm::dvec4(q)); }

double arc(const glm::dvec4& p, glm::dvec4 q) {
    if (glm::dot(p, q) < 0.0) q = -q;
    return 2.0 * std::atan2(glm::length(p - q), glm::length(p + q));
}

// How far the normalised chord from a to b strays from the arc at some fraction of it, at most, for an arc omega
// apart: max over t of |atan2(t sin w, 1 - t + t cos w) - t w|, found on a fine grid (the deviation is smooth, with
// one maximum; the grid's step of 1/4096 misses it by under 1e-12 rad), times 2 for the rotation's own arc.
double chord_departure(double omega) {
    double worst = 0.0;
    for (int i = 0; i <= 4096; ++i) {
        const double t = i / 4096.0;
        worst = std::max(worst, std::fabs(std::atan2(t * std::sin(omega), 1.0 - t + t * std::cos(omega)) - t * omega));
    }
    return 2.0 * worst + 1e-12;
}

// The bound on raster's float slerp between unit float quaternions an arc omega (rotation angle, twice the
// quaternion arc w) apart, in that arc's radians and in length. Inputs are unit to 3u. The float dot product of the
// two is off by at most 10u (4u for four products summed, 6u from the inputs' lengths), so the arc acos gives by
// 10u / sin(w) + u w; each weight sin(t w) / sin(w) <= 1 is off by 7u (3u per sine, u for the quotient) plus its
// arc's error, and the weighted sum adds 3u: the result sits within 23u + 2 (10u / sin(w) + 2u) of the arc's point,
// 27u + 20u / sin(w) in all. Where the float cosine passes 0.9995 the chord replaces the weights: 16u of rounding
// plus the chord's departure. With the cosine off by 10u, either branch may run near the switch: the larger bound.
// Doubled for the rotation's arc.
double slerp_bound(double omega) {
    const double w = 0.5 * omega;
    double along = 0.0;
    if (w >= std::acos(std::min(1.0, 0.9995 + 10.0 * u))) along = 27.0 * u + 20.0 * u / std::sin(w);
    if (w <= std::acos(0.9995 - 10.0 * u)) along = std::max(along, 16.0 * u + 0.5 * chord_departure(w));
    return 2.0 * along;
}

glm::vec4 random_unit_quaternion() {
    for (;;) {
        const glm::vec4 q(static_cast<float>(signed_unit()), static_cast<float>(signed_unit()),
                          static_cast<float>(signed_unit()), static_cast<float>(signed_unit()));
        if (glm::length(q) > 0.1f) return glm::normalize(q);
    }
}

// A second rotation for `a`: random, or near a or -a (the chord's region and its edge, at arcs from 1e-6 to 0.2),
// or exactly a or -a.
glm::vec4 partner_of(const glm::vec4& a) {
    const double kind = unit();
    if (kind < 0.5) return random_unit_quaternion();
    const float sign = coin() ? 1.0f : -1.0f;
    if (kind < 0.6) return sign * a;
    const glm::vec4 nudge = random_unit_quaternion() * static_cast<float>(log_uniform(1e-6, 0.2));
    return sign * glm::normalize(a + nudge);
}

struct SlerpCase {
    glm::vec4 a, b;
    float t = 0.0f;
};

std::ostream& operator<<(std::ostream& os, const SlerpCase& c) {
    return os << "SlerpCase{" << literal(c.a) << ", " << literal(c.b) << ", " << float_literal(c.t) << "}";
}

Gen<SlerpCase> slerp_cases() {
    return gen::exec([] {
        SlerpCase c;
        c.a = random_unit_quaternion();
        c.b = partner_of(c.a);
        const double kind = unit();
        c.t = kind < 0.1 ? 0.0f : kind < 0.2 ? 1.0f : static_cast<float>(unit());
        return c;
    });
}

// Checks that q lies a fraction t of the way along the short arc from a to b, and is unit, within slack added to
// slerp's bound.
void check_on_arc(const glm::vec4& q, const glm::vec4& a, const glm::vec4& b, double t, double slack,
                  const std::string& what) {
    const glm::dvec4 from = unit_double(a), to = unit_double(b), at = glm::dvec4(q);
    const double omega = arc(from, to), bound = slerp_bound(omega) + slack;
    const double length = glm::length(at);
    if (std::fabs(length - 1.0) > bound)
        fail_case(what + " has length " + double_literal(length) + ", not 1 within " + double_literal(bound));
    const glm::dvec4 unit_at = at / length;
    const double from_start = arc(from, unit_at), to_end = arc(unit_at, to);
    if (std::fabs(from_start - t * omega) > bound || std::fabs(to_end - (1.0 - t) * omega) > bound)
        fail_case(what + " is " + double_literal(from_start) + " rad from the start and " + double_literal(to_end) +
                  " from the end of a " + double_literal(omega) + "-rad turn; a fraction " + double_literal(t) +
                  " of it along the short way is " + double_literal(t * omega) + " and " +
                  double_literal((1.0 - t) * omega) + ", within " + double_literal(bound));
}

// A track of 2 to 6 keys at increasing float times (from -10 to 60 s, gaps of 0.01 to 10 s), of one interpolation.
template <typename T, typename Value>
Track<T> random_track(Value value) {
    Track<T> track;
    const double kind = unit();
    track.interpolation = kind < 0.34   ? KeyInterpolation::linear
                          : kind < 0.67 ? KeyInterpolation::step
                                        : KeyInterpolation::cubic_spline;
    const size_t keys = 2 + static_cast<size_t>(unit() * 5.0);
    float time = static_cast<float>(70.0 * unit() - 10.0);
    for (size_t k = 0; k < keys; ++k) {
        track.times.push_back(time);
        time = std::nextafter(time + static_cast<float>(log_uniform(0.01, 10.0)), INFINITY);
    }
    const size_t per_key = track.interpolation == KeyInterpolation::cubic_spline ? 3 : 1;
    for (size_t i = 0; i < keys * per_key; ++i) track.values.push_back(value());
    return track;
}

struct TrackCase {
    Track<glm::vec3> moves;
    Track<glm::vec4> turns;
    float scale = 1.0f;  // of the moves' values
};

const char* name_of(KeyInterpolation i) {
    return i == KeyInterpolation::linear ? "linear" : i == KeyInterpolation::step ? "step" : "cubic_spline";
}

template <typename T>
void print_track(std::ostream& os, const char* name, const Track<T>& track) {
    os << " " << name << "{" << name_of(track.interpolation) << " times";
    for (const float t : track.times) os << " " << float_literal(t);
    os << " values";
    for (const T& v : track.values) os << " " << literal(v);
    os << "}";
}

std::ostream& operator<<(std::ostream& os, const TrackCase& c) {
    os << "TrackCase{";
    print_track(os, "moves", c.moves);
    print_track(os, "turns", c.turns);
    return os << "}";
}

Gen<TrackCase> track_cases() {
    return gen::exec([] {
        TrackCase c;
        const double scale = log_uniform(0.01, 100.0);
        c.moves = random_track<glm::vec3>([&] { return random_vector(scale); });
        c.turns = random_track<glm::vec4>([] { return random_unit_quaternion(); });
        // Rotation keys close to each other in half the cases, to reach slerp's chord region through tracks too.
        if (coin())
            for (size_t i = 1; i < c.turns.values.size(); ++i) c.turns.values[i] = partner_of(c.turns.values[i - 1]);
        return c;
    });
}

// The value of key k (for a cubic spline, the middle of its three).
template <typename T>
const T& key_of(const Track<T>& track, size_t k) {
    return track.values[track.interpolation == KeyInterpolation::cubic_spline ? 3 * k + 1 : k];
}

// glTF 2.0's cubic spline (Appendix C) between keys k and k + 1 at fraction s of the gap, in double, and the sum
// of its terms' sizes per component (what its float evaluation's rounding scales with).
template <typename D>
D hermite(const std::vector<D>& v, size_t k, double s, double gap, D* sizes) {
    const double s2 = s * s, s3 = s2 * s;
    const double h[4] = {2 * s3 - 3 * s2 + 1, (s3 - 2 * s2 + s) * gap, -2 * s3 + 3 * s2, (s3 - s2) * gap};
    const D terms[4] = {v[3 * k + 1], v[3 * k + 2], v[3 * k + 4], v[3 * k + 3]};
    D out(0.0);
    *sizes = D(0.0);
    for (int j = 0; j < 4; ++j) {
        out += h[j] * terms[j];
        *sizes += (std::fabs(h[j]) + 6.0 * (j % 2 ? gap : 1.0)) * glm::abs(terms[j]);
    }
    return out;
}

template <typename D, typename F>
std::vector<D> in_double(const std::vector<F>& values) {
    return std::vector<D>(values.begin(), values.end());
}

}  // namespace

// slerp(a, b, t) for unit float quaternions a and b and t in [0, 1] is unit and lies t of the way from a to b along
// the short arc (from b's sign facing a), within slerp_bound: constant angular speed, the short way round.
RASTER_PROPERTY(Animation, slerpIsUnitAndTurnsAtAConstantRateTheShortWay) {
    const SlerpCase c = *slerp_cases();
    RC_CLASSIFY(arc(unit_double(c.a), unit_double(c.b)) < 2.0 * kChordArc, "within the chord's arc");
    check_on_arc(impl.blocks.slerp(c.a, c.b, c.t), c.a, c.b, c.t, 0.0, "slerp");
}

// At each key's time a track gives that key's value: exactly for positions (the blend's weights are then exactly
// 1 and 0), and for rotations the key normalised, within 8u a component (two float normalisations of a unit
// quaternion, 3u each, and the key's own 2u from unit).
RASTER_PROPERTY(Animation, aTrackSampledAtAKeyGivesThatKeysValue) {
    const TrackCase c = *track_cases();
    RC_CLASSIFY(true, name_of(c.moves.interpolation));
    for (size_t k = 0; k < c.moves.times.size(); ++k) {
        const glm::vec3 got = impl.blocks.sample_positions(c.moves, c.moves.times[k]), want = key_of(c.moves, k);
        if (got != want)
            fail_case("the " + std::string(name_of(c.moves.interpolation)) + " position track at key " +
                      std::to_string(k) + "'s time gives " + literal(got) + ", not the key's " + literal(want));
    }
    for (size_t k = 0; k < c.turns.times.size(); ++k) {
        const glm::dvec4 got(impl.blocks.sample_rotations(c.turns, c.turns.times[k])), want = unit_double(key_of(c.turns, k));
        for (int i = 0; i < 4; ++i)
            if (std::fabs(got[i] - want[i]) > 8.0 * u)
                fail_case("the " + std::string(name_of(c.turns.interpolation)) + " rotation track at key " +
                          std::to_string(k) + "'s time gives " + literal(glm::vec4(got)) + ", not the key's " +
                          literal(glm::vec4(want)) + " within 8u a component");
    }
}

// At a time strictly between keys k and k + 1, a fraction s of the gap along (s in double from the float times),
// with e = 4u the float fraction's error (two float differences and a quotient of exact float times):
// - a step track holds key k exactly (a rotation normalised, within 8u a component);
// - a linear position is a + s (b - a) within (e + 3u)(|a| + |b|) a component;
// - a linear rotation lies s of the way along slerp's arc, within slerp_bound, plus e times the arc for the
//   fraction, plus 12u for sample_track's normalisation (3u of length, twice that in arc, twice for the rotation);
// - a cubic spline is glTF's Hermite form sum_j c_j x_j (c_j the cubic factor of term x_j, times the gap for a
//   tangent) within (1.5 e + 6u) sum_j (|c_j| + 6 g_j) |x_j|, g_j the gap for a tangent and 1 for a value: each
//   factor's cubic in s is off by at most 6u times its monomials' sizes (under 6), the products and the sum add
//   5u |c_j|, and the fraction's error moves each term by at most 1.5 e g_j |x_j| (no factor's slope passes 1.5);
//   a cubic rotation is that form normalised, within twice its bound over its length, and 6u for the float's.
RASTER_PROPERTY(Animation, betweenKeysATrackFollowsItsInterpolation) {
    const TrackCase c = *track_cases();
    const double e = 4.0 * u;
    RC_CLASSIFY(true, name_of(c.moves.interpolation));
    for (size_t k = 0; k + 1 < c.moves.times.size(); ++k) {
        const float lo = c.moves.times[k], hi = c.moves.times[k + 1];
        const float time = std::clamp(static_cast<float>(lo + (hi - lo) * unit()), std::nextafter(lo, hi),
                                      std::nextafter(hi, lo));
        const double s = (double(time) - lo) / (double(hi) - lo), gap = double(hi) - lo;
        const glm::dvec3 got(impl.blocks.sample_positions(c.moves, time));
        glm::dvec3 want, bound;
        switch (c.moves.interpolation) {
            case KeyInterpolation::step: want = glm::dvec3(key_of(c.moves, k)), bound = glm::dvec3(0.0); break;
            case KeyInterpolation::linear: {
                const glm::dvec3 a(c.moves.values[k]), b(c.moves.values[k + 1]);
                want = a + s * (b - a);
                bound = (e + 3.0 * u) * (glm::abs(a) + glm::abs(b));
                break;
            }
            case KeyInterpolation::cubic_spline: {
                glm::dvec3 sizes;
                want = hermite(in_double<glm::dvec3>(c.moves.values), k, s, gap, &sizes);
                bound = (1.5 * e + 6.0 * u) * sizes;
                break;
            }
        }
        for (int i = 0; i < 3; ++i)
            if (std::fabs(got[i] - want[i]) > bound[i])
                fail_case("the " + std::string(name_of(c.moves.interpolation)) + " position track at " +
                          float_literal(time) + " s, " + double_literal(s) + " of the way from key " +
                          std::to_string(k) + ", gives " + literal(glm::vec3(got)) + "; its interpolation gives " +
                          literal(glm::vec3(want)) + " within " + literal(glm::vec3(bound)));
    }
    for (size_t k = 0; k + 1 < c.turns.times.size(); ++k) {
        const float lo = c.turns.times[k], hi = c.turns.times[k + 1];
        const float time = std::clamp(static_cast<float>(lo + (hi - lo) * unit()), std::nextafter(lo, hi),
                                      std::nextafter(hi, lo));
        const double s = (double(time) - lo) / (double(hi) - lo), gap = double(hi) - lo;
        const glm::vec4 got = impl.blocks.sample_rotations(c.turns, time);
        const std::string what = std::string(name_of(c.turns.interpolation)) + " rotation track at " +
                                 float_literal(time) + " s, " + double_literal(s) + " of the way from key " +
                                 std::to_string(k) + ",";
        if (c.turns.interpolation == KeyInterpolation::linear) {
            const glm::vec4 &a = c.turns.values[k], &b = c.turns.values[k + 1];
            check_on_arc(got, a, b, s, e * arc(unit_double(a), unit_double(b)) + 12.0 * u, "the " + what);
            continue;
        }
        glm::dvec4 want = unit_double(key_of(c.turns, k)), sizes(0.0);
        double bound = 8.0 * u;
        if (c.turns.interpolation == KeyInterpolation::cubic_spline) {
            const glm::dvec4 h = hermite(in_double<glm::dvec4>(c.turns.values), k, s, gap, &sizes);
            const double length = glm::length(h);
            RC_PRE(length > 1e-3);  // a spline through (near) zero has no direction to normalise
            want = h / length;
            bound = 2.0 * (1.5 * e + 6.0 * u) * glm::length(sizes) / length + 6.0 * u;
        }
        const glm::dvec4 got_double(got);
        for (int i = 0; i < 4; ++i)
            if (std::fabs(got_double[i] - want[i]) > bound)
                fail_case("the " + what + " gives " + literal(got) + "; its interpolation gives " +
                          literal(glm::vec4(want)) + " within " + double_literal(bound) + " a component");
    }
}

}  // namespace raster::properties
