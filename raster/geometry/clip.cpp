// Clipping: Sutherland-Hodgman against six planes in homogeneous clip space, carrying original barycentrics.
#include "raster/geometry/clip.h"

#include <algorithm>
#include <cmath>

namespace raster {

extern const std::array<glm::vec3, 3> kCornerBarycentrics = {
    glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};

namespace {

enum Plane { kNear, kFar, kLeft, kRight, kBottom, kTop, kPlaneCount };

// Signed distance-like value: >= 0 inside. Exact plane equations, each scaled by a positive factor. In double,
// because the float sum of two coordinates near FLT_MAX overflows (the sign of the sum is the same either way).
inline double plane_distance(int plane, const glm::vec4& p, const ClipVolume& volume) {
    const double x = p.x, y = p.y, w = p.w;
    switch (plane) {
        case kNear:
            if (volume.orthographic) return w - double(p.z);  // z <= w
            return w - double(volume.near);
        case kFar:
            if (volume.orthographic) return double(p.z);  // z >= 0
            return double(volume.far) - w;
        case kLeft: return x + volume.side * w;
        case kRight: return volume.side * w - x;
        case kBottom: return y + volume.side * w;
        default: return volume.side * w - y;
    }
}

inline bool finite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// Bit mask of the planes a point is outside of.
inline unsigned outcode(const glm::vec4& p, const ClipVolume& volume) {
    unsigned code = 0;
    for (int plane = 0; plane < kPlaneCount; ++plane)
        if (plane_distance(plane, p, volume) < 0.0) code |= 1u << plane;
    return code;
}

// The point where the segment from `inside` to `outside` crosses the plane. In double and clamped to the segment:
// in float, outside - inside overflows for coordinates near FLT_MAX, and t * inf with t = 0 gives NaN.
inline ClipVertex intersect(const ClipVertex& inside, double d_in, const ClipVertex& outside, double d_out) {
    const double t = d_in / (d_in - d_out);  // in [0, 1): d_in >= 0 > d_out
    const auto between = [t](float from, float to) {
        const double value = double(from) + t * (double(to) - double(from));
        return static_cast<float>(std::clamp(value, double(std::min(from, to)), double(std::max(from, to))));
    };
    ClipVertex vertex;
    for (int i = 0; i < 4; ++i) vertex.position[i] = between(inside.position[i], outside.position[i]);
    for (int i = 0; i < 3; ++i) vertex.bary[i] = between(inside.bary[i], outside.bary[i]);
    return vertex;
}

}  // namespace

bool inside_clip_volume(const glm::vec4& p, const ClipVolume& volume) {
    return finite(p) && outcode(p, volume) == 0;
}

ClippedPolygon clip_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const ClipVolume& volume) {
    ClippedPolygon result;
    if (!finite(a) || !finite(b) || !finite(c)) return result;
    const unsigned ca = outcode(a, volume), cb = outcode(b, volume), cc = outcode(c, volume);
    if (ca & cb & cc) return result;  // all three outside one plane
    result.vertices[0] = {a, kCornerBarycentrics[0]};
    result.vertices[1] = {b, kCornerBarycentrics[1]};
    result.vertices[2] = {c, kCornerBarycentrics[2]};
    result.count = 3;
    const unsigned crossing = ca | cb | cc;
    if (crossing == 0) return result;  // entirely inside: untouched (the front end's shortcut, inside_clip_volume)
    result.clipped = true;

    std::array<ClipVertex, kMaxClippedVertices> scratch;
    auto* input = &result.vertices;
    auto* output = &scratch;
    int count = 3;
    for (int plane = 0; plane < kPlaneCount; ++plane) {
        if (!(crossing & (1u << plane))) continue;
        int written = 0;
        for (int i = 0; i < count; ++i) {
            const ClipVertex& current = (*input)[i];
            const ClipVertex& next = (*input)[(i + 1) % count];
            const double d_current = plane_distance(plane, current.position, volume);
            const double d_next = plane_distance(plane, next.position, volume);
            const bool current_in = d_current >= 0.0, next_in = d_next >= 0.0;
            if (written + 2 > kMaxClippedVertices) {  // only a numerically degenerate sliver gets here
                result.count = 0;
                return result;
            }
            if (current_in) (*output)[written++] = current;
            if (current_in != next_in) {
                (*output)[written++] = current_in ? intersect(current, d_current, next, d_next)
                                                  : intersect(next, d_next, current, d_current);
            }
        }
        count = written;
        std::swap(input, output);
        if (count < 3) {
            result.count = 0;
            return result;
        }
    }
    if (input != &result.vertices) result.vertices = *input;
    // Rounding in the intersection can leave w a hair below `near`; pin it so the divide stays safe. (An
    // orthographic w is 1, and every intersection of 1 and 1 is 1.)
    if (!volume.orthographic)
        for (int i = 0; i < count; ++i)
            if (result.vertices[i].position.w < volume.near) result.vertices[i].position.w = volume.near;
    result.count = count;
    return result;
}

}  // namespace raster
