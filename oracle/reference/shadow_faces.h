// The shadow maps' conventions as docs/shadows.md writes them, transcribed for the oracle from the document, not
// from raster's code: the cube's faces, the face a direction falls in, each face's camera and the light's clip
// planes.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// Face 2 i + k looks along +e_i (k = 0) or -e_i (k = 1); right = axis x up.
struct ShadowFace {
    glm::dvec3 axis, up, right;
};
inline constexpr int kShadowFaces = 6;
const ShadowFace& shadow_face(int face);

// The faces raster may pick for a direction d from the light, for every d in the box: the axis of the largest
// |component| (x before y before z on a tie), on the side of its sign (+ for 0).
std::vector<int> possible_faces(const Interval3& direction);

// A face's camera, as raster builds it (float): at the light, looking at light + axis (a float sum) with the
// face's up, a 90-degree field of view and the light's clip planes.
struct ShadowPlanes {
    float near = 0.0f, far = 0.0f;
};
Camera shadow_face_camera(const glm::vec3& light, int face, const ShadowPlanes& planes);

// The light's clip planes: far = 2 max over the scene's vertices of |world - light| (max norm), in float and at
// most 2^126, 1 when every vertex is at the light; near = far / 2^16, at least 2^-100.
ShadowPlanes shadow_planes(const std::vector<glm::dvec3>& world, const glm::vec3& light);

}  // namespace raster::oracle
