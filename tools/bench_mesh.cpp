// A generated bench mesh's face normals and its vertex normals from them.
#include "tools/bench_mesh.h"

namespace raster::tools {

Vec3 face_normal(const Mesh& mesh, const Triangle& t) {
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    return cross(b - a, c - a);  // length = twice the area
}

void set_area_weighted_normals(Mesh& mesh) {
    std::fill(mesh.normals.begin(), mesh.normals.end(), Vec3{});
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = face_normal(mesh, t);
        for (uint32_t corner : t) mesh.normals[corner] = mesh.normals[corner] + n;
    }
    for (Vec3& n : mesh.normals) n = normalized(n);
}

}  // namespace raster::tools
