// Wavefront OBJ meshes: tinyobjloader parses, this file validates and flattens its corners into MeshData.
#include "raster/formats/mesh_obj.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"

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

// Statements of the OBJ specification (and tinyobjloader's vw / t); anything else is not OBJ text.
bool known_statement(std::string_view keyword) {
    static constexpr std::string_view kKnown[] = {
        "v",   "vt",      "vn",    "vp",   "f",     "l",     "p",        "o",        "g",          "s",
        "mg",  "usemtl",  "mtllib", "cstype", "deg", "bmat",  "step",     "curv",     "curv2",      "surf",
        "parm", "trim",   "hole",  "scrv", "sp",    "end",   "con",      "call",     "csh",        "bevel",
        "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap", "vw", "t"};
    for (std::string_view known : kKnown)
        if (keyword == known) return true;
    return false;
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// tinyobjloader skips what it cannot read: unknown statements, coordinates that are not numbers (read as 0, so
// "nan" would silently become 0), missing coordinates (read as 0: a truncated file loads) and faces of fewer than
// 3 corners. This scan refuses all of them first, naming the line, and checks face indices as it goes.
void check_obj_text(std::string_view text, const std::string& name) {
    size_t positions = 0, normals = 0;
    struct LaterIndex {
        int line;
        long index;
        bool normal;
    };
    std::vector<LaterIndex> later;  // positive indices past what is defined so far, checked at the end
    int line_number = 0;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const std::vector<std::string_view> words = split_words(line);
        if (words.empty() || words[0][0] == '#') continue;
        auto fail = [&](const std::string& message) { throw InputError(name, line_number, 0, message); };
        const std::string_view keyword = words[0];
        if (!known_statement(keyword)) {
            std::string shown(keyword.substr(0, 32));
            for (char& c : shown)
                if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
            fail("not an OBJ statement: '" + shown + "'");
        }
        if (keyword == "v" || keyword == "vn") {
            if (words.size() < 4)
                fail(std::string(keyword == "v" ? "a vertex" : "a normal") + " needs 3 coordinates, has " +
                     std::to_string(words.size() - 1));
            for (size_t k = 1; k < words.size(); ++k) {
                const std::string word(words[k]);
                char* parsed_end = nullptr;
                errno = 0;
                const double value = std::strtod(word.c_str(), &parsed_end);
                if (parsed_end != word.c_str() + word.size()) fail("'" + word + "' is not a number");
                if (!std::isfinite(value) || std::fabs(value) > 3.0e38) fail("'" + word + "' is not a finite number");
            }
            ++(keyword == "v" ? positions : normals);
        } else if (keyword == "f") {
            if (words.size() < 4) fail("a face needs at least 3 vertices, has " + std::to_string(words.size() - 1));
            if (words.size() - 1 > kMaxPolygonVertices)
                fail("a face has " + std::to_string(words.size() - 1) + " vertices, more than " +
                     std::to_string(kMaxPolygonVertices));
            for (size_t k = 1; k < words.size(); ++k) {
                // v, v/vt, v//vn or v/vt/vn; texture indices are not read
                const std::string corner(words[k]);
                std::vector<std::string> parts(1);
                for (char c : corner) {
                    if (c == '/') parts.emplace_back();
                    else parts.back() += c;
                }
                if (parts.size() > 3) fail("face corner '" + corner + "' has more than 3 parts");
                for (size_t part = 0; part < parts.size(); part += 2) {
                    if (part == 2 && parts[2].empty()) fail("face corner '" + corner + "' has an empty normal index");
                    char* parsed_end = nullptr;
                    errno = 0;
                    const long index = std::strtol(parts[part].c_str(), &parsed_end, 10);
                    if (parts[part].empty() || *parsed_end != '\0' || errno == ERANGE)
                        fail("face corner '" + corner + "' is not a vertex index");
                    const bool normal = part == 2;
                    const size_t count = normal ? normals : positions;
                    if (index == 0) fail("face corner '" + corner + "': OBJ indices start at 1");
                    if (index < -static_cast<long>(count))
                        fail("face corner '" + corner + "': relative index " + std::to_string(index) + " but only " +
                             std::to_string(count) + (normal ? " normals" : " vertices") + " precede it");
                    if (index > 0 && static_cast<size_t>(index) > count) later.push_back({line_number, index, normal});
                }
            }
        }
    }
    for (const LaterIndex& ref : later) {
        const size_t count = ref.normal ? normals : positions;
        if (static_cast<size_t>(ref.index) > count)
            throw InputError(name, ref.line, 0,
                             std::string("face uses ") + (ref.normal ? "normal " : "vertex ") + std::to_string(ref.index) +
                                 " but the file has " + std::to_string(count));
    }
}

}  // namespace

MeshData parse_obj(std::string_view text, const std::string& name) {
    check_obj_text(text, name);
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
