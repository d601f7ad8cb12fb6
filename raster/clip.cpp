// Clipping: Sutherland-Hodgman against six planes in homogeneous clip space, carrying original barycentrics.
#include "raster/clip.h"

#include <cmath>

namespace raster {
namespace {

enum Plane { kNear, kFar, kLeft, kRight, kBottom, kTop, kPlaneCount };

// Signed distance-like value: >= 0 inside. Exact plane equations, each scaled by a positive factor.
inline float plane_distance(int plane, const glm::vec4& p, const ClipVolume& volume) {
    switch (plane) {
        case kNear: return p.w - volume.near;
        case kFar: return volume.far - p.w;
        case kLeft: return p.x + p.w;
        case kRight: return p.w - p.x;
        case kBottom: return p.y + p.w;
        default: return p.w - p.y;
    }
}

inline bool finite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// Bit mask of the planes a point is outside of.
inline unsigned outcode(const glm::vec4& p, const ClipVolume& volume) {
    unsigned code = 0;
    for (int plane = 0; plane < kPlaneCount; ++plane)
        if (plane_distance(plane, p, volume) < 0.0f) code |= 1u << plane;
    return code;
}

// The point where the segment from `inside` to `outside` crosses the plane.
inline ClipVertex intersect(const ClipVertex& inside, float d_in, const ClipVertex& outside, float d_out) {
    const float t = d_in / (d_in - d_out);
    return {inside.position + t * (outside.position - inside.position), inside.bary + t * (outside.bary - inside.bary)};
}

}  // namespace

ClippedPolygon clip_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const ClipVolume& volume) {
    ClippedPolygon result;
    if (!finite(a) || !finite(b) || !finite(c)) return result;
    const unsigned ca = outcode(a, volume), cb = outcode(b, volume), cc = outcode(c, volume);
    if (ca & cb & cc) return result;  // all three outside one plane
    result.vertices[0] = {a, {1.0f, 0.0f, 0.0f}};
    result.vertices[1] = {b, {0.0f, 1.0f, 0.0f}};
    result.vertices[2] = {c, {0.0f, 0.0f, 1.0f}};
    result.count = 3;
    const unsigned crossing = ca | cb | cc;
    if (crossing == 0) return result;  // entirely inside: untouched
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
            const float d_current = plane_distance(plane, current.position, volume);
            const float d_next = plane_distance(plane, next.position, volume);
            const bool current_in = d_current >= 0.0f, next_in = d_next >= 0.0f;
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
    // Rounding in the intersection can leave w a hair below `near`; pin it so the divide stays safe.
    for (int i = 0; i < count; ++i)
        if (result.vertices[i].position.w < volume.near) result.vertices[i].position.w = volume.near;
    result.count = count;
    return result;
}

}  // namespace raster
