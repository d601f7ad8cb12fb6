// Fuzz target: glTF and GLB bytes through raster's glTF reader (tinygltf behind our checks, accessors, node trees,
// materials), then the default framing and the scene check every renderer relies on. External files come from
// memory: tri.bin (a triangle's positions and indices) and tex.png (a 2 x 2 image); any other name is missing.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "raster/compat/mesh_scene.h"
#include "raster/core/errors.h"
#include "raster/gltf/gltf_scene.h"
#include "raster/scene/validation.h"

namespace {

std::string triangle_buffer() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::string bytes(sizeof positions + sizeof indices, '\0');
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + sizeof positions, indices, sizeof indices);
    return bytes;
}

const unsigned char kTinyPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
    0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xfd, 0xd4, 0x9a, 0x73, 0x00, 0x00, 0x00, 0x12, 0x49,
    0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xc0, 0x00, 0xc2, 0x0c, 0xff, 0x81, 0x00, 0x00, 0x1f, 0xee,
    0x05, 0xfb, 0xf1, 0xab, 0xba, 0x77, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

std::string memory_file(const std::string& path, uint64_t max_bytes) {
    std::string bytes;
    if (path == "tri.bin") bytes = triangle_buffer();
    else if (path == "tex.png") bytes.assign(reinterpret_cast<const char*>(kTinyPng), sizeof kTinyPng);
    else throw raster::InputError("'" + path + "': no such file");
    if (bytes.size() > max_bytes) throw raster::InputError("'" + path + "' is past the cap");
    return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        raster::Scene scene;
        const raster::GltfSceneParts parts = raster::read_gltf_scene(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.gltf", memory_file, scene);
        raster::frame_scene(scene, !parts.camera, !parts.lights);
        raster::validate_scene(scene);
    } catch (const raster::InputError&) {
        // Rejecting bad input with an InputError is the expected outcome; any other exception is a finding.
    }
    return 0;
}
