// The organic bench mesh: the cube sphere's lattice, each point jittered and displaced once, split into triangles.
#include "tools/organic_mesh.h"

#include <map>

#include "tools/noise.h"

namespace raster::tools {

Mesh make_organic(const OrganicParams& params) {
    const int n = params.cells_per_face_side;
    const GradientNoise noise(params.seed);
    const double cell_angle = (kPi / 2.0) / n;  // a cell's side at a face's centre, in radians

    // The cube's surface lattice: integer points (i, j, k) in [0, n]^3 with a coordinate at 0 or n. A point on a
    // seam belongs to several faces; the map gives it one vertex, and its jitter is a function of the point alone.
    std::map<std::array<int, 3>, uint32_t> vertex_of_lattice_point;
    Mesh mesh;
    auto vertex = [&](std::array<int, 3> lattice) {
        if (auto it = vertex_of_lattice_point.find(lattice); it != vertex_of_lattice_point.end()) return it->second;
        const Vec3 on_cube{2.0 * lattice[0] / n - 1.0, 2.0 * lattice[1] / n - 1.0, 2.0 * lattice[2] / n - 1.0};
        Vec3 direction = normalized(on_cube);
        // Jitter along the sphere: two tangent directions, offsets from a stream seeded by the lattice point.
        SplitMix64 random(params.seed ^ (uint64_t(lattice[0]) << 42) ^ (uint64_t(lattice[1]) << 21) ^
                          uint64_t(lattice[2]));
        const Vec3 helper = std::abs(direction.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
        const Vec3 tangent_u = normalized(cross(helper, direction)), tangent_v = cross(direction, tangent_u);
        // A cell's side on the sphere shrinks about as 1 / |on_cube|^2 from a face's centre to its corners.
        const double local_cell = cell_angle / dot(on_cube, on_cube);
        const double du = (random.uniform() * 2 - 1) * params.jitter * local_cell;
        const double dv = (random.uniform() * 2 - 1) * params.jitter * local_cell;
        direction = normalized(direction + du * tangent_u + dv * tangent_v);
        const double radius =
            1.0 + params.lump_amplitude * noise.fractal(params.lump_frequency * direction + Vec3{0.37, 1.91, 2.53},
                                                        params.octaves);
        const Vec3 p = radius * direction;
        const uint32_t id =
            mesh.add_vertex({p.x * params.stretch.x, p.y * params.stretch.y, p.z * params.stretch.z});
        vertex_of_lattice_point.emplace(lattice, id);
        return id;
    };

    // Face (axis, sign): the lattice coordinate `axis` is fixed at 0 or n; grid steps (a, b) run along
    // axis + 1 and axis + 2 (the latter reversed on the negative faces), so that a x b points outwards and the
    // grid's quads, taken a then b, are counter-clockwise seen from outside.
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {+1, -1})
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) {
                    auto corner = [&](int da, int db) {
                        std::array<int, 3> lattice{};
                        lattice[axis] = sign > 0 ? n : 0;
                        lattice[(axis + 1) % 3] = a + da;
                        lattice[(axis + 2) % 3] = sign > 0 ? b + db : n - (b + db);
                        return vertex(lattice);
                    };
                    const uint32_t v00 = corner(0, 0), v10 = corner(1, 0), v11 = corner(1, 1), v01 = corner(0, 1);
                    const double diagonal_00_11 = length(mesh.positions[v11] - mesh.positions[v00]);
                    const double diagonal_10_01 = length(mesh.positions[v01] - mesh.positions[v10]);
                    if (diagonal_00_11 <= diagonal_10_01)
                        mesh.triangles.insert(mesh.triangles.end(), {{v00, v10, v11}, {v00, v11, v01}});
                    else
                        mesh.triangles.insert(mesh.triangles.end(), {{v00, v10, v01}, {v10, v11, v01}});
                }
    set_area_weighted_normals(mesh);
    return mesh;
}

}  // namespace raster::tools
