// Stanford PLY meshes: the header parsed, the body read into MeshData under the file's name, files read whole.
#include "raster/formats/mesh_ply.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>

#include "raster/core/errors.h"
#include "raster/formats/ply_body.h"
#include "raster/formats/ply_header.h"

namespace raster {
namespace {

constexpr uint64_t kMaxFileBytes = uint64_t{1} << 31;  // 2 GiB

std::string object_name(const std::string& name) {
    std::string stem = std::filesystem::path(name).stem().string();
    return stem.empty() ? std::string("mesh") : stem;
}

}  // namespace

MeshData parse_ply(std::string_view bytes, const std::string& name) {
    const ply::Header header = ply::parse_header(bytes, name);
    MeshData mesh;
    ply::read_body(header, bytes.substr(header.body_offset), header.body_offset, name, mesh);
    mesh.object_names.push_back(object_name(name));
    mesh.object_first_triangle.push_back(0);
    return mesh;
}

MeshData load_ply(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(name, 0, 0, "cannot read PLY file: is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, 0, std::string("cannot open PLY file: ") + std::strerror(errno));
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
        throw InputError(name, 0, 0, "PLY file is too large: " + std::to_string(size) + " bytes (limit 2 GiB)");
    std::string bytes;
    if (!ec) bytes.reserve(static_cast<size_t>(size));
    constexpr size_t kChunk = size_t{1} << 20;
    // Uninitialised: each read fills what it reports (zeroing a megabyte per file cost more than reading a small one).
    const std::unique_ptr<char[]> chunk(new char[kChunk]);
    for (;;) {
        in.read(chunk.get(), static_cast<std::streamsize>(kChunk));
        const auto got = static_cast<size_t>(in.gcount());
        if (bytes.size() + got > kMaxFileBytes)
            throw InputError(name, 0, 0, "PLY file is too large (limit 2 GiB)");
        bytes.append(chunk.get(), got);
        if (in.eof()) break;
        if (!in) throw InputError(name, 0, 0, "error while reading PLY file");
    }
    return parse_ply(bytes, name);
}

}  // namespace raster
