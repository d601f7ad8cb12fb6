// The oracle's own sampling of keyframe tracks and posing of animated meshes, in double (animation_pose.h).
//
// THE BOUNDS on raster's float sampling (raster/scene/animation.cpp), u = 2^-24, with e = 4u the error of raster's
// float fraction s = (t - t_k) / (t_{k+1} - t_k) (two differences of float times and a quotient, 3u, relative):
//  - outside the keys, at a step, or at a key's own time raster returns the key's float exactly (weights 1 and 0);
//    a rotation after sample_track's float normalisation, within 3u a component of the double one: 8u in R^4;
//  - linear positions: a + s (b - a), within (e + 3u)(|a| + |b|) a component;
//  - linear rotations, the quaternion arc w apart: raster's float dot product is off by 10u, its acos by
//    10u / sin(w) + u w, each weight sin(t w) / sin(w) <= 1 by 7u plus the arc's error, the weighted sum 3u: on the
//    arc within 27u + 20u / sin(w) in arc and in length. Where its float cosine passes 0.9995 raster blends the
//    normalised chord instead: 16u of rounding (the difference, the product and the sum, 3u a component, and the
//    normalisation's 3u, in R^4) plus the chord's own departure from the arc, computed here; near the switch,
//    whichever of the two it may take. Add e w for the fraction and 3u for the normalisation;
//    a point that far along and off the arc is at most twice that from the oracle's in R^4;
//  - cubic splines sum_j c_j x_j (c_j a cubic in s, times the gap for a tangent): within (1.5 e + 6u)
//    sum_j (|c_j| + 6 g_j) |x_j|, g_j the gap for a tangent and 1 for a value (each cubic's float evaluation is off
//    by 6u times its monomials, under 6, the products and sum add 5u |c_j|, and no cubic's slope in s passes 1.5);
//    a rotation is then normalised: 2 |dH| / |H| + 6u in R^4 (2, the most two facing unit quaternions can differ,
//    where |H| is too small for that to mean anything).
// A sampled rotation's matrix entries then move by at most 4 d + 2 d^2 for a distance d (model_precision.h), on
// top of raster's own float quaternion step.
#include "oracle/reference/animation_pose.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "oracle/reference/model_transform.h"

namespace raster::oracle {
namespace {

constexpr double u = 0x1p-24;
constexpr double e = 4.0 * u;

// Where `time` falls: before the first key (k = 0, s = 0, at_key), after the last (the last key, at_key), or
// between keys k and k + 1 at fraction s.
struct KeySpan {
    size_t k = 0;
    double s = 0.0, gap = 0.0;
    bool at_key = true;
};

KeySpan span_of(const std::vector<float>& times, float time) {
    KeySpan out;
    if (!(time > times.front())) return out;
    if (time >= times.back()) {
        out.k = times.size() - 1;
        return out;
    }
    size_t k = 0;
    while (times[k + 1] <= time) ++k;  // times[k] <= time < times[k + 1]
    out.k = k;
    out.gap = double(times[k + 1]) - double(times[k]);
    out.s = (double(time) - double(times[k])) / out.gap;
    out.at_key = out.s == 0.0;
    return out;
}

size_t value_index(KeyInterpolation interpolation, size_t k) {
    return interpolation == KeyInterpolation::cubic_spline ? 3 * k + 1 : k;
}

// glTF's cubic spline between keys k and k + 1 (values in-tangent, value, out-tangent per key), and its terms'
// sizes for the bound.
template <typename Double, typename Float>
Double cubic(const std::vector<Float>& values, const KeySpan& at, Double* sizes) {
    const double s = at.s, s2 = s * s, s3 = s2 * s;
    const double factor[4] = {2 * s3 - 3 * s2 + 1, (s3 - 2 * s2 + s) * at.gap, -2 * s3 + 3 * s2, (s3 - s2) * at.gap};
    const size_t k = at.k;
    const Double term[4] = {Double(values[3 * k + 1]), Double(values[3 * k + 2]), Double(values[3 * k + 4]),
                            Double(values[3 * k + 3])};
    Double out(0.0);
    *sizes = Double(0.0);
    for (int j = 0; j < 4; ++j) {
        out += factor[j] * term[j];
        *sizes += (std::fabs(factor[j]) + 6.0 * (j % 2 ? at.gap : 1.0)) * glm::abs(term[j]);
    }
    return out;
}

double quaternion_arc(const glm::dvec4& a, const glm::dvec4& b) {
    return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));  // a and b unit and facing
}

// The largest departure of the normalised chord from the arc, for an arc w: max over t of
// |atan2(t sin w, 1 - t + t cos w) - t w|, on a grid of 1/4096 (smooth with one maximum: the grid misses it by
// under 1e-12).
double chord_departure(double w) {
    double worst = 0.0;
    for (int i = 1; i < 4096; ++i) {
        const double t = i / 4096.0;
        worst = std::max(worst, std::fabs(std::atan2(t * std::sin(w), 1.0 - t + t * std::cos(w)) - t * w));
    }
    return worst + 1e-12;
}

