// The cube faces, face choice, face cameras and clip planes of docs/shadows.md.
#include "oracle/reference/shadow_faces.h"

#include <algorithm>
#include <cmath>

namespace raster::oracle {

const ShadowFace& shadow_face(int face) {
    // docs/shadows.md: +x (up +y), -x (up +y), +y (up -z), -y (up +z), +z (up +y), -z (up +y); right = axis x up.
    static const ShadowFace faces[kShadowFaces] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}, {{0, 1, 0}, {0, 0, -1}, {-1, 0, 0}},
        {{0, -1, 0}, {0, 0, 1}, {-1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
    };
    return faces[face];
}

std::vector<int> possible_faces(const Interval3& d) {
    Interval size[3];
    for (int i = 0; i < 3; ++i) {
        const Interval& c = d[i];
        size[i] = c.lo >= 0.0 ? c : c.hi <= 0.0 ? -c : Interval(0.0, std::max(-c.lo, c.hi));
    }
    // raster: x if |x| >= |y| and |x| >= |z|; else y if |y| >= |z|; else z.
    const bool x_may = size[0].hi >= size[1].lo && size[0].hi >= size[2].lo;
    const bool x_may_not = size[0].lo < size[1].hi || size[0].lo < size[2].hi;
    const bool y_may = x_may_not && size[1].hi >= size[2].lo;
    const bool z_may = x_may_not && size[1].lo < size[2].hi;
    std::vector<int> faces;
    const bool axis_may[3] = {x_may, y_may, z_may};
    for (int i = 0; i < 3; ++i) {
        if (!axis_may[i]) continue;
        if (d[i].hi >= 0.0) faces.push_back(2 * i);
        if (d[i].lo < 0.0) faces.push_back(2 * i + 1);
    }
    return faces;
}

Camera shadow_face_camera(const glm::vec3& light, int face, const ShadowPlanes& planes) {
    const ShadowFace& f = shadow_face(face);
    Camera camera;
    camera.eye = light;
    camera.target = light + glm::vec3(f.axis);
    camera.up = glm::vec3(f.up);
    camera.fov_y_degrees = 90.0f;
    camera.near = planes.near;
    camera.far = planes.far;
    return camera;
}

ShadowPlanes shadow_planes(const std::vector<glm::dvec3>& world, const glm::vec3& light) {
    double farthest = 0.0;
    for (const glm::dvec3& p : world)
        for (int i = 0; i < 3; ++i) farthest = std::max(farthest, std::fabs(p[i] - double(light[i])));
    ShadowPlanes planes;
    planes.far = farthest > 0.0 ? static_cast<float>(std::min(2.0 * farthest, 0x1p126)) : 1.0f;
    planes.near = std::max(planes.far * 0x1p-16f, 0x1p-100f);
    return planes;
}

}  // namespace raster::oracle
