// Mesh files: the loader the extension names.
#include "raster/formats/mesh_file.h"

#include <string>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/formats/mesh_obj.h"
#include "raster/formats/mesh_ply.h"

namespace raster {

namespace {

[[noreturn]] void unknown_format(const std::filesystem::path& path, const std::string& extension) {
    throw InputError(path.string(), 0, 0, "unknown mesh format '" + extension + "' (expected .obj or .ply)");
}

}  // namespace

bool is_mesh_file(const std::filesystem::path& path) {
    const std::string extension = lowercase_extension(path);
    return extension == ".obj" || extension == ".ply";
}

MeshData load_mesh_file(const std::filesystem::path& path) {
    const std::string extension = lowercase_extension(path);
    if (extension == ".obj") return load_obj(path);
    if (extension == ".ply") return load_ply(path);
    unknown_format(path, extension);
}

MeshData parse_mesh_file(std::string_view bytes, const std::filesystem::path& path) {
    const std::string extension = lowercase_extension(path);
    if (extension == ".obj") return parse_obj(bytes, path.string());
    if (extension == ".ply") return parse_ply(bytes, path.string());
    unknown_format(path, extension);
}

}  // namespace raster