// raster's float cosine is within 10u of the true one, so it may take either branch where the true cosine is within
// 10u of 0.9995: the bound is the larger of the branches it may take.
double linear_rotation_bound(double w) {
    double along = 0.0;
    if (w >= std::acos(std::min(1.0, 0.9995 + 10.0 * u))) along = 27.0 * u + 20.0 * u / std::sin(w);
    if (w <= std::acos(0.9995 - 10.0 * u)) along = std::max(along, 16.0 * u + chord_departure(w));
    return 2.0 * (along + e * w + 3.0 * u);
}

}  // namespace

glm::dvec4 oracle_slerp(const glm::dvec4& a, const glm::dvec4& from_b, double t) {
    const glm::dvec4 b = glm::dot(a, from_b) < 0.0 ? -from_b : from_b;
    const glm::dvec4 across = b - glm::dot(a, b) * a;
    const double across_length = glm::length(across);
    if (across_length == 0.0) return a;
    const double w = quaternion_arc(a, b);
    return a * std::cos(t * w) + (across / across_length) * std::sin(t * w);
}

SampledVector oracle_sample(const Track<glm::vec3>& track, float time) {
    const KeySpan at = span_of(track.times, time);
    SampledVector out;
    if (at.at_key || track.interpolation == KeyInterpolation::step) {
        out.value = glm::dvec3(track.values[value_index(track.interpolation, at.k)]);
        return out;
    }
    if (track.interpolation == KeyInterpolation::linear) {
        const glm::dvec3 a(track.values[at.k]), b(track.values[at.k + 1]);
        out.value = a + at.s * (b - a);
        out.bound = (e + 3.0 * u) * (glm::abs(a) + glm::abs(b));
        return out;
    }
    glm::dvec3 sizes;
    out.value = cubic<glm::dvec3>(track.values, at, &sizes);
    out.bound = (1.5 * e + 6.0 * u) * sizes;
    return out;
}

SampledRotation oracle_sample(const Track<glm::vec4>& track, float time) {
    const KeySpan at = span_of(track.times, time);
    SampledRotation out;
    if (at.at_key || track.interpolation == KeyInterpolation::step) {
        out.wxyz = glm::normalize(glm::dvec4(track.values[value_index(track.interpolation, at.k)]));
        out.bound = 8.0 * u;
        return out;
    }
    if (track.interpolation == KeyInterpolation::linear) {
        const glm::dvec4 a = glm::normalize(glm::dvec4(track.values[at.k]));
        glm::dvec4 b = glm::normalize(glm::dvec4(track.values[at.k + 1]));
        if (glm::dot(a, b) < 0.0) b = -b;
        out.wxyz = oracle_slerp(a, b, at.s);
        out.bound = linear_rotation_bound(quaternion_arc(a, b));
        return out;
    }
    glm::dvec4 sizes;
    const glm::dvec4 h = cubic<glm::dvec4>(track.values, at, &sizes);
    const double length = glm::length(h), error = (1.5 * e + 6.0 * u) * glm::length(sizes);
    out.wxyz = length > 0.0 ? h / length : glm::dvec4(1.0, 0.0, 0.0, 0.0);
    out.bound = length > 2.0 * error ? 2.0 * error / length + 6.0 * u : 2.0;
    return out;
}

ModelMatrixError posed_model_error(const SceneAnimation& animation, size_t mesh, float time) {
    const SceneAnimation::Placement& placement = animation.meshes[mesh];
    std::vector<StepError> steps;
    for (const TransformStep& step : placement.local) steps.push_back(raster_step_error(step));
    for (int at = placement.node; at >= 0; at = animation.nodes[static_cast<size_t>(at)].parent) {
        const AnimatedNode& node = animation.nodes[static_cast<size_t>(at)];
        for (const TransformStep& step : node.fixed) steps.push_back(raster_step_error(step));
        const SampledVector scale =
            node.scale.empty() ? SampledVector{glm::dvec3(node.rest_scale), glm::dvec3(0.0)} : oracle_sample(node.scale, time);
        StepError& s = steps.emplace_back();
        for (int i = 0; i < 3; ++i) s.exact[i][i] = scale.value[i], s.bound[i][i] = scale.bound[i];

        const SampledRotation rotation = node.rotation.empty()
                                             ? SampledRotation{glm::normalize(glm::dvec4(node.rest_rotation)), 0.0}
                                             : oracle_sample(node.rotation, time);
        // raster's float quaternion step's own error, for whatever float quaternion it holds, plus the sampling's.
        StepError r = raster_step_error(QuaternionStep{glm::vec4(rotation.wxyz)});
        r.exact = unit_quaternion_matrix(rotation.wxyz[0], rotation.wxyz[1], rotation.wxyz[2], rotation.wxyz[3]);
        const double d = rotation.bound;
        for (int c = 0; c < 3; ++c)
            for (int row = 0; row < 3; ++row) r.bound[c][row] += 4.0 * d + 2.0 * d * d;
        steps.push_back(r);

        const SampledVector offset = node.translation.empty()
                                         ? SampledVector{glm::dvec3(node.rest_translation), glm::dvec3(0.0)}
                                         : oracle_sample(node.translation, time);
        StepError& t = steps.emplace_back();
        for (int i = 0; i < 3; ++i) t.exact[3][i] = offset.value[i], t.bound[3][i] = offset.bound[i];
    }
    return raster_chain_error(steps);
}

}  // namespace raster::oracle
