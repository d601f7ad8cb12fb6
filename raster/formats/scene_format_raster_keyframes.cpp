// The raster format's keyframes: a scene-graph node's scale, rotation and translation at increasing times, read
// into the node's animation tracks (docs/animation.md).
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "raster/formats/scene_formats.h"
#include "raster/scene/animation.h"

namespace raster {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxKeyframes = size_t{1} << 16;

// A rotate or quaternion step as a unit quaternion (w, x, y, z).
glm::vec4 unit_quaternion(const TransformStep& step) {
    if (const auto* q = std::get_if<QuaternionStep>(&step)) return glm::normalize(q->wxyz);
    const auto& rotate = std::get<RotateStep>(step);
    const double half = 0.5 * rotate.degrees * kPi / 180.0;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(rotate.axis)) * std::sin(half);
    return glm::vec4(static_cast<float>(std::cos(half)), glm::vec3(axis));
}

}  // namespace

void read_raster_keyframes(const Node& node, const DocumentReader& reader, AnimatedNode& animated) {
    const Node& keyframes = reader.required(node, "keyframes");
    reader.expect_sequence(keyframes, "keyframes");
    if (keyframes.size() == 0) reader.fail(keyframes, "keyframes needs at least one key");
    if (keyframes.size() > kMaxKeyframes) reader.fail(keyframes, "more than " + std::to_string(kMaxKeyframes) + " keyframes");
    KeyInterpolation interpolation = KeyInterpolation::linear;
    if (const Node& v = reader.optional(node, "interpolation"); v.is_defined()) {
        const std::string name = reader.string(v, "interpolation");
        if (name == "step") interpolation = KeyInterpolation::step;
        else if (name != "linear") reader.fail(v, "interpolation is linear or step, got '" + name + "'");
    }
    animated.scale.interpolation = animated.rotation.interpolation = animated.translation.interpolation = interpolation;
    float previous = 0.0f;
    for (size_t k = 0; k < keyframes.size(); ++k) {
        const Node& key = keyframes[k];
        reader.expect_map(key, "a keyframe");
        reader.check_keys(key, {"time", "translate", "rotate", "quaternion", "scale"});
        const float time = reader.finite_float(reader.required(key, "time"), "keyframe time");
        if (k > 0 && !(time > previous))
            reader.fail(key, "keyframe times must increase: " + std::to_string(time) + " after " + std::to_string(previous));
        previous = time;
        if (reader.optional(key, "rotate").is_defined() && reader.optional(key, "quaternion").is_defined())
            reader.fail(key, "a keyframe gives its rotation as rotate or as quaternion, not both");
        for (const Node::Entry& entry : key.entries()) {
            const std::string& kind = entry.key.text();
            if (kind == "time") continue;
            const TransformStep step = read_transform_step(kind, entry.value, reader);
            if (kind == "translate") {
                animated.translation.times.push_back(time);
                animated.translation.values.push_back(std::get<TranslateStep>(step).offset);
            } else if (kind == "scale") {
                animated.scale.times.push_back(time);
                animated.scale.values.push_back(std::get<ScaleStep>(step).factors);
            } else {
                animated.rotation.times.push_back(time);
                animated.rotation.values.push_back(unit_quaternion(step));
            }
        }
    }
}

}  // namespace raster
