// The icosphere bench mesh: the icosahedron's faces wound outwards, then split into four, level by level.
#include "tools/icosphere_mesh.h"

#include <map>
#include <utility>

namespace raster::tools {

Mesh make_icosphere(int subdivisions) {
    Mesh mesh;
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const Vec3 corners[12] = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (const Vec3& c : corners) mesh.add_vertex(normalized(c), normalized(c));
    std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    // The icosahedron is convex around the origin: a face is counter-clockwise from outside when its normal
    // points away from the origin. Subdivision keeps each face's winding.
    for (Triangle& f : faces)
        if (dot(cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]),
                mesh.positions[f[0]]) < 0)
            std::swap(f[1], f[2]);

    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint_of_edge;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const std::pair<uint32_t, uint32_t> key = std::minmax(a, b);
            if (auto it = midpoint_of_edge.find(key); it != midpoint_of_edge.end()) return it->second;
            const Vec3 p = normalized(mesh.positions[a] + mesh.positions[b]);
            const uint32_t id = mesh.add_vertex(p, p);
            midpoint_of_edge.emplace(key, id);
            return id;
        };
        std::vector<Triangle> finer;
        finer.reserve(faces.size() * 4);
        for (const Triangle& f : faces) {
            const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(finer);
    }
    mesh.triangles = std::move(faces);
    return mesh;
}

}  // namespace raster::tools
