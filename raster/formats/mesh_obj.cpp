// Wavefront OBJ meshes: the statements read and checked, faces triangulated, corners flattened into MeshData.
#include "raster/formats/mesh_obj.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/formats/mesh_obj_reader.h"
#include "raster/formats/polygon_triangulation.h"

namespace raster {

namespace {

bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Normals are kept only when every face corner names one; then each distinct (position, normal) pair of the
// corners becomes one vertex, numbered in the order the triangles first use it. Without normals, positions keep
// their file numbering, so faces stay connected and normals can be averaged across them.
class VertexNumbering {
public:
    VertexNumbering(obj::ObjStatements& file, MeshData& mesh) : file_(file), mesh_(mesh) {
        with_normals_ = !file.normals.empty();
        for (const obj::Corner& corner : file.corners) with_normals_ = with_normals_ && corner.normal != obj::kNoNormal;
    }

    uint32_t vertex_of(const obj::Corner& corner) {
        if (!with_normals_) return corner.position;
        const uint64_t key = uint64_t{corner.position} << 32 | corner.normal;
        const auto [it, inserted] = vertex_.try_emplace(key, static_cast<uint32_t>(mesh_.positions.size()));
        if (inserted) {
            mesh_.positions.push_back(file_.positions[corner.position]);
            mesh_.normals.push_back(file_.normals[corner.normal]);
            if (!file_.colors.empty()) mesh_.colors.push_back(file_.colors[corner.position]);
        }
        return it->second;
    }

    // Hands the file's positions and colours to the mesh when they keep their numbering.
    void finish() {
        if (with_normals_) return;
        mesh_.positions = std::move(file_.positions);
        mesh_.colors = std::move(file_.colors);
    }

private:
    obj::ObjStatements& file_;
    MeshData& mesh_;
    bool with_normals_ = false;
    std::unordered_map<uint64_t, uint32_t> vertex_;
};

}  // namespace

MeshData parse_obj(std::string_view text, const std::string& name) {
    obj::ObjStatements file = obj::read_obj_statements(text, name);
    if (file.positions.size() > kMaxMeshVertices)
        throw InputError(name, 0, 0, "more than " + std::to_string(kMaxMeshVertices) + " vertices");
    for (const glm::vec3& position : file.positions)
        if (!is_finite(position)) throw InputError(name, 0, 0, "a vertex coordinate is not a finite number");
    uint64_t triangle_count = 0;
    for (const obj::Face& face : file.faces) triangle_count += face.corner_count - 2;
    if (triangle_count > kMaxMeshTriangles)
        throw InputError(name, 0, 0, "more than " + std::to_string(kMaxMeshTriangles) + " triangles");

    MeshData mesh;
    mesh.triangles.reserve(triangle_count);
    // Texture coordinates are kept when every corner names one (the scene drops them where no material is textured).
    bool with_uvs = !file.texcoords.empty();
    for (const obj::Corner& corner : file.corners) with_uvs = with_uvs && corner.texcoord != obj::kNoTexcoord;
    if (with_uvs) mesh.corner_uvs.reserve(triangle_count);
    const bool with_materials = !file.material_names.empty();
    for (size_t k = 0; k < file.material_libraries.size(); ++k)
        mesh.material_libraries.push_back({file.material_libraries[k], file.material_library_lines[k]});
    VertexNumbering numbering(file, mesh);
    std::vector<glm::vec3> polygon;
    std::vector<PolygonTriangle> triangles;
    uint32_t run_material = obj::kNoMaterial;
    for (size_t object = 0; object < file.objects.size(); ++object) {
        mesh.object_names.push_back(file.objects[object].name);
        mesh.object_first_triangle.push_back(static_cast<uint32_t>(mesh.triangles.size()));
        const size_t end = object + 1 < file.objects.size() ? file.objects[object + 1].first_face : file.faces.size();
        for (size_t f = file.objects[object].first_face; f < end; ++f) {
            const obj::Corner* corners = &file.corners[file.faces[f].first_corner];
            polygon.clear();
            for (size_t k = 0; k < file.faces[f].corner_count; ++k)
                polygon.push_back(file.positions[corners[k].position]);
            triangles.clear();
            triangulate_polygon(polygon, triangles);
            const uint32_t material = file.faces[f].material;
            if (with_materials && !triangles.empty() &&
                (mesh.material_runs.empty() || material != run_material)) {
                run_material = material;
                mesh.material_runs.push_back({material == obj::kNoMaterial ? "" : file.material_names[material],
                                              static_cast<uint32_t>(mesh.triangles.size())});
            }
            for (const PolygonTriangle& t : triangles) {
                mesh.triangles.push_back({{numbering.vertex_of(corners[t[0]]), numbering.vertex_of(corners[t[1]]),
                                           numbering.vertex_of(corners[t[2]])}});
                if (with_uvs)
                    mesh.corner_uvs.push_back({{file.texcoords[corners[t[0]].texcoord],
                                                file.texcoords[corners[t[1]].texcoord],
                                                file.texcoords[corners[t[2]].texcoord]}});
            }
        }
    }
    numbering.finish();
    for (const glm::vec3& normal : mesh.normals)
        if (!is_finite(normal)) throw InputError(name, 0, 0, "a normal is not a finite number");
    return mesh;
}

MeshData load_obj(const std::filesystem::path& path) {
    return parse_obj(read_file_bytes(path, uint64_t{2} << 30), path.string());
}

}  // namespace raster
