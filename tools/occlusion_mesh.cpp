// The occlusion bench mesh: each layer's grid of heights and normals, wound counter-clockwise towards the camera.
#include "tools/occlusion_mesh.h"

namespace raster::tools {

Mesh make_occlusion(const OcclusionParams& params) {
    Mesh mesh;
    const int n = params.cells_per_side;
    for (int step = 0; step < params.layers; ++step) {
        const int layer = params.farthest_first ? params.layers - 1 - step : step;
        const double distance = params.first_distance + layer * params.spacing;
        const double half_size =
            params.coverage_margin * distance * std::tan(params.half_fov_degrees * kPi / 180.0);
        const double k = 2.0 * kPi * params.waves_per_sheet / (2.0 * half_size);  // wave number
        const double phase_x = 0.7 * layer, phase_y = 1.3 * layer;                 // layers differ
        const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = half_size * (2.0 * i / n - 1.0), y = half_size * (2.0 * j / n - 1.0);
                const double sx = std::sin(k * x + phase_x), cx = std::cos(k * x + phase_x);
                const double sy = std::sin(k * y + phase_y), cy = std::cos(k * y + phase_y);
                const double height = params.wave_amplitude * sx * cy;  // towards the camera (+z)
                const double dh_dx = params.wave_amplitude * k * cx * cy, dh_dy = -params.wave_amplitude * k * sx * sy;
                mesh.add_vertex({x, y, -distance + height}, normalized({-dh_dx, -dh_dy, 1.0}));
            }
        // x right, y up, seen from +z: (i, j) -> (i + 1, j) -> (i + 1, j + 1) is counter-clockwise.
        auto at = [&](int i, int j) { return first + static_cast<uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                mesh.triangles.insert(mesh.triangles.end(), {{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                                                             {at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
    return mesh;
}

}  // namespace raster::tools
