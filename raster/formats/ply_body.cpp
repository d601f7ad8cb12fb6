// PLY body: each element read with either value reader (ascii or binary), faces fan-triangulated, sizes bounded.
#include "raster/formats/ply_body.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "raster/formats/ply_value_readers.h"

namespace raster::ply {
namespace {

// The fewest body bytes one instance of `e` can occupy (ascii: one byte less for the file's very last token).
uint64_t min_instance_bytes(const Element& e, Format format) {
    uint64_t bytes = 0;
    if (format == Format::BinaryLittleEndian) {
        for (const Property& p : e.properties) {
            uint64_t b = p.is_list ? type_size(p.count_type) : type_size(p.type);
            if (p.role == Role::Indices) b += 3 * type_size(p.type);  // a face has at least 3 indices
            bytes += b;
        }
    } else {
        // Every token is at least one character followed by one separator (the very last may lack it: +1 slack).
        for (const Property& p : e.properties) bytes += p.role == Role::Indices ? 2 * 4 : 2;
    }
    return bytes;
}

template <class Reader>
float finite_float(Reader& r, double v, const char* what) {
    if (!std::isfinite(v)) r.fail(std::string("non-finite ") + what);
    if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
        r.fail(std::string(what) + " is out of the float range");
    return static_cast<float>(v);
}

template <class Reader>
float colour_channel(Reader& r, double v, Type t) {
    if (t == Type::UInt8) return static_cast<float>(v / 255.0);
    if (t == Type::UInt16) return static_cast<float>(v / 65535.0);
    if (!std::isfinite(v)) r.fail("non-finite colour value");
    return static_cast<float>(std::clamp(v, 0.0, 1.0));
}

template <class Reader>
int64_t read_list_count(Reader& r, Type t) {
    const int64_t n = r.read_integer(t);
    if (n < 0) r.fail("negative list count " + std::to_string(n));
    return n;
}

template <class Reader>
void skip_element(Reader& r, const Element& e) {
    if (e.properties.empty()) return;  // occupies no bytes and no tokens
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        for (const Property& p : e.properties) {
            if (p.is_list)
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
            else
                r.read_scalar(p.type);
        }
        r.end_instance();
    }
}

template <class Reader>
void read_vertices(Reader& r, const Element& e, size_t reserve, MeshData& mesh, std::vector<glm::vec2>& uvs) {
    const bool has_colour = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::Red; });
    const bool has_normal = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::NX; });
    mesh.positions.reserve(reserve);
    if (has_colour) mesh.colors.reserve(reserve);
    if (has_normal) mesh.normals.reserve(reserve);
    const bool has_uv = std::any_of(e.properties.begin(), e.properties.end(),
                                    [](const Property& p) { return p.role == Role::U; });
    if (has_uv) uvs.reserve(reserve);
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        glm::vec3 position(0.0f), normal(0.0f), colour(0.0f);
        glm::vec2 uv(0.0f);
        for (const Property& p : e.properties) {
            if (p.is_list) {
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
                continue;
            }
            const double v = r.read_scalar(p.type);
            switch (p.role) {
                case Role::X: position.x = finite_float(r, v, "x coordinate"); break;
                case Role::Y: position.y = finite_float(r, v, "y coordinate"); break;
                case Role::Z: position.z = finite_float(r, v, "z coordinate"); break;
                case Role::NX: normal.x = finite_float(r, v, "normal nx"); break;
                case Role::NY: normal.y = finite_float(r, v, "normal ny"); break;
                case Role::NZ: normal.z = finite_float(r, v, "normal nz"); break;
                case Role::U: uv.x = finite_float(r, v, "texture coordinate u"); break;
                case Role::V: uv.y = finite_float(r, v, "texture coordinate v"); break;
                case Role::Red: colour.x = colour_channel(r, v, p.type); break;
                case Role::Green: colour.y = colour_channel(r, v, p.type); break;
                case Role::Blue: colour.z = colour_channel(r, v, p.type); break;
                default: break;
            }
        }
        r.end_instance();
        mesh.positions.push_back(position);
        if (has_colour) mesh.colors.push_back(colour);
        if (has_normal) mesh.normals.push_back(normal);
        if (has_uv) uvs.push_back(uv);
    }
}

