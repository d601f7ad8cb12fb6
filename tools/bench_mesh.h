// A generated bench mesh (positions, unit normals, triangles), its area-weighted normals, and its checks.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include "tools/vec3.h"

namespace raster::tools {

inline constexpr double kPi = 3.14159265358979323846;

using Triangle = std::array<uint32_t, 3>;

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // one per position, unit
    std::vector<Triangle> triangles;

    uint32_t add_vertex(Vec3 position, Vec3 normal = {}) {
        positions.push_back(position);
        normals.push_back(normal);
        return static_cast<uint32_t>(positions.size() - 1);
    }
};

Vec3 face_normal(const Mesh& mesh, const Triangle& t);

// Area-weighted mean of the normals of the faces around each vertex, normalised.
void set_area_weighted_normals(Mesh& mesh);

// What every mesh must satisfy before it is written; prints the summary line and returns false on a defect.
// `outward` is the direction each face is expected to face at its centroid (e.g. away from the centre).
template <typename OutwardFn>
bool check_mesh(const char* name, const Mesh& mesh, OutwardFn outward) {
    size_t inward = 0, degenerate = 0, bad_normals = 0;
    double min_area = INFINITY, max_area = 0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = face_normal(mesh, t);
        const double area = 0.5 * length(n);
        if (!(area > 0)) ++degenerate;
        min_area = std::min(min_area, area);
        max_area = std::max(max_area, area);
        const Vec3 centroid = (1.0 / 3.0) * (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]);
        if (dot(n, outward(centroid)) <= 0) ++inward;
    }
    for (const Vec3& n : mesh.normals) bad_normals += !(std::abs(length(n) - 1.0) < 1e-6);
    std::cerr << name << ": " << mesh.positions.size() << " vertices, " << mesh.triangles.size()
              << " triangles, triangle area " << min_area << " .. " << max_area << " (ratio "
              << (min_area > 0 ? max_area / min_area : INFINITY) << "), facing the wrong way " << inward
              << ", degenerate " << degenerate << ", non-unit normals " << bad_normals << "\n";
    return inward == 0 && degenerate == 0 && bad_normals == 0;
}

}  // namespace raster::tools
