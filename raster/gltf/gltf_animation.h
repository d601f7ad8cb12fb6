// glTF animations as raster's keyframe tracks (docs/gltf.md#animation): the first animation's channels read into
// the nodes they move, each sampler's times and values checked like any accessor.
#pragma once

#include <vector>

#include "raster/gltf/gltf_accessors.h"
#include "raster/gltf/gltf_warnings.h"
#include "raster/scene/animation.h"

namespace raster {

// The most keys (times and values) the channels of an animation may read together.
inline constexpr uint64_t kMaxGltfAnimationKeys = uint64_t{1} << 22;

// Reads animation 0 of `model` into `animation`'s nodes; `node_index[g]` is the animated node of glTF node g, or -1
// where the scene does not reach it (its channels move nothing drawn). Returns whether a channel moves a node.
// Throws InputError naming the JSON path of a malformed channel or sampler.
bool read_gltf_animation(const tinygltf::Model& model, const GltfAccessorReader& accessors,
                         const std::vector<int>& node_index, SceneAnimation& animation, GltfWarnings& warnings);

}  // namespace raster
