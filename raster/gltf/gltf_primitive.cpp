// One glTF primitive as raster's mesh data (gltf_primitive.h).
#include "raster/gltf/gltf_primitive.h"

#include <cmath>

#include <glm/vec2.hpp>

namespace raster {
namespace {

constexpr int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

// Accessor `name` of the primitive, or -1.
int attribute(const tinygltf::Primitive& primitive, const char* name) {
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

// Every triangle's corners as vertices of their own: one per corner, in order.
void unweld(MeshData& mesh) {
    std::vector<glm::vec3> positions, colors;
    positions.reserve(mesh.triangles.size() * 3);
    if (!mesh.colors.empty()) colors.reserve(mesh.triangles.size() * 3);
    uint32_t next = 0;
    for (TriangleIndices& triangle : mesh.triangles)
        for (uint32_t& v : triangle.v) {
            positions.push_back(mesh.positions[v]);
            if (!mesh.colors.empty()) colors.push_back(mesh.colors[v]);
            v = next++;
        }
    mesh.positions = std::move(positions);
    mesh.colors = std::move(colors);
}

}  // namespace

std::vector<TriangleIndices> gltf_triangles(int mode, const std::vector<uint32_t>& indices) {
    std::vector<TriangleIndices> out;
    const size_t n = indices.size();
    if (mode == kTriangles) {
        for (size_t i = 0; i + 2 < n; i += 3) out.push_back({{indices[i], indices[i + 1], indices[i + 2]}});
    } else if (mode == kTriangleStrip) {
        for (size_t i = 0; i + 2 < n; ++i)
            out.push_back({{indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]}});
    } else if (mode == kTriangleFan) {
        for (size_t i = 0; i + 2 < n; ++i) out.push_back({{indices[i + 1], indices[i + 2], indices[0]}});
    }
    return out;
}

std::optional<MeshData> read_gltf_primitive(const GltfAccessorReader& reader, const tinygltf::Primitive& primitive,
                                            const std::string& at, const GltfMaterial& material, GltfWarnings& warnings) {
    const int mode = primitive.mode < 0 ? kTriangles : primitive.mode;
    if (mode < kTriangles) return std::nullopt;
    if (mode > kTriangleFan) reader.fail(at + "/mode", std::to_string(mode) + " is not a primitive mode (0 to 6)");
    const int position_accessor = attribute(primitive, "POSITION");
    if (position_accessor < 0) reader.fail(at + "/attributes", "has no POSITION");
    const std::string attributes_at = at + "/attributes/";

    MeshData mesh;
    int components = 0;
    // Counts are checked before anything is read: an accessor without a view costs nothing in the file.
    const size_t vertex_count = reader.count(position_accessor, attributes_at + "POSITION");
    if (vertex_count > kMaxMeshVertices)
        reader.fail(attributes_at + "POSITION", std::to_string(vertex_count) + " vertices; raster reads at most " +
                                                    std::to_string(kMaxMeshVertices));
    for (const auto& [name, accessor] : primitive.attributes)
        if (name == "NORMAL" || name == "COLOR_0" || name == "TEXCOORD_0")
            if (const size_t count = reader.count(accessor, attributes_at + name); count != vertex_count)
                reader.fail(attributes_at + name, std::to_string(count) + " elements for " + std::to_string(vertex_count) +
                                                      " positions");
    const std::vector<float> positions =
        reader.floats(position_accessor, attributes_at + "POSITION", {TINYGLTF_TYPE_VEC3}, {}, components);
    for (size_t i = 0; i < vertex_count; ++i) mesh.positions.emplace_back(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = reader.indices(primitive.indices, at + "/indices", vertex_count);
    } else {
        indices.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    if (mode == kTriangles && indices.size() % 3 != 0)
        warnings.say(at + ": a triangle list of " + std::to_string(indices.size()) +
                     " indices; the last " + std::to_string(indices.size() % 3) + " make no triangle");
    mesh.triangles = gltf_triangles(mode, indices);
    if (mesh.triangles.size() > kMaxMeshTriangles)
        reader.fail(at, std::to_string(mesh.triangles.size()) + " triangles; raster reads at most " +
                            std::to_string(kMaxMeshTriangles) + " a primitive");

    // Every other attribute has one element per vertex (their counts were checked above).
    const auto per_vertex = [&](const char* name, std::initializer_list<int> types, std::initializer_list<int> normalized,
                                int& got) {
        return reader.floats(attribute(primitive, name), attributes_at + name, types, normalized, got);
    };
    if (attribute(primitive, "NORMAL") >= 0) {
        const std::vector<float> normals = per_vertex("NORMAL", {TINYGLTF_TYPE_VEC3}, {}, components);
        for (size_t i = 0; i < vertex_count; ++i) mesh.normals.emplace_back(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    }
    if (attribute(primitive, "COLOR_0") >= 0) {
        const std::vector<float> colors =
            per_vertex("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, components);
        for (size_t i = 0; i < vertex_count; ++i) {
            const float* c = &colors[i * static_cast<size_t>(components)];
            for (int k = 0; k < 3; ++k)
                if (!(c[k] >= 0.0f && c[k] <= 1.0f))
                    reader.fail(attributes_at + "COLOR_0", "colour " + std::to_string(i) + " has a component outside [0, 1]");
            mesh.colors.push_back(glm::vec3(c[0], c[1], c[2]) * material.color_factor);
        }
    }
    if (material.material.texture && attribute(primitive, "TEXCOORD_0") >= 0) {
        const std::vector<float> uvs =
            per_vertex("TEXCOORD_0", {TINYGLTF_TYPE_VEC2},
                       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, components);
        std::vector<glm::vec2> corners_of_vertex(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) {
            glm::dvec2 uv(uvs[2 * i], uvs[2 * i + 1]);
            if (material.uv_transform) {
                uv = material.uv_transform->apply(uv);  // in glTF's texture space, before v turns up
                if (!std::isfinite(static_cast<float>(uv.x)) || !std::isfinite(static_cast<float>(uv.y)))
                    reader.fail(attributes_at + "TEXCOORD_0", "texture coordinate " + std::to_string(i) +
                                                                  " leaves float's range under KHR_texture_transform");
            }
            corners_of_vertex[i] = {static_cast<float>(uv.x), static_cast<float>(1.0 - uv.y)};
        }
        for (const TriangleIndices& triangle : mesh.triangles) {
            TriangleUvs corners;
            for (int k = 0; k < 3; ++k) corners.uv[k] = corners_of_vertex[triangle.v[k]];
            mesh.corner_uvs.push_back(corners);
        }
    }
    if (!primitive.targets.empty()) warnings.say(at + ": morph targets are not applied; the base shape is drawn");
    if (mesh.normals.empty()) {
        if (mesh.triangles.size() * 3 > kMaxMeshVertices)
            reader.fail(at, std::to_string(mesh.triangles.size()) + " triangles without normals need a vertex a corner, past raster's " +
                                std::to_string(kMaxMeshVertices));
        unweld(mesh);
    }
    return mesh;
}

}  // namespace raster
