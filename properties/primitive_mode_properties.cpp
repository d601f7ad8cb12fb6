// glTF's primitive modes seen in pixels: a triangle strip and a triangle fan over random vertices, read by the real
// glTF loader and rendered, give the same visibility buffer, sample for sample (triangle, barycentrics, depth), as
// the triangle list whose indices the glTF 2.0 specification's numbering gives, written here: strip triangle i is
// (v_i, v_{i+1+i%2}, v_{i+2-i%2}), fan triangle i is (v_{i+1}, v_{i+2}, v_0). A strip whose odd triangles keep their
// order, or a fan numbered from the wrong vertex, shows as other triangles or barycentrics.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "properties/building_blocks.h"
#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"
#include "raster/compat/scene_loader.h"

namespace raster::properties {
namespace {

struct ModeCase {
    std::vector<glm::vec3> vertices;  // 3 to 10, within [-1, 1]^2 x [-0.5, 0.5]
    bool fan = false;                 // else a strip
};

std::ostream& operator<<(std::ostream& os, const ModeCase& c) {
    os << "ModeCase{" << (c.fan ? "fan" : "strip");
    for (const glm::vec3& v : c.vertices) os << " " << literal(v);
    return os << "}";
}

Gen<ModeCase> mode_cases() {
    return gen::exec([] {
        ModeCase c;
        c.fan = coin();
        c.vertices.resize(3 + static_cast<size_t>(8.0 * unit() * 0.999));
        for (glm::vec3& v : c.vertices)
            v = glm::vec3(static_cast<float>(2.0 * unit() - 1.0), static_cast<float>(2.0 * unit() - 1.0),
                          static_cast<float>(unit() - 0.5));
        return c;
    });
}

// The list the specification's numbering gives, as vertex indices.
std::vector<uint16_t> spec_list(const ModeCase& c) {
    std::vector<uint16_t> out;
    const int triangles = static_cast<int>(c.vertices.size()) - 2;
    for (int i = 0; i < triangles; ++i) {
        const int corners[3] = {c.fan ? i + 1 : i, c.fan ? i + 2 : i + 1 + i % 2, c.fan ? 0 : i + 2 - i % 2};
        for (const int k : corners) out.push_back(static_cast<uint16_t>(k));
    }
    return out;
}

// A folder of this process's own for the models' external buffers.
const std::filesystem::path& model_folder() {
    static const std::filesystem::path folder = [] {
        auto path = std::filesystem::temp_directory_path() / ("raster_primitive_modes_" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return folder;
}

// The case's scene drawn as a strip or fan (`as_list` false) or as the spec's list, unlit on a 64 x 48 frame. Each
// model names its buffer file, written here: the positions, then the list's indices.
Scene scene_of(const ModeCase& c, bool as_list) {
    const std::vector<uint16_t> list = spec_list(c);
    std::string bytes(c.vertices.size() * sizeof(glm::vec3), '\0');
    std::memcpy(bytes.data(), c.vertices.data(), bytes.size());
    const size_t index_offset = bytes.size();
    bytes.append(reinterpret_cast<const char*>(list.data()), list.size() * sizeof(uint16_t));
    const std::filesystem::path folder = model_folder();
    std::ofstream(folder / "modes.bin", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    glm::vec3 lo = c.vertices.front(), hi = c.vertices.front();
    for (const glm::vec3& v : c.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const std::string count = std::to_string(c.vertices.size());
    std::string primitive = "{\"attributes\": {\"POSITION\": 0}, \"mode\": " + std::string(as_list ? "4" : c.fan ? "6" : "5");
    if (as_list) primitive += ", \"indices\": 1";
    const std::string text =
        "{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"mesh\": 0}],"
        " \"meshes\": [{\"primitives\": [" + primitive + "}]}],"
        " \"buffers\": [{\"uri\": \"modes.bin\", \"byteLength\": " + std::to_string(bytes.size()) + "}],"
        " \"bufferViews\": [{\"buffer\": 0, \"byteOffset\": 0, \"byteLength\": " + std::to_string(index_offset) + "},"
        " {\"buffer\": 0, \"byteOffset\": " + std::to_string(index_offset) + ", \"byteLength\": " +
        std::to_string(list.size() * 2) + "}],"
        " \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": " + count + ", \"type\": \"VEC3\","
        " \"min\": " + yaml_vector(lo) + ", \"max\": " + yaml_vector(hi) + "},"
        " {\"bufferView\": 1, \"componentType\": 5123, \"count\": " + std::to_string(list.size()) + ", \"type\": \"SCALAR\"}]}";
    Scene scene = parse_scene_file(text, folder / (as_list ? "list.gltf" : "modes.gltf")).scene;
    scene.settings.width = 64;
    scene.settings.height = 48;
    scene.settings.shading = ShadingMode::unlit;
    return scene;
}

}  // namespace

RASTER_DRAWING_PROPERTY(PrimitiveModes, aStripOrFanCoversTheSamplesOfTheListTheSpecNumbers) {
    const ModeCase c = *mode_cases();
    const Scene drawn_scene = scene_of(c, false), list_scene = scene_of(c, true);
    RC_ASSERT(drawn_scene.meshes.size() == 1 && list_scene.meshes.size() == 1);
    RC_ASSERT(drawn_scene.meshes[0].data->triangles.size() == c.vertices.size() - 2);
    const RenderResult drawn = render_with(impl, drawn_scene), list = render_with(impl, list_scene);
    const VisibilityBuffer &a = drawn.visibility, &b = list.visibility;
    int covered = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const size_t at = a.index(x, y, 0);
            covered += a.triangle[at] != kNoTriangle;
            if (a.triangle[at] != b.triangle[at] || a.bary[at] != b.bary[at] || a.view_depth[at] != b.view_depth[at])
                fail_case("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): the " + (c.fan ? "fan" : "strip") +
                          " shows triangle " + std::to_string(static_cast<int>(a.triangle[at])) + ", the list " +
                          std::to_string(static_cast<int>(b.triangle[at])) + " (-1: none), or other barycentrics or depth");
        }
    RC_CLASSIFY(covered > 0, "some sample covered");
}

}  // namespace raster::properties
