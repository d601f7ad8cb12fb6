// Interval arithmetic in double for the oracle's colour bounds: every operation returns an interval that contains
// the operation's result for every choice of its operands within theirs. Computed with round-to-nearest: the
// intervals it serves are at least float roundings wide (~1e-7), against which double's own rounding (~1e-16 per
// operation) is negligible, and each use adds a float-rounding allowance far larger than that.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

namespace raster::oracle {

struct Interval {
    double lo = 0.0, hi = 0.0;
    Interval() = default;
    Interval(double value) : lo(value), hi(value) {}  // NOLINT: a number is the interval holding only it
    Interval(double low, double high) : lo(low), hi(high) {}
    static Interval everything() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    // Widened by `by` on both sides. An allowance that is NaN (a magnitude product inf * 0: an unbounded operand
    // next to a zero one) bounds nothing, so the result is everything; NaN bounds would read as "nowhere" to every
    // comparison after (the differential fuzzer found a light skipped, and a pixel's allowed colour left at its
    // ambient part, for a sample whose barycentric tolerance was unbounded).
    Interval widened(double by) const {
        if (std::isnan(by)) return everything();
        return {lo - by, hi + by};
    }
    bool contains(double v) const { return lo <= v && v <= hi; }
    double magnitude() const { return std::max(std::fabs(lo), std::fabs(hi)); }
};

inline Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Interval operator-(Interval a) { return {-a.hi, -a.lo}; }
inline Interval operator*(Interval a, Interval b) {
    const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
    // 0 * inf is NaN: an unbounded operand times one that may be 0 is unbounded.
    if (std::isnan(p0) || std::isnan(p1) || std::isnan(p2) || std::isnan(p3)) return Interval::everything();
    // The first smallest and the first largest in the order above (as a scan would pick among equal zeros).
    return {std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3))};
}
// Division by an interval that contains 0 is unbounded.
inline Interval operator/(Interval a, Interval b) {
    if (b.lo <= 0.0 && b.hi >= 0.0) return Interval::everything();
    return a * Interval(1.0 / b.hi, 1.0 / b.lo);
}
inline Interval hull(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
// max(0, x).
inline Interval positive_part(Interval a) { return {std::max(0.0, a.lo), std::max(0.0, a.hi)}; }
inline Interval square(Interval a) {
    if (a.lo >= 0.0) return {a.lo * a.lo, a.hi * a.hi};
    if (a.hi <= 0.0) return {a.hi * a.hi, a.lo * a.lo};
    return {0.0, std::max(a.lo * a.lo, a.hi * a.hi)};
}
inline Interval sqrt(Interval a) { return {std::sqrt(std::max(0.0, a.lo)), std::sqrt(std::max(0.0, a.hi))}; }
// x^e for x >= 0 and e > 0: by repeated squaring for whole exponents up to 256 (at most 16 products: a few
// double roundings), std::pow otherwise.
inline double power_of(double x, double e) {
    if (e <= 256.0 && e == std::floor(e)) {
        unsigned n = static_cast<unsigned>(e);
        double result = 1.0, square = x;
        for (; n; n >>= 1, square *= square)
            if (n & 1u) result *= square;
        return result;
    }
    return std::pow(x, e);
}
// x^e over the interval, the negative part of `a` taken as 0: increasing in x.
inline Interval power(Interval a, double e) {
    const Interval x = positive_part(a);
    return {power_of(x.lo, e), power_of(x.hi, e)};
}

struct Interval3 {
    Interval x, y, z;
    Interval3() = default;
    Interval3(Interval a, Interval b, Interval c) : x(a), y(b), z(c) {}
    explicit Interval3(const glm::dvec3& v) : x(v.x), y(v.y), z(v.z) {}
    Interval& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
    const Interval& operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
    Interval3 widened(double by) const { return {x.widened(by), y.widened(by), z.widened(by)}; }
    // The largest magnitude any component can have.
    double magnitude() const { return std::max({x.magnitude(), y.magnitude(), z.magnitude()}); }
};

inline Interval3 operator+(const Interval3& a, const Interval3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Interval3 operator-(const Interval3& a, const Interval3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Interval3 operator*(Interval s, const Interval3& v) { return {s * v.x, s * v.y, s * v.z}; }
inline Interval3 operator*(const Interval3& a, const Interval3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Interval dot(const Interval3& a, const Interval3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Interval length_squared(const Interval3& v) { return square(v.x) + square(v.y) + square(v.z); }
inline Interval3 hull(const Interval3& a, const Interval3& b) { return {hull(a.x, b.x), hull(a.y, b.y), hull(a.z, b.z)}; }

// v / |v| for every v in the box. Where the box reaches the origin a direction can be anything (or, as a renderer
// returns for a zero vector, nothing): every component is in [-1, 1].
inline Interval3 unit(const Interval3& v) {
    const Interval length = sqrt(length_squared(v));
    if (!(length.lo > 0.0)) return {Interval(-1.0, 1.0), Interval(-1.0, 1.0), Interval(-1.0, 1.0)};
    // Each component of a unit vector is in [-1, 1]; dividing the box by the length interval may overshoot.
    auto clamp_unit = [](Interval c) { return Interval(std::max(-1.0, c.lo), std::min(1.0, c.hi)); };
    return {clamp_unit(v.x / length), clamp_unit(v.y / length), clamp_unit(v.z / length)};
}

}  // namespace raster::oracle
