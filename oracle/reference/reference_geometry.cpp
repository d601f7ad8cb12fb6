// Exact clipping and projection of every triangle in double, with the precision model's bounds per polygon.
#include "oracle/reference/reference_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "oracle/reference/camera_precision.h"
#include "oracle/reference/matrix_magnitude.h"
#include "oracle/reference/precision.h"

namespace raster::oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A polygon vertex during exact clipping: its clip position, the magnitudes its float version was computed
// from, its float error bound, and what made the edge from it to the next vertex.
struct ClipVertex {
    glm::dvec4 clip;
    glm::dvec4 magnitudes;
    glm::dvec4 error;
    EdgeKind outgoing;
};

enum Plane { kNear, kFar, kLeft, kRight, kBottom, kTop, kPlaneCount };

// The clip planes of the documented conventions (docs/conventions.md) (w >= near, w <= far, |x|, |y| <= side w;
// orthographic: z <= w, z >= 0), >= 0 inside.
struct Planes {
    double near, far, side;
    bool orthographic;
};
double plane_distance(int plane, const glm::dvec4& p, const Planes& planes) {
    const double side = planes.side;
    switch (plane) {
        case kNear: return planes.orthographic ? p.w - p.z : p.w - planes.near;
        case kFar: return planes.orthographic ? p.z : planes.far - p.w;
        case kLeft: return p.x + side * p.w;
        case kRight: return side * p.w - p.x;
        case kBottom: return p.y + side * p.w;
        default: return side * p.w - p.y;
    }
}

// How far a vertex's distance to the plane can move with its error bound e: |n|.e.
double plane_distance_error(int plane, const glm::dvec4& e, const Planes& planes) {
    const double side = planes.side;
    switch (plane) {
        case kNear: return planes.orthographic ? e.w + e.z : e.w;
        case kFar: return planes.orthographic ? e.z : e.w;
        case kLeft:
        case kRight: return e.x + side * e.w;
        default: return e.y + side * e.w;
    }
}

EdgeKind plane_edge_kind(int plane) {
    return plane == kNear ? EdgeKind::near : plane == kFar ? EdgeKind::far : EdgeKind::side;
}

// Sutherland-Hodgman in double, keeping track of which plane made each edge.
std::vector<ClipVertex> clip_exactly(std::vector<ClipVertex> polygon, const Planes& planes) {
    for (int plane = 0; plane < kPlaneCount && polygon.size() >= 3; ++plane) {
        std::vector<ClipVertex> out;
        const size_t n = polygon.size();
        for (size_t i = 0; i < n; ++i) {
            const ClipVertex& current = polygon[i];
            const ClipVertex& next = polygon[(i + 1) % n];
            const double d_current = plane_distance(plane, current.clip, planes);
            const double d_next = plane_distance(plane, next.clip, planes);
            const bool current_in = d_current >= 0.0, next_in = d_next >= 0.0;
            if (current_in) out.push_back(current);
            if (current_in == next_in) continue;
            // Always from the inside vertex towards the outside one, as raster does.
            const ClipVertex& in = current_in ? current : next;
            const ClipVertex& outside = current_in ? next : current;
            const double d_in = current_in ? d_current : d_next, d_out = current_in ? d_next : d_current;
            const double t = d_in / (d_in - d_out);
            ClipVertex cut;
            cut.clip = in.clip + t * (outside.clip - in.clip);
            cut.magnitudes = glm::max(in.magnitudes, outside.magnitudes);
            cut.error = clip_step_error(
                {in.clip, in.error, in.magnitudes, d_in, plane_distance_error(plane, in.error, planes)},
                {outside.clip, outside.error, outside.magnitudes, d_out, plane_distance_error(plane, outside.error, planes)});
            // Leaving the half-space, the next edge runs along the plane; entering it, along the original edge.
            cut.outgoing = current_in ? plane_edge_kind(plane) : current.outgoing;
            out.push_back(cut);
        }
        polygon = std::move(out);
    }
    if (polygon.size() < 3) polygon.clear();
    return polygon;
}

