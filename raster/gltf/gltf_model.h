// Untrusted glTF 2.0 bytes (.gltf or .glb) into tinygltf's model, safely: the GLB container and the JSON's nesting
// checked before tinygltf sees them, external files read only through a reader that keeps them inside the model's
// folder and under a size cap, and images kept encoded for raster and the oracle to decode each on their own.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "raster/gltf/tiny_gltf_config.h"

namespace raster {

// Reads an external file a model names (a buffer's or an image's URI, already percent-decoded) relative to the
// model's folder: at most `max_bytes` bytes, else an InputError; an InputError too when it is missing or would
// leave the folder.
using GltfFileReader = std::function<std::string(const std::string& relative_path, uint64_t max_bytes)>;

// The reader of the files in `model`'s folder and below it: a path that is absolute, climbs out with '..', or
// resolves (through links) outside the folder is refused, as is anything but a regular file. Backslashes are read
// as separators, as Windows exporters write them.
GltfFileReader gltf_folder_reader(const std::filesystem::path& model);

// Limits on what a model may make raster read or hold.
inline constexpr uint64_t kMaxGltfFileBytes = uint64_t{1} << 30;      // the .gltf/.glb file
inline constexpr uint64_t kMaxGltfExternalBytes = uint64_t{1} << 30;  // all its external files together
inline constexpr int kMaxGltfJsonDepth = 64;                          // arrays and objects inside each other

// Parses a model: `name` is its path, for messages and to tell .glb from .gltf by content (GLB starts with "glTF").
// Throws InputError naming the file and, where known, the JSON path of the problem.
tinygltf::Model parse_gltf_model(std::string_view bytes, const std::string& name, const GltfFileReader& files);

// The encoded bytes of image `index` (an image file, a data URI or a buffer view's bytes, range-checked); empty when
// tinygltf could not read its file (the caller warns and leaves the texture out).
std::string gltf_image_bytes(const tinygltf::Model& model, int index, const std::string& name);

}  // namespace raster
