// The cube shadow map's faces, written down once (docs/shadows.md): which face a direction from the light falls
// in, each face's axis, right and up, and where on the face the direction lands.
#pragma once

#include <cmath>

#include <glm/vec3.hpp>

namespace raster {

// Face 2 i + k looks along +e_i (k = 0) or -e_i (k = 1): +x, -x, +y, -y, +z, -z. A face is a camera at the light
// with a 90-degree field of view, looking along `axis` with `up`; its `right` is axis x up. A direction d from the
// light lands at face coordinates s = right.d / axis.d, t = up.d / axis.d in [-1, 1], i.e. at the point
// ((s + 1) / 2 N, (1 - t) / 2 N) of an N x N face image (x right, y down, as screen space), and its depth on the
// face is axis.d, the view depth the face's camera sees.
struct CubeFace {
    glm::vec3 axis, up, right;
};
inline constexpr int kCubeFaces = 6;
inline const CubeFace& cube_face(int face) {
    static const CubeFace faces[kCubeFaces] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},    {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}},
        {{0, 1, 0}, {0, 0, -1}, {-1, 0, 0}},  {{0, -1, 0}, {0, 0, 1}, {-1, 0, 0}},
        {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}},   {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
    };
    return faces[face];
}

// The face a direction from the light falls in: the axis of its largest |component| (x before y before z on a tie),
// on the side of its sign (+ for 0).
inline int cube_face_of(const glm::vec3& d) {
    const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    const int axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    return 2 * axis + (d[axis] < 0.0f ? 1 : 0);
}

}  // namespace raster
