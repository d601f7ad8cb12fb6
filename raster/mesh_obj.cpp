// Wavefront OBJ meshes: tinyobjloader parses, this file validates and flattens its corners into MeshData.
#include "raster/mesh_obj.h"

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include <tiny_obj_loader.h>

#include "raster/errors.h"
#include "raster/file_io.h"

namespace raster {

namespace {

// The line number tinyobjloader mentions in its message ("... line 12 ..."), or 0.
int line_in_message(const std::string& message) {
    const size_t at = message.find("line ");
    if (at == std::string::npos) return 0;
    return std::atoi(message.c_str() + at + 5);
}

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line;
}

}  // namespace

MeshData parse_obj(std::string_view text, const std::string& name) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;  // colours only when every vertex has them
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(std::string(text), "", config)) {
        const std::string message = first_line(reader.Error());
        throw InputError(name, line_in_message(message), 0, message.empty() ? "malformed OBJ" : message);
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const size_t position_count = attrib.vertices.size() / 3;
    const size_t normal_count = attrib.normals.size() / 3;
    if (position_count > kMaxMeshVertices)
        throw InputError(name, 0, 0, "more than " + std::to_string(kMaxMeshVertices) + " vertices");
    for (float value : attrib.vertices)
        if (!std::isfinite(value)) throw InputError(name, 0, 0, "a vertex coordinate is not a finite number");
    const bool has_colors = attrib.colors.size() == attrib.vertices.size() && !attrib.colors.empty();

    bool every_corner_has_normal = normal_count > 0;
    size_t corner_total = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (unsigned char corners : shape.mesh.num_face_vertices)
            if (corners != 3) throw InputError(name, 0, 0, "a face has fewer than 3 vertices");
        corner_total += shape.mesh.indices.size();
        for (const tinyobj::index_t& index : shape.mesh.indices) {
            if (index.vertex_index < 0 || static_cast<size_t>(index.vertex_index) >= position_count)
                throw InputError(name, 0, 0, "face uses vertex " + std::to_string(index.vertex_index + 1) +
                                                 " but the file has " + std::to_string(position_count));
            if (index.normal_index >= 0 && static_cast<size_t>(index.normal_index) >= normal_count)
                throw InputError(name, 0, 0, "face uses normal " + std::to_string(index.normal_index + 1) +
                                                 " but the file has " + std::to_string(normal_count));
            every_corner_has_normal = every_corner_has_normal && index.normal_index >= 0;
        }
    }
    if (corner_total / 3 > kMaxMeshTriangles)
        throw InputError(name, 0, 0, "more than " + std::to_string(kMaxMeshTriangles) + " triangles");

    MeshData mesh;
    auto position = [&](int i) {
        return glm::vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    };
    auto color = [&](int i) {
        return glm::vec3(attrib.colors[3 * i], attrib.colors[3 * i + 1], attrib.colors[3 * i + 2]);
    };
    if (!every_corner_has_normal) {
        // Positions keep their file indices, so faces stay connected and normals can be averaged across them.
        mesh.positions.reserve(position_count);
        for (size_t i = 0; i < position_count; ++i) mesh.positions.push_back(position(static_cast<int>(i)));
        if (has_colors)
            for (size_t i = 0; i < position_count; ++i) mesh.colors.push_back(color(static_cast<int>(i)));
    }
    // With normals, each distinct (position, normal) pair becomes one vertex.
    std::map<std::pair<int, int>, uint32_t> corner_vertex;
    auto vertex_for = [&](const tinyobj::index_t& index) -> uint32_t {
        if (!every_corner_has_normal) return static_cast<uint32_t>(index.vertex_index);
        auto [it, inserted] = corner_vertex.try_emplace({index.vertex_index, index.normal_index},
                                                        static_cast<uint32_t>(mesh.positions.size()));
        if (inserted) {
            mesh.positions.push_back(position(index.vertex_index));
            const int n = index.normal_index;
            mesh.normals.push_back(glm::vec3(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]));
            if (has_colors) mesh.colors.push_back(color(index.vertex_index));
        }
        return it->second;
    };
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        mesh.object_names.push_back(shape.name);
        mesh.object_first_triangle.push_back(static_cast<uint32_t>(mesh.triangles.size()));
        const auto& indices = shape.mesh.indices;
        for (size_t i = 0; i + 2 < indices.size(); i += 3)
            mesh.triangles.push_back({{vertex_for(indices[i]), vertex_for(indices[i + 1]), vertex_for(indices[i + 2])}});
    }
    for (const glm::vec3& n : mesh.normals)
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
            throw InputError(name, 0, 0, "a normal is not a finite number");
    return mesh;
}

MeshData load_obj(const std::filesystem::path& path) {
    return parse_obj(read_file_bytes(path, uint64_t{2} << 30), path.string());
}

}  // namespace raster
