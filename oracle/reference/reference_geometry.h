// The exact geometry the comparator measures against: every scene triangle in double precision, in view space and
// clipped as raster clips it, in screen pixels, with its radius and depth errors from the precision model.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "oracle/reference/scene_geometry.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// What made an edge of a clipped polygon: the triangle itself, a side plane (the image border), near or far.
enum class EdgeKind : uint8_t { triangle, side, near, far };

// One scene triangle after exact clipping (precision.h gives the meaning of each bound).
struct ReferencePolygon {
    uint32_t first = 0;             // its vertices and edge kinds start here
    uint32_t count = 0;             // 0 when nothing of it is inside the view volume
    bool culled = false;            // back-facing in a scene that culls back faces: no renderer may show it
    bool facing_uncertain = false;  // culling on, and its facing is within the float error (precision.h, 7)
    double radius = 0;              // r: snap + float screen error of its vertices, px, max norm
    double depth_error = 0;         // largest absolute view depth error of its clipped vertices (clip boundary):
                                    // their w error, or, orthographic, their z error times far - near
    double relative_depth_error = 0;  // largest relative 1/w error of its clipped vertices
    double reversed_z_error = 0;    // largest reversed-Z error of its clipped vertices, float roundings included
};

// Where the ray through a screen point meets a triangle's plane (in front of the eye), in exact arithmetic.
struct ExactHit {
    bool valid = false;   // false when the ray is parallel to the plane or meets it behind the eye
    double view_depth = 0;
    double reversed_z = 0;  // d = z/w as raster's projection defines it
    glm::dvec3 bary{0.0};   // perspective-correct, w.r.t. the original vertices (may be negative outside)
};

// The extremes of a triangle's exact values over the max-norm square of half-side h around a screen point.
// Each is linear-fractional in the screen point with one denominator, so when that denominator keeps its sign over
// the square (`bounded`) the extremes are at the corners; otherwise the ray grazes the plane somewhere in the
// square and every value is unbounded.
struct SquareRange {
    bool bounded = false;
    double min_view_depth = 0, max_view_depth = 0;
    double min_reversed_z = 0, max_reversed_z = 0;
    glm::dvec3 min_bary{0.0}, max_bary{0.0};
};

// What a view clips to and snaps at: its near and far planes, the sub-pixel bits, whether back faces are culled,
// and its side planes |x|, |y| <= side w. A shadow map's face takes side > 1: its polygons reach a little past its
// border, so that the side clips' edges lie beyond every texel centre, and the scene's own vertices, which often
// sit exactly on a face's corner directions (where the side clips' error bound has no finite value), lie strictly
// inside.
struct ViewVolume {
    double near = 0.1, far = 100.0;
    int snap_bits = 8;
    bool cull_backfaces = false;
    double side = 1.0;
    bool orthographic = false;  // w = 1, near and far on z (docs/conventions.md "Clipping")
};

class ReferenceGeometry {
public:
    // `geometry` is the oracle's view of `scene` (oracle_scene), clipped and snapped as the scene's settings say.
    ReferenceGeometry(const Scene& scene, const OracleScene& geometry);
    // The same for another view of the scene's triangles (oracle_view: a shadow map's face) and its volume.
    ReferenceGeometry(const Scene& scene, const OracleScene& geometry, const ViewVolume& volume);

    size_t size() const { return polygons_.size(); }
    const ReferencePolygon& polygon(uint32_t id) const { return polygons_[id]; }
    std::span<const glm::dvec2> screen_vertices(uint32_t id) const;
    EdgeKind edge_kind(uint32_t id, uint32_t edge) const { return edge_kinds_[polygons_[id].first + edge]; }
    double near() const { return near_; }
    double far() const { return far_; }
    bool orthographic() const { return camera_.orthographic; }

    ExactHit hit(uint32_t id, const glm::dvec2& screen) const;
    SquareRange range_around(uint32_t id, const glm::dvec2& screen, double half_side) const;
    // How far Embree's barycentrics for the ray through `screen` can be from exact (precision.h, section 5).
    glm::dvec3 embree_barycentric_error(uint32_t id, const glm::dvec2& screen) const;
    // How far Embree's view depth for the ray through `screen` can be from exact (precision.h, section 5); infinite
    // where the ray misses the triangle's plane in front of the eye.
    double embree_view_depth_error(uint32_t id, const glm::dvec2& screen) const;
    // The same in reversed-Z units (d = z/w = -P22 + P32 / t), for the oracle's choice between two surfaces.
    double embree_reversed_z_error(uint32_t id, const glm::dvec2& screen) const;
    // Whether Embree's edge-by-edge test may report a hit on the triangle for the ray through `screen`
    // (precision.h, section 5, "Embree's coverage").
    bool embree_may_cover(uint32_t id, const glm::dvec2& screen) const;
    // Whether it may report no hit there though the exact triangle covers the sample (same section).
    bool embree_may_miss(uint32_t id, const glm::dvec2& screen) const;

    // Max-norm distance from `screen` to the polygon's boundary (every edge, whatever made it); infinite when the
    // polygon is empty.
    double boundary_distance(uint32_t id, const glm::dvec2& screen) const;
    // True when the ray through `screen` meets the exact triangle inside the view volume: a valid hit with every
    // barycentric >= 0 and near <= t <= far (samples are always inside the side planes). Decided from the hit,
    // not from the clipped polygon, whose near-duplicate vertices (an edge clipped through a viewport corner) give
    // edges whose direction is rounding noise.
    bool contains(uint32_t id, const glm::dvec2& screen) const;

private:
    struct ViewTriangle {
        glm::dvec3 a, edge1, edge2;  // vertex 0 and the edges to vertices 1 and 2, view space
        glm::dvec3 oracle_error[3];  // how far the oracle's float view-space vertices can be from these
        double plane_noise = 0;      // per unit of ray direction: a smaller determinant has no exact hit
    };
    // What Embree's evaluation bounds need for one triangle and one sample's ray.
    struct EmbreeRay {
        glm::dvec3 vertices[3];            // view space relative to the ray's origin, exact
        glm::dvec3 direction;              // the camera ray through the sample (z = -1)
        glm::dvec3 vertex_error[3];        // how far Embree's float vertices relative to the origin can be off
    };
    EmbreeRay embree_ray(uint32_t id, const glm::dvec2& screen) const;
    // embree_view_depth_error with the exact hit at `screen` already found.
    double embree_view_depth_error(uint32_t id, const glm::dvec2& screen, const ExactHit& exact) const;

    OracleCamera camera_;
    double near_ = 0, far_ = 0;
    std::vector<ViewTriangle> triangles_;
    std::vector<ReferencePolygon> polygons_;
    std::vector<glm::dvec2> screen_;
    std::vector<EdgeKind> edge_kinds_;
};

// An original vertex of a triangle in clip space: the oracle's exact position, its magnitudes |P||V||M||(p, 1)|, and
// how far raster's float clip position can be from it (precision.h section 2 and camera_precision.h).
struct ClipBound {
    glm::dvec4 clip{0.0}, magnitudes{0.0}, error{0.0};
};
ClipBound original_clip_vertex(const Scene& scene, const OracleScene& geometry, uint32_t triangle, int corner);

// Max-norm distance from point p to the segment [a, b]: min over t in [0, 1] of max(|dx(t)|, |dy(t)|). That is a
// convex piecewise-linear function of t, so its minimum is at an end or where one term is 0 or the two are equal.
double max_norm_distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

}  // namespace raster::oracle
