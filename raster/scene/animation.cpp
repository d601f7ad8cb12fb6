// Keyframe animation: sampling tracks and chaining the animated nodes (animation.h).
#include "raster/scene/animation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace raster {
namespace {

// The key interval holding `time` and how far into it: k with times[k] <= time < times[k + 1], u in [0, 1).
struct Interval {
    size_t k;
    float u, span;
};
Interval interval_of(const std::vector<float>& times, float time) {
    const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    const float span = times[k + 1] - times[k];
    return {k, span > 0.0f ? (time - times[k]) / span : 0.0f, span};
}

// glTF's cubic Hermite spline between keys k and k + 1: values are (in-tangent, value, out-tangent) per key.
template <typename T>
T hermite(const std::vector<T>& values, const Interval& i) {
    const float u = i.u, u2 = u * u, u3 = u2 * u;
    const T& v0 = values[3 * i.k + 1];
    const T& b0 = values[3 * i.k + 2];
    const T& a1 = values[3 * (i.k + 1)];
    const T& v1 = values[3 * (i.k + 1) + 1];
    return (2.0f * u3 - 3.0f * u2 + 1.0f) * v0 + (u3 - 2.0f * u2 + u) * i.span * b0 + (-2.0f * u3 + 3.0f * u2) * v1 +
           (u3 - u2) * i.span * a1;
}

// The value of key k (for a cubic spline, the middle of its three).
template <typename T>
const T& key_value(const Track<T>& track, size_t k) {
    return track.values[track.interpolation == KeyInterpolation::cubic_spline ? 3 * k + 1 : k];
}

template <typename T, typename Blend>
T sample(const Track<T>& track, float time, Blend blend) {
    if (!(time > track.times.front())) return key_value(track, 0);  // NaN too: no interval holds it
    if (time >= track.times.back()) return key_value(track, track.times.size() - 1);
    const Interval i = interval_of(track.times, time);
    switch (track.interpolation) {
        case KeyInterpolation::step: return key_value(track, i.k);
        case KeyInterpolation::cubic_spline: return hermite(track.values, i);
        case KeyInterpolation::linear: break;
    }
    return blend(key_value(track, i.k), key_value(track, i.k + 1), i.u);
}

}  // namespace

glm::vec4 slerp(const glm::vec4& a, const glm::vec4& from_b, float t) {
    float cosine = glm::dot(a, from_b);
    const glm::vec4 b = cosine < 0.0f ? -from_b : from_b;
    cosine = std::fabs(cosine);
    // Nearly the same rotation: the arc is a straight line to float precision, and sin(angle) would be ~0.
    if (cosine > 0.9995f) return glm::normalize(a + t * (b - a));
    const float angle = std::acos(cosine);
    const float s = std::sin(angle);
    return (std::sin((1.0f - t) * angle) / s) * a + (std::sin(t * angle) / s) * b;
}

glm::vec3 sample_track(const Track<glm::vec3>& track, float time) {
    return sample(track, time, [](const glm::vec3& a, const glm::vec3& b, float u) { return a + u * (b - a); });
}

glm::vec4 sample_track(const Track<glm::vec4>& track, float time) {
    const glm::vec4 q = sample(track, time, [](const glm::vec4& a, const glm::vec4& b, float u) { return slerp(a, b, u); });
    const float length = glm::length(q);
    return length > 0.0f ? q / length : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
}

std::vector<TransformStep> node_steps_at(const AnimatedNode& node, float time) {
    std::vector<TransformStep> steps = node.fixed;
    steps.push_back(ScaleStep{node.scale.empty() ? node.rest_scale : sample_track(node.scale, time)});
    steps.push_back(QuaternionStep{node.rotation.empty() ? node.rest_rotation : sample_track(node.rotation, time)});
    steps.push_back(TranslateStep{node.translation.empty() ? node.rest_translation : sample_track(node.translation, time)});
    return steps;
}

std::vector<TransformStep> node_chain_at(const SceneAnimation& animation, int node, float time) {
    std::vector<TransformStep> chain;
    for (int at = node; at >= 0; at = animation.nodes[static_cast<size_t>(at)].parent) {
        const std::vector<TransformStep> own = node_steps_at(animation.nodes[static_cast<size_t>(at)], time);
        chain.insert(chain.end(), own.begin(), own.end());
    }
    return chain;
}

void find_animation_span(SceneAnimation& animation) {
    bool any = false;
    const auto widen = [&](const std::vector<float>& times) {
        if (times.empty()) return;
        animation.start = any ? std::min(animation.start, times.front()) : times.front();
        animation.end = any ? std::max(animation.end, times.back()) : times.back();
        any = true;
    };
    for (const AnimatedNode& node : animation.nodes) {
        widen(node.scale.times);
        widen(node.rotation.times);
        widen(node.translation.times);
    }
    if (!any) animation.start = animation.end = 0.0f;
}

}  // namespace raster
