// The shared body of the scene-format fuzz targets: parse_scene on the input, meshes resolved inside a sandbox.
#include "fuzz/scene_input.h"

#include <string>
#include <string_view>

#include "fuzz/sandbox.h"
#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"

namespace raster::fuzz {
namespace {

std::string binary_triangle_ply() {
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float positions[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    ply.append(reinterpret_cast<const char*>(positions), sizeof positions);
    const unsigned char corners = 3;
    const int indices[3] = {0, 1, 2};
    ply.append(reinterpret_cast<const char*>(&corners), 1);
    ply.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return ply;
}

Sandbox& scene_sandbox() {
    static Sandbox sandbox("scene", {
        {"tri.obj", "o tri\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"},
        {"quad.ply",
         "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
         "property list uchar int vertex_indices\nend_header\n"
         "-1 -1 0 255 0 0\n1 -1 0 0 255 0\n1 1 0 0 0 255\n-1 1 0 255 255 0\n4 0 1 2 3\n"},
        {"tri_binary.ply", binary_triangle_ply()},
        // A textured OBJ with its MTL library and image, and a PLY with texture coordinates: the texture paths.
        {"tex.ppm", std::string("P6\n2 2\n255\n") + std::string("\xff\x00\x00\x00\xff\x00\x00\x00\xff\xff\xff\xff", 12)},
        {"textured.obj", "mtllib textured.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                         "usemtl tex\nf 1/1 2/2 3/3\nusemtl plain\nf 1/1 3/3 4/4\n"},
        {"textured.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd tex.ppm\nnewmtl plain\nKd 0.5 0.2 0.1\n"},
        {"uv.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "property float u\nproperty float v\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "-1 -1 0 0 0\n1 -1 0 4 0\n0 1 0 2 3\n3 0 1 2\n"},
    });
    return sandbox;
}

}  // namespace

int fuzz_scene_text(const uint8_t* data, size_t size, const char* file_name) {
    const Sandbox& sandbox = scene_sandbox();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (could_spell_a_slash(text)) return 0;
    try {
        parse_scene(text, sandbox.path() / file_name);
    } catch (const InputError&) {
        // Rejecting bad input with an InputError is the expected outcome; any other exception is a finding.
    }
    return 0;
}

}  // namespace raster::fuzz