// Whether some point of the triangle may be kept by a renderer while lying within the float error of the eye,
// where a screen position is unbounded (precision.h, section 6, "the eye"): the triangle (x, y, w), clipped to
// the box |x| <= w + E_x + E_w, |y| <= w + E_y + E_w, near - E_w <= w <= E_w with E its vertices' largest
// errors, keeps a point. Sutherland-Hodgman keeps degenerate (collinear) input exact, which matters here: a
// triangle seen exactly edge-on through the eye is the case that needs this.
bool passes_by_the_eye(const std::vector<ClipVertex>& triangle, double near) {
    glm::dvec4 e(0.0);
    for (const ClipVertex& v : triangle) e = glm::max(e, v.error);
    if (!(near <= 2.0 * e.w)) return false;  // the band of w is empty: the near plane cuts the eye's surroundings
    const std::array<glm::dvec4, 6> half_spaces = {
        // (a, b, c, d): a x + b y + c w + d >= 0
        glm::dvec4(0, 0, -1, e.w),          glm::dvec4(0, 0, 1, e.w - near),
        glm::dvec4(-1, 0, 1, e.x + e.w),    glm::dvec4(1, 0, 1, e.x + e.w),
        glm::dvec4(0, -1, 1, e.y + e.w),    glm::dvec4(0, 1, 1, e.y + e.w)};
    std::vector<glm::dvec3> polygon;
    for (const ClipVertex& v : triangle) polygon.emplace_back(v.clip.x, v.clip.y, v.clip.w);
    for (const glm::dvec4& h : half_spaces) {
        std::vector<glm::dvec3> out;
        const size_t n = polygon.size();
        for (size_t i = 0; i < n; ++i) {
            const glm::dvec3 &a = polygon[i], &b = polygon[(i + 1) % n];
            const double da = glm::dot(glm::dvec3(h), a) + h.w, db = glm::dot(glm::dvec3(h), b) + h.w;
            if (da >= 0.0) out.push_back(a);
            if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
        }
        polygon = std::move(out);
        if (polygon.empty()) return false;
    }
    return true;
}

}  // namespace

ClipBound original_clip_vertex(const Scene& scene, const OracleScene& geometry, uint32_t id, int corner) {
    const OracleTriangle& triangle = geometry.triangles[id];
    const uint32_t vertex = triangle.vertex[corner];
    const glm::dmat4& projection = geometry.camera.projection;
    const ModelMatrixError& model = geometry.models[triangle.mesh];
    const glm::dmat4 magnitude_chain =
        absolute(projection) * absolute(geometry.camera.view) * raster_model_magnitude(model);
    const glm::vec3& position = scene.meshes[triangle.mesh].data->positions[vertex - geometry.mesh_first_vertex[triangle.mesh]];
    ClipBound bound;
    bound.clip = projection * glm::dvec4(geometry.view[vertex], 1.0);
    bound.magnitudes = magnitude_chain * glm::abs(glm::dvec4(glm::dvec3(position), 1.0));
    bound.error = vertex_error(bound.magnitudes) +
                  camera_clip_error(geometry.camera_error, geometry.camera, geometry.world[vertex]) +
                  model_clip_error(model, geometry.camera_error, geometry.camera, position);
    return bound;
}

double max_norm_distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 d = b - a, o = a - p;  // the offset from p at t is o + t d
    auto at = [&](double t) {
        t = std::clamp(t, 0.0, 1.0);
        return std::max(std::fabs(o.x + t * d.x), std::fabs(o.y + t * d.y));
    };
    double best = std::min(at(0.0), at(1.0));
    if (d.x != 0.0) best = std::min(best, at(-o.x / d.x));
    if (d.y != 0.0) best = std::min(best, at(-o.y / d.y));
    if (d.x != d.y) best = std::min(best, at((o.y - o.x) / (d.x - d.y)));    // o.x + t d.x == o.y + t d.y
    if (d.x != -d.y) best = std::min(best, at(-(o.x + o.y) / (d.x + d.y)));  // o.x + t d.x == -(o.y + t d.y)
    return best;
}

