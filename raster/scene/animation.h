// Keyframe animation: tracks that move a scene's nodes over time (a node's scale, rotation and translation), the
// node tree they move, and which meshes, lights and camera each node carries; and the sampling of a track at a time
// (linear, step, cubic spline; rotations by spherical interpolation the short way). docs/animation.md.
#pragma once

#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/scene/model_transform.h"

namespace raster {

enum class KeyInterpolation {
    linear,        // straight between keys; rotations by slerp, the short way
    step,          // each key's value until the next key
    cubic_spline,  // glTF's cubic Hermite spline: each key has an in-tangent, a value and an out-tangent
};

// Keys at increasing times (seconds). `values` has one value per key, or three (in-tangent, value, out-tangent) for
// a cubic spline. Rotations are unit quaternions w, x, y, z. An empty track leaves its part of the node at rest.
template <typename T>
struct Track {
    std::vector<float> times;
    std::vector<T> values;
    KeyInterpolation interpolation = KeyInterpolation::linear;
    bool empty() const { return times.empty(); }
};

// A node of the animated tree: applied to the object first its `fixed` steps, then scale, rotation and translation
// (each its track's value at the time, else its rest value), then its parent's.
struct AnimatedNode {
    int parent = -1;
    std::vector<TransformStep> fixed;
    glm::vec3 rest_scale{1.0f}, rest_translation{0.0f};
    glm::vec4 rest_rotation{1.0f, 0.0f, 0.0f, 0.0f};
    Track<glm::vec3> scale, translation;
    Track<glm::vec4> rotation;
};

// What a scene's animation moves. A scene without one holds none (Scene::animation is null).
struct SceneAnimation {
    std::vector<AnimatedNode> nodes;
    // Per scene mesh, in order: its node (-1: not moved) and its own steps, applied before its node's chain.
    struct Placement {
        int node = -1;
        std::vector<TransformStep> local;
    };
    std::vector<Placement> meshes;
    std::vector<int> light_nodes;  // per light: the node at whose origin it sits, or -1
    int camera_node = -1;          // the node the camera looks from (down its -z, its +y up), or -1
    float start = 0.0f, end = 0.0f;  // the first and last key of every track
};

// The value of a track at `time`: before the first key its first value, after the last its last value.
glm::vec3 sample_track(const Track<glm::vec3>& track, float time);
// The same for a rotation, a unit quaternion (w, x, y, z).
glm::vec4 sample_track(const Track<glm::vec4>& track, float time);

// The unit quaternion a fraction `t` of the way from unit quaternion `a` to `b` along the shorter arc (b is negated
// when a . b < 0, since q and -q are the same rotation), at a constant angular speed.
glm::vec4 slerp(const glm::vec4& a, const glm::vec4& b, float t);

// The node's own steps at `time`: fixed, then scale, rotation and translation.
std::vector<TransformStep> node_steps_at(const AnimatedNode& node, float time);
// The node's chain at `time`: its own steps, then its parent's chain, up to the root.
std::vector<TransformStep> node_chain_at(const SceneAnimation& animation, int node, float time);

// The span of every track's keys into animation.start and .end (0 and 0 without keys).
void find_animation_span(SceneAnimation& animation);

}  // namespace raster
