// Binary little-endian PLY for the bench meshes, and the atomic write that puts it in place.
#include "tools/ply_writer.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <system_error>

#include "tools/atomic_rename.h"

namespace raster::tools {

namespace {

void append_le32(std::string& out, uint32_t value) {
    for (int byte = 0; byte < 4; ++byte) out.push_back(static_cast<char>((value >> (8 * byte)) & 0xff));
}
void append_float(std::string& out, double value) {
    const float f = static_cast<float>(value);
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    append_le32(out, bits);
}

}  // namespace

std::string ply_bytes(const Mesh& mesh, const std::string& comment) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment " + comment +
                      "\ncomment made by tools/make_bench_meshes\nelement vertex " +
                      std::to_string(mesh.positions.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\nelement face " +
                      std::to_string(mesh.triangles.size()) +
                      "\nproperty list uchar uint vertex_indices\nend_header\n";
    out.reserve(out.size() + mesh.positions.size() * 24 + mesh.triangles.size() * 13);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3 p = mesh.positions[i], n = mesh.normals[i];
        for (double v : {p.x, p.y, p.z, n.x, n.y, n.z}) append_float(out, v);
    }
    for (const Triangle& t : mesh.triangles) {
        out.push_back(3);
        for (uint32_t index : t) append_le32(out, index);
    }
    return out;
}

bool write_atomically(const std::filesystem::path& path, const std::string& bytes) {
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            std::cerr << "make_bench_meshes: " << temporary.string() << ": cannot write\n";
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return false;
        }
    }
    return rename_over(temporary, path, "make_bench_meshes");
}

}  // namespace raster::tools