ReferenceGeometry::ReferenceGeometry(const Scene& scene, const OracleScene& geometry)
    : ReferenceGeometry(scene, geometry,
                        ViewVolume{scene.camera.near, scene.camera.far, scene.settings.snap_bits,
                                   scene.settings.cull_backfaces, 1.0,
                                   scene.camera.projection == Projection::orthographic}) {}

ReferenceGeometry::ReferenceGeometry(const Scene& scene, const OracleScene& geometry, const ViewVolume& volume)
    : camera_(geometry.camera), near_(volume.near), far_(volume.far) {
    const glm::dmat4 view_magnitude = absolute(camera_.view);
    const size_t triangle_count = geometry.triangles.size();
    triangles_.resize(triangle_count);
    polygons_.resize(triangle_count);
    screen_.reserve(triangle_count * 3);
    edge_kinds_.reserve(triangle_count * 3);
    const double snap = snap_displacement(volume.snap_bits);

    for (uint32_t id = 0; id < triangle_count; ++id) {
        const OracleTriangle& triangle = geometry.triangles[id];
        const glm::dmat4 view_magnitude_chain = view_magnitude * absolute(geometry.models[triangle.mesh].exact);
        const auto& positions = scene.meshes[triangle.mesh].data->positions;
        const uint32_t first_vertex = geometry.mesh_first_vertex[triangle.mesh];
        std::vector<ClipVertex> polygon(3);
        glm::dvec3 view_vertex[3], oracle_error[3];
        double vertex_magnitude = 0.0;  // the largest |V||M||p| (2-norm), for the plane noise
        for (int k = 0; k < 3; ++k) {
            const uint32_t vertex = triangle.vertex[k];
            const glm::dvec4 p{glm::dvec3(positions[vertex - first_vertex]), 1.0};
            view_vertex[k] = geometry.view[vertex];
            const glm::dvec3 view_magnitude_k = glm::dvec3(view_magnitude_chain * glm::abs(p));
            vertex_magnitude = std::max(vertex_magnitude, glm::length(view_magnitude_k));
            oracle_error[k] = float_gamma(kOracleTransformRoundings) * view_magnitude_k;
            const ClipBound bound = original_clip_vertex(scene, geometry, id, k);
            polygon[k].clip = bound.clip;
            polygon[k].magnitudes = bound.magnitudes;
            polygon[k].error = bound.error;
            polygon[k].outgoing = EdgeKind::triangle;
        }
        const glm::dvec3 edge1 = view_vertex[1] - view_vertex[0], edge2 = view_vertex[2] - view_vertex[0];
        triangles_[id] = {view_vertex[0], edge1, edge2, {oracle_error[0], oracle_error[1], oracle_error[2]},
                          plane_noise(edge1, edge2, vertex_magnitude)};
        ReferencePolygon& out = polygons_[id];
        out.culled = volume.cull_backfaces && !faces_viewer(camera_, view_vertex[0], view_vertex[1], view_vertex[2]);
        if (volume.cull_backfaces) {
            const glm::dvec4 clip[3] = {polygon[0].clip, polygon[1].clip, polygon[2].clip};
            const glm::dvec4 error[3] = {polygon[0].error, polygon[1].error, polygon[2].error};
            out.facing_uncertain = facing_is_uncertain(clip, error);
        }
        out.first = static_cast<uint32_t>(screen_.size());
        const std::vector<ClipVertex> original = polygon;
        // An orthographic w is 1: no point comes near the eye's singularity.
        const bool unbounded = !volume.orthographic && passes_by_the_eye(original, near_);
        const Planes planes{near_, far_, volume.side, volume.orthographic};
        const std::vector<ClipVertex> clipped = clip_exactly(std::move(polygon), planes);
        out.count = static_cast<uint32_t>(clipped.size());
        out.radius = snap;
        for (const ClipVertex& v : clipped) {
            screen_.push_back(screen_of_ndc(camera_, {v.clip.x / v.clip.w, v.clip.y / v.clip.w}));
            edge_kinds_.push_back(v.outgoing);
        }
        // The bounds come from the clipped vertices; a triangle with nothing inside the view volume still gets
        // them from its original vertices that float error may put in front of the near plane, for samples
        // where a float clip kept a sliver. A vertex within its w error of the eye has no bounded screen
        // position at all (screen_error is infinite), and then neither has anything about the triangle.
        for (const ClipVertex& v : clipped.empty() ? original : clipped) {
            if (clipped.empty() && !(plane_distance(kNear, v.clip, planes) + plane_distance_error(kNear, v.error, planes) >= 0.0))
                continue;
            const glm::dvec2 error = screen_error(v.clip, v.error, camera_.width, camera_.height);
            out.radius = std::max(out.radius, snap + std::max(error.x, error.y));
            // Orthographic: raster reads t = far - z (far - near) from its float z, in double, and rounds it (1).
            const double depth_error =
                volume.orthographic ? (v.error.z + v.error.w) * (far_ - near_) + float_gamma(1) * std::max(std::fabs(far_), std::fabs(near_))
                                    : v.error.w;
            out.depth_error = std::max(out.depth_error, depth_error);
            out.relative_depth_error = std::max(out.relative_depth_error, relative_depth_error(v.clip.w, v.error.w));
            out.reversed_z_error = std::max(out.reversed_z_error, reversed_z_error(v.clip, v.error));
        }
        if (unbounded) out.radius = kInfinity;
    }
}