template <class Reader>
void read_faces(Reader& r, const Element& e, uint64_t vertex_count, size_t reserve, MeshData& mesh) {
    const bool has_colour = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::Red; });
    mesh.triangles.reserve(reserve);  // at least one triangle per face
    if (has_colour) mesh.face_colors.reserve(reserve);
    std::vector<uint32_t> polygon;
    polygon.reserve(kMaxPolygonVertices);
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        polygon.clear();
        glm::vec3 colour(0.0f);
        for (const Property& p : e.properties) {
            if (p.role == Role::Indices) {
                const int64_t n = read_list_count(r, p.count_type);
                if (n < 3)
                    r.fail("face " + std::to_string(i) + " (0-based) has " + std::to_string(n) +
                           " vertices; a polygon needs at least 3");
                if (static_cast<uint64_t>(n) > kMaxPolygonVertices)
                    r.fail("face " + std::to_string(i) + " (0-based) has " + std::to_string(n) + " vertices (limit " +
                           std::to_string(kMaxPolygonVertices) + ")");
                for (int64_t k = 0; k < n; ++k) {
                    const int64_t index = r.read_integer(p.type);
                    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
                        r.fail("face " + std::to_string(i) + " (0-based): vertex index " + std::to_string(index) +
                               " out of range (the file has " + std::to_string(vertex_count) + " vertices)");
                    polygon.push_back(static_cast<uint32_t>(index));
                }
            } else if (p.is_list) {
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
            } else {
                const double v = r.read_scalar(p.type);
                switch (p.role) {
                    case Role::Red: colour.x = colour_channel(r, v, p.type); break;
                    case Role::Green: colour.y = colour_channel(r, v, p.type); break;
                    case Role::Blue: colour.z = colour_channel(r, v, p.type); break;
                    default: break;
                }
            }
        }
        r.end_instance();
        const size_t new_triangles = polygon.size() - 2;
        if (mesh.triangles.size() + new_triangles > kMaxMeshTriangles)
            r.fail("too many triangles after triangulating face " + std::to_string(i) + " (limit " +
                   std::to_string(kMaxMeshTriangles) + ")");
        for (size_t k = 1; k + 1 < polygon.size(); ++k) mesh.triangles.push_back({{polygon[0], polygon[k], polygon[k + 1]}});
        if (has_colour) mesh.face_colors.insert(mesh.face_colors.end(), new_triangles, colour);
    }
}


// Reads every element in header order. Truncation is found where the data ends (exact line or byte offset), so
// reservations are capped by what the body can hold: a header claiming millions of entries over a few bytes of body
// allocates only for those bytes. Every loop iteration consumes at least one token or byte, or throws.
template <class Reader>
void read_elements(Reader& r, const Header& header, size_t body_size, MeshData& mesh) {
    uint64_t vertex_count = 0;
    for (const Element& e : header.elements)
        if (e.name == "vertex") vertex_count = e.count;
    std::vector<glm::vec2> vertex_uvs;
    for (const Element& e : header.elements) {
        const uint64_t min_bytes = std::max<uint64_t>(1, min_instance_bytes(e, header.format));
        const auto reserve = static_cast<size_t>(std::min<uint64_t>(e.count, (uint64_t{body_size} + 1) / min_bytes));
        if (e.name == "vertex")
            read_vertices(r, e, reserve, mesh, vertex_uvs);
        else if (e.name == "face")
            read_faces(r, e, vertex_count, reserve, mesh);
        else
            skip_element(r, e);
    }
    r.finish();
    // Per-vertex texture coordinates become each triangle's corners' (MeshData keeps them per corner, as OBJ has them).
    if (!vertex_uvs.empty()) {
        mesh.corner_uvs.reserve(mesh.triangles.size());
        for (const TriangleIndices& t : mesh.triangles)
            mesh.corner_uvs.push_back({{vertex_uvs[t.v[0]], vertex_uvs[t.v[1]], vertex_uvs[t.v[2]]}});
    }
}

}  // namespace

void read_body(const Header& header, std::string_view body, size_t bytes_before, const std::string& name,
               MeshData& mesh) {
    if (header.format == Format::Ascii) {
        AsciiReader reader(body, header.line_count + 1, name);
        read_elements(reader, header, body.size(), mesh);
    } else {
        BinaryReader reader(body, bytes_before, name);
        read_elements(reader, header, body.size(), mesh);
    }
}

}  // namespace raster::ply
