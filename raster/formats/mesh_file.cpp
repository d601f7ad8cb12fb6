// Mesh files: the loader the extension names.
#include "raster/formats/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj.h"
#include "raster/formats/mesh_ply.h"

namespace raster {

MeshData load_mesh_file(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".obj") return load_obj(path);
    if (extension == ".ply") return load_ply(path);
    throw InputError(path.string(), 0, 0, "unknown mesh format '" + extension + "' (expected .obj or .ply)");
}

}  // namespace raster