std::span<const glm::dvec2> ReferenceGeometry::screen_vertices(uint32_t id) const {
    const ReferencePolygon& p = polygons_[id];
    return {screen_.data() + p.first, p.count};
}

ExactHit ReferenceGeometry::hit(uint32_t id, const glm::dvec2& screen) const {
    // Moeller-Trumbore from the ray's origin (the eye; orthographic, the plane z = 0); the direction has z = -1,
    // so t is the view depth.
    const ViewTriangle& tri = triangles_[id];
    const glm::dvec3 direction = ray_direction(camera_, screen);
    const glm::dvec3 p = glm::cross(direction, tri.edge2);
    const double determinant = glm::dot(tri.edge1, p);
    ExactHit hit;
    // Within the plane noise (precision.h) the double geometry cannot place the hit: none (NaN and inf included).
    if (!(std::fabs(determinant) > tri.plane_noise * glm::length(direction)) || !std::isfinite(determinant))
        return hit;
    const glm::dvec3 to_origin = ray_origin(camera_, screen) - tri.a;
    const glm::dvec3 q = glm::cross(to_origin, tri.edge1);
    const double u = glm::dot(to_origin, p) / determinant;
    const double v = glm::dot(direction, q) / determinant;
    const double t = glm::dot(tri.edge2, q) / determinant;
    // A perspective ray starts at the eye; an orthographic one is a whole line, cut by near and far alone.
    if (!(camera_.orthographic ? std::isfinite(t) : t > 0.0)) return hit;
    hit.valid = true;
    hit.view_depth = t;
    hit.reversed_z = reversed_z(camera_, t);
    hit.bary = {1.0 - u - v, u, v};
    return hit;
}

ReferenceGeometry::EmbreeRay ReferenceGeometry::embree_ray(uint32_t id, const glm::dvec2& screen) const {
    const ViewTriangle& tri = triangles_[id];
    EmbreeRay ray{{tri.a, tri.a + tri.edge1, tri.a + tri.edge2}, ray_direction(camera_, screen), {}};
    for (int k = 0; k < 3; ++k) ray.vertex_error[k] = tri.oracle_error[k];
    if (!camera_.orthographic) return ray;  // the origin is 0: Embree's v - origin is exact
    // Embree takes the origin o rounded to float (off by u |o|) and forms v - o in float (one rounding of a value
    // within |v - o| + e + u |o|): precision.h's bounds, written for an origin at 0, hold for the vertices relative
    // to o with these errors.
    const glm::dvec3 origin = ray_origin(camera_, screen);
    const double u = float_gamma(1);
    for (int k = 0; k < 3; ++k) {
        ray.vertices[k] -= origin;
        const glm::dvec3 moved = tri.oracle_error[k] + u * glm::abs(origin);
        ray.vertex_error[k] = moved + u * (glm::abs(ray.vertices[k]) + moved);
    }
    return ray;
}

