// glTF animations as raster's keyframe tracks (gltf_animation.h).
#include "raster/gltf/gltf_animation.h"

#include <string>

#include <glm/geometric.hpp>

namespace raster {
namespace {

KeyInterpolation interpolation_of(const std::string& name, const GltfAccessorReader& accessors, const std::string& at) {
    if (name == "LINEAR" || name.empty()) return KeyInterpolation::linear;
    if (name == "STEP") return KeyInterpolation::step;
    if (name == "CUBICSPLINE") return KeyInterpolation::cubic_spline;
    accessors.fail(at + "/interpolation", "'" + name + "' is not LINEAR, STEP or CUBICSPLINE");
}

// A sampler's keys: its input's times, increasing, and its output's values, one per key (three for a cubic spline).
template <typename T>
Track<T> read_track(const tinygltf::AnimationSampler& sampler, const std::string& at, const GltfAccessorReader& accessors,
                    int type, std::initializer_list<int> normalized) {
    Track<T> track;
    track.interpolation = interpolation_of(sampler.interpolation, accessors, at);
    int components = 0;
    track.times = accessors.floats(sampler.input, at + "/input", {TINYGLTF_TYPE_SCALAR}, {}, components);
    for (size_t k = 1; k < track.times.size(); ++k)
        if (!(track.times[k] > track.times[k - 1]))
            accessors.fail(at + "/input", "key " + std::to_string(k) + "'s time " + std::to_string(track.times[k]) +
                                              " does not follow " + std::to_string(track.times[k - 1]));
    const std::vector<float> values = accessors.floats(sampler.output, at + "/output", {type}, normalized, components);
    const size_t per_key = track.interpolation == KeyInterpolation::cubic_spline ? 3 : 1;
    const size_t count = values.size() / static_cast<size_t>(components);
    if (count != track.times.size() * per_key)
        accessors.fail(at + "/output", std::to_string(count) + " values for " + std::to_string(track.times.size()) +
                                           " keys" + (per_key == 3 ? " (a cubic spline needs three a key)" : ""));
    for (size_t i = 0; i < count; ++i) {
        T value;
        for (int c = 0; c < components; ++c) value[c] = values[i * static_cast<size_t>(components) + static_cast<size_t>(c)];
        track.values.push_back(value);
    }
    return track;
}

// glTF writes a rotation x, y, z, w; raster keeps w, x, y, z, each key's value a unit quaternion (tangents as written).
void to_unit_wxyz(Track<glm::vec4>& track, const GltfAccessorReader& accessors, const std::string& at) {
    const bool cubic = track.interpolation == KeyInterpolation::cubic_spline;
    for (size_t i = 0; i < track.values.size(); ++i) {
        glm::vec4& q = track.values[i];
        q = {q.w, q.x, q.y, q.z};
        if (cubic && i % 3 != 1) continue;
        const float length = glm::length(q);
        if (!(length > 0.0f)) accessors.fail(at + "/output", "rotation " + std::to_string(i) + " is the zero quaternion");
        q /= length;
    }
}

}  // namespace

bool read_gltf_animation(const tinygltf::Model& model, const GltfAccessorReader& accessors,
                         const std::vector<int>& node_index, SceneAnimation& animation, GltfWarnings& warnings) {
    if (model.animations.empty()) return false;
    if (model.animations.size() > 1)
        warnings.say("the file has " + std::to_string(model.animations.size()) + " animations; raster plays the first ('" +
                     model.animations[0].name + "')");
    const tinygltf::Animation& clip = model.animations[0];
    bool moves = false;
    uint64_t keys = 0;  // every channel reads its sampler's keys: their total is capped, not each sampler's
    for (size_t c = 0; c < clip.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = clip.channels[c];
        const std::string at = "/animations/0/channels/" + std::to_string(c);
        if (channel.target_node < 0 || static_cast<size_t>(channel.target_node) >= model.nodes.size())
            accessors.fail(at + "/target/node", "there is no node " + std::to_string(channel.target_node));
        if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= clip.samplers.size())
            accessors.fail(at + "/sampler", "there is no sampler " + std::to_string(channel.sampler));
        const std::string& path = channel.target_path;
        if (path == "weights") {
            warnings.say(at + ": morph target weights are not animated");
            continue;
        }
        if (path != "translation" && path != "rotation" && path != "scale")
            accessors.fail(at + "/target/path", "'" + path + "' is not translation, rotation, scale or weights");
        const int target = node_index[static_cast<size_t>(channel.target_node)];
        if (target < 0) continue;  // a node the scene does not draw
        if (!model.nodes[static_cast<size_t>(channel.target_node)].matrix.empty())
            accessors.fail(at + "/target/node", "node " + std::to_string(channel.target_node) +
                                                    " has a matrix; glTF animates only nodes given by scale, rotation and translation");
        const tinygltf::AnimationSampler& sampler = clip.samplers[static_cast<size_t>(channel.sampler)];
        const std::string sampler_at = "/animations/0/samplers/" + std::to_string(channel.sampler);
        keys += accessors.count(sampler.input, sampler_at + "/input") + accessors.count(sampler.output, sampler_at + "/output");
        if (keys > kMaxGltfAnimationKeys)
            accessors.fail(at, "the animation's channels read more than " + std::to_string(kMaxGltfAnimationKeys) + " keys");
        AnimatedNode& node = animation.nodes[static_cast<size_t>(target)];
        if (path == "rotation") {
            node.rotation = read_track<glm::vec4>(sampler, sampler_at, accessors, TINYGLTF_TYPE_VEC4,
                                                  {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                   TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
            to_unit_wxyz(node.rotation, accessors, sampler_at);
        } else {
            (path == "scale" ? node.scale : node.translation) =
                read_track<glm::vec3>(sampler, sampler_at, accessors, TINYGLTF_TYPE_VEC3, {});
        }
        moves = true;
    }
    return moves;
}

}  // namespace raster