glm::dvec3 ReferenceGeometry::embree_barycentric_error(uint32_t id, const glm::dvec2& screen) const {
    const ExactHit exact = hit(id, screen);
    if (!exact.valid) return glm::dvec3(std::numeric_limits<double>::infinity());
    const EmbreeRay ray = embree_ray(id, screen);
    return oracle::embree_barycentric_error(ray.vertices, ray.direction, exact.bary);
}

double ReferenceGeometry::embree_view_depth_error(uint32_t id, const glm::dvec2& screen) const {
    return embree_view_depth_error(id, screen, hit(id, screen));
}

double ReferenceGeometry::embree_view_depth_error(uint32_t id, const glm::dvec2& screen, const ExactHit& exact) const {
    if (!exact.valid) return std::numeric_limits<double>::infinity();
    const EmbreeRay ray = embree_ray(id, screen);
    return oracle::embree_view_depth_error(ray.vertices, ray.vertex_error, ray.direction, exact.view_depth);
}

double ReferenceGeometry::embree_reversed_z_error(uint32_t id, const glm::dvec2& screen) const {
    const ExactHit exact = hit(id, screen);
    const double error = embree_view_depth_error(id, screen, exact);  // infinite without a valid hit
    return reversed_z_error_of_view_depth(camera_, exact.view_depth, error);
}

bool ReferenceGeometry::embree_may_cover(uint32_t id, const glm::dvec2& screen) const {
    const EmbreeRay ray = embree_ray(id, screen);
    return oracle::embree_may_cover(ray.vertices, ray.vertex_error, ray.direction);
}

bool ReferenceGeometry::embree_may_miss(uint32_t id, const glm::dvec2& screen) const {
    const EmbreeRay ray = embree_ray(id, screen);
    return oracle::embree_may_miss(ray.vertices, ray.vertex_error, ray.direction);
}

SquareRange ReferenceGeometry::range_around(uint32_t id, const glm::dvec2& screen, double half_side) const {
    SquareRange range;
    if (!std::isfinite(half_side)) return range;
    ExactHit corner[4];
    for (int k = 0; k < 4; ++k) {
        const glm::dvec2 c = screen + glm::dvec2(k & 1 ? half_side : -half_side, k & 2 ? half_side : -half_side);
        corner[k] = hit(id, c);
        if (!corner[k].valid) return range;  // behind the eye or parallel somewhere: unbounded
    }
    // All four in front: t = const / determinant with determinant affine in the screen point, so t > 0 at the four
    // corners means the determinant keeps its sign over the square.
    range.bounded = true;
    range.min_view_depth = range.max_view_depth = corner[0].view_depth;
    range.min_reversed_z = range.max_reversed_z = corner[0].reversed_z;
    range.min_bary = range.max_bary = corner[0].bary;
    for (int k = 1; k < 4; ++k) {
        range.min_view_depth = std::min(range.min_view_depth, corner[k].view_depth);
        range.max_view_depth = std::max(range.max_view_depth, corner[k].view_depth);
        range.min_reversed_z = std::min(range.min_reversed_z, corner[k].reversed_z);
        range.max_reversed_z = std::max(range.max_reversed_z, corner[k].reversed_z);
        range.min_bary = glm::min(range.min_bary, corner[k].bary);
        range.max_bary = glm::max(range.max_bary, corner[k].bary);
    }
    return range;
}

double ReferenceGeometry::boundary_distance(uint32_t id, const glm::dvec2& screen) const {
    const std::span<const glm::dvec2> v = screen_vertices(id);
    double best = kInfinity;
    for (size_t i = 0; i < v.size(); ++i)
        best = std::min(best, max_norm_distance_to_segment(screen, v[i], v[(i + 1) % v.size()]));
    return best;
}

bool ReferenceGeometry::contains(uint32_t id, const glm::dvec2& screen) const {
    if (polygons_[id].count == 0) return false;
    const ExactHit exact = hit(id, screen);
    return exact.valid && exact.bary.x >= 0.0 && exact.bary.y >= 0.0 && exact.bary.z >= 0.0 && near_ <= exact.view_depth &&
           exact.view_depth <= far_;
}

}  // namespace raster::oracle
