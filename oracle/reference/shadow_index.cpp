// The shadow index: per cube face, the occluders' exact polygons in face pixels, binned in a grid, and the map's
// possible answers over a footprint.
#include "oracle/reference/shadow_index.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "oracle/reference/precision.h"
#include "raster/core/conventions.h"

namespace raster::oracle {
namespace {

constexpr int kGrid = 64;  // cells per face side
constexpr double kSideTolerance = 1e-12;  // relative: a determinant this small calls the sides equal

uint64_t position_key(const glm::vec3& p) {
    uint32_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    return (uint64_t(bits[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(bits[1]) * 0xC2B2AE3D27D4EB4Full) ^
           (uint64_t(bits[2]) + 0x165667B19E3779F9ull);
}

// Per vertex: the first vertex of its mesh at the same float position (raster's map draws them at one point).
std::vector<uint32_t> welded_vertices(const Scene& scene, const OracleScene& geometry) {
    std::vector<uint32_t> canonical(geometry.world.size());
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const auto& positions = scene.meshes[m].data->positions;
        const uint32_t first = geometry.mesh_first_vertex[m];
        std::unordered_multimap<uint64_t, uint32_t> seen;
        for (uint32_t i = 0; i < positions.size(); ++i) {
            canonical[first + i] = first + i;
            const uint64_t key = position_key(positions[i]);
            auto [begin, end] = seen.equal_range(key);
            for (auto it = begin; it != end; ++it)
                if (positions[it->second - first] == positions[i]) {
                    canonical[first + i] = it->second;
                    break;
                }
            if (canonical[first + i] == first + i) seen.emplace(key, first + i);
        }
    }
    return canonical;
}

// The sign of det(p - l, q - l, r - l), 0 when within rounding of 0.
int side_of(const glm::dvec3& l, const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
    const glm::dvec3 a = p - l, b = q - l, c = r - l;
    const double det = glm::dot(glm::cross(a, b), c);
    const double scale = glm::length(a) * glm::length(b) * glm::length(c);
    if (!(std::fabs(det) > kSideTolerance * scale)) return 0;
    return det > 0.0 ? 1 : -1;
}


TexelRect expanded(const TexelRect& r, double by) { return {r.x0 - by, r.x1 + by, r.y0 - by, r.y1 + by}; }

// Whether the segment [a, b] meets the rectangle (Liang-Barsky).
bool segment_meets(const TexelRect& r, const glm::dvec2& a, const glm::dvec2& b) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - r.x0, r.x1 - a.x, a.y - r.y0, r.y1 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

// Whether a convex polygon meets the rectangle (separating axes: the rectangle's and the polygon's edges). An edge
// too short to have a direction is no axis, and a polygon without area is its edges: both err towards meeting.
bool polygon_meets(const std::span<const glm::dvec2>& v, const TexelRect& r) {
    double min_x = v[0].x, max_x = v[0].x, min_y = v[0].y, max_y = v[0].y, area = 0.0, scale = 0.0;
    for (size_t i = 0; i < v.size(); ++i) {
        const glm::dvec2 &a = v[i], &b = v[(i + 1) % v.size()];
        min_x = std::min(min_x, a.x), max_x = std::max(max_x, a.x);
        min_y = std::min(min_y, a.y), max_y = std::max(max_y, a.y);
        area += a.x * b.y - a.y * b.x;
        scale = std::max({scale, std::fabs(a.x), std::fabs(a.y)});
    }
    if (max_x < r.x0 || min_x > r.x1 || max_y < r.y0 || min_y > r.y1) return false;
    if (!(std::fabs(area) > 1e-12 * scale * scale)) {
        for (size_t i = 0; i < v.size(); ++i)
            if (segment_meets(r, v[i], v[(i + 1) % v.size()])) return true;
        return false;
    }
    const double orientation = area > 0.0 ? 1.0 : -1.0;
    const glm::dvec2 corners[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x0, r.y1}, {r.x1, r.y1}};
    for (size_t i = 0; i < v.size(); ++i) {
        const glm::dvec2 &a = v[i], edge = v[(i + 1) % v.size()] - a;
        if (!(glm::length(edge) > 1e-12 * scale)) continue;
        bool all_outside = true;
        for (const glm::dvec2& c : corners)
            all_outside = all_outside && orientation * (edge.x * (c.y - a.y) - edge.y * (c.x - a.x)) < 0.0;
        if (all_outside) return false;
    }
    return true;
}

}  // namespace

std::vector<uint8_t> boundary_edges(const Scene& scene, const OracleScene& geometry, const glm::dvec3& light,
                                    const std::vector<uint8_t>& casts) {
    const std::vector<uint32_t> canonical = welded_vertices(scene, geometry);
    std::vector<uint8_t> boundary(geometry.triangles.size(), 0x7);
    struct Use {
        uint32_t triangle;
        int edge;
    };
    std::unordered_map<uint64_t, std::vector<Use>> uses;
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
        if (!casts[id]) continue;  // a surface that casts no shadow leaves its neighbours' edges open
        const auto& v = geometry.triangles[id].vertex;
        const uint32_t c[3] = {canonical[v[0]], canonical[v[1]], canonical[v[2]]};
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;  // degenerate: every edge a boundary
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = c[k], b = c[(k + 1) % 3];
            uses[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)].push_back({id, k});
        }
    }
    for (const auto& [key, list] : uses) {
        if (list.size() != 2) continue;
        const auto& t = geometry.triangles[list[0].triangle].vertex;
        const auto& n = geometry.triangles[list[1].triangle].vertex;
        const int k = list[0].edge, m = list[1].edge;
        const glm::dvec3 &p = geometry.world[t[k]], &q = geometry.world[t[(k + 1) % 3]];
        const int mine = side_of(light, p, q, geometry.world[t[(k + 2) % 3]]);
        const int theirs = side_of(light, p, q, geometry.world[n[(m + 2) % 3]]);
        if (mine * theirs >= 0) continue;  // a silhouette (folded over the edge seen from the light), or edge-on
        boundary[list[0].triangle] &= static_cast<uint8_t>(~(1u << k));
        boundary[list[1].triangle] &= static_cast<uint8_t>(~(1u << m));
    }
    return boundary;
}

struct ShadowIndex::Face {
    OracleScene view;
    std::unique_ptr<ReferenceGeometry> reference;
    std::vector<uint16_t> boundary;  // per triangle: bit e when the polygon's edge e can bound the occluders
    double cell = 1.0;               // face pixels per grid cell
    std::vector<std::vector<uint32_t>> cells;
    std::vector<uint32_t> everywhere;  // triangles with no bounded screen position: in every query
};

namespace {

// The polygon edges of triangle `id` on a face that can bound the occluders: its own boundary edges, found by the
// homogeneous line of each original edge, and every edge a clip plane made.
uint16_t polygon_boundary(const ReferenceGeometry& reference, const OracleScene& view, uint32_t id,
                          uint8_t triangle_boundary) {
    const std::span<const glm::dvec2> screen = reference.screen_vertices(id);
    const ReferencePolygon& polygon = reference.polygon(id);
    bool whole = screen.size() == 3;
    for (uint32_t e = 0; e < screen.size(); ++e) whole = whole && reference.edge_kind(id, e) == EdgeKind::triangle;
    if (whole) return triangle_boundary;
    glm::dvec3 line[3];  // in (ndc x, ndc y, 1)
    glm::dvec3 clip[3];
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4 c = view.camera.projection * glm::dvec4(view.view[view.triangles[id].vertex[k]], 1.0);
        clip[k] = {c.x, c.y, c.w};
    }
    for (int k = 0; k < 3; ++k) line[k] = glm::cross(clip[k], clip[(k + 1) % 3]);
    uint16_t mask = 0;
    for (uint32_t e = 0; e < polygon.count; ++e) {
        if (reference.edge_kind(id, e) != EdgeKind::triangle) {
            mask |= static_cast<uint16_t>(1u << e);
            continue;
        }
        const glm::dvec2 a = ndc_of_screen(view.camera, screen[e]), b = ndc_of_screen(view.camera, screen[(e + 1) % screen.size()]);
        int best = 0;
        double best_residual = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double norm = std::hypot(line[k].x, line[k].y);
            if (!(norm > 0.0)) continue;
            const double residual = (std::fabs(glm::dot(line[k], glm::dvec3(a, 1.0))) +
                                     std::fabs(glm::dot(line[k], glm::dvec3(b, 1.0)))) / norm;
            if (residual < best_residual) best_residual = residual, best = k;
        }
        if (triangle_boundary & (1u << best)) mask |= static_cast<uint16_t>(1u << e);
    }
    return mask;
}

}  // namespace

ShadowIndex::ShadowIndex(const Scene& scene, const OracleScene& geometry, size_t light,
                         const std::vector<uint8_t>& casts) {
    const glm::vec3 position = scene.lights[light].position;
    planes_ = shadow_planes(geometry.world, position);
    const std::vector<uint8_t> triangle_boundary = boundary_edges(scene, geometry, glm::dvec3(position), casts);
    const int n = scene.settings.shadows.resolution;
    for (int face = 0; face < kShadowFaces; ++face) {
        auto f = std::make_unique<Face>();
        f->view = oracle_view(scene, shadow_face_camera(position, face, planes_), n, n);
        f->reference = std::make_unique<ReferenceGeometry>(
            scene, f->view, ViewVolume{planes_.near, planes_.far, kDefaultSnapBits, false, 1.0 + 4.0 / n});
        f->boundary.assign(geometry.triangles.size(), 0);
        f->cell = static_cast<double>(n) / kGrid;
        f->cells.resize(kGrid * kGrid);
        for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
            if (!casts[id]) continue;
            const ReferencePolygon& polygon = f->reference->polygon(id);
            if (polygon.count < 3) continue;
            f->boundary[id] = polygon_boundary(*f->reference, f->view, id, triangle_boundary[id]);
            if (!std::isfinite(polygon.radius)) {
                f->everywhere.push_back(id);
                continue;
            }
            double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
            for (const glm::dvec2& v : f->reference->screen_vertices(id)) {
                x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
            }
            auto cell_of = [&](double p) { return std::clamp(static_cast<int>(std::floor(p / f->cell)), 0, kGrid - 1); };
            const double r = polygon.radius;
            for (int cy = cell_of(y0 - r); cy <= cell_of(y1 + r); ++cy)
                for (int cx = cell_of(x0 - r); cx <= cell_of(x1 + r); ++cx) f->cells[cy * kGrid + cx].push_back(id);
        }
        faces_.push_back(std::move(f));
    }
}

ShadowIndex::~ShadowIndex() = default;

namespace {

// The polygon's part inside the rectangle (Sutherland-Hodgman against its four sides).
std::vector<glm::dvec2> clipped_to(const std::span<const glm::dvec2>& polygon, const TexelRect& r) {
    std::vector<glm::dvec2> out(polygon.begin(), polygon.end()), next;
    const glm::dvec3 sides[4] = {{1, 0, -r.x0}, {-1, 0, r.x1}, {0, 1, -r.y0}, {0, -1, r.y1}};  // a x + b y + c >= 0
    for (const glm::dvec3& side : sides) {
        next.clear();
        for (size_t i = 0; i < out.size(); ++i) {
            const glm::dvec2 &a = out[i], &b = out[(i + 1) % out.size()];
            const double da = side.x * a.x + side.y * a.y + side.z, db = side.x * b.x + side.y * b.y + side.z;
            if (da >= 0.0) next.push_back(a);
            if ((da >= 0.0) != (db >= 0.0)) next.push_back(a + (da / (da - db)) * (b - a));
        }
        out.swap(next);
        if (out.empty()) break;
    }
    return out;
}

}  // namespace

template <class Visit>
void ShadowIndex::each_candidate(int face, const TexelRect& region, Visit visit) const {
    const Face& f = *faces_[static_cast<size_t>(face)];
    thread_local std::vector<uint32_t> candidates;
    candidates.clear();
    auto cell_of = [&](double p) { return std::clamp(static_cast<int>(std::floor(p / f.cell)), 0, kGrid - 1); };
    for (int cy = cell_of(region.y0); cy <= cell_of(region.y1); ++cy)
        for (int cx = cell_of(region.x0); cx <= cell_of(region.x1); ++cx) {
            const auto& cell = f.cells[cy * kGrid + cx];
            candidates.insert(candidates.end(), cell.begin(), cell.end());
        }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (uint32_t id : candidates) {
        const ReferencePolygon& polygon = f.reference->polygon(id);
        const TexelRect near = expanded(region, polygon.radius);
        const std::span<const glm::dvec2> vertices = f.reference->screen_vertices(id);
        if (!polygon_meets(vertices, near)) continue;
        // The map's depth of this surface in the region: raster's value at a texel centre is the exact plane's at
        // a point of the triangle within the radius (precision.h, section 1), so the plane over the triangle's part
        // of the widened region (a convex polygon: the extremes are at its vertices), and the rounding of raster's
        // view depth.
        SurfaceRange range;
        range.bounded = true;
        range.nearest = std::numeric_limits<double>::infinity();
        range.farthest = -range.nearest;
        for (const glm::dvec2& p : clipped_to(vertices, near)) {
            const ExactHit hit = f.reference->hit(id, p);
            if (!hit.valid) {
                range.bounded = false;
                break;
            }
            range.nearest = std::min(range.nearest, hit.view_depth);
            range.farthest = std::max(range.farthest, hit.view_depth);
        }
        const double rounding = view_depth_rounding(polygon.relative_depth_error);
        range.nearest *= 1.0 - rounding;
        range.farthest *= 1.0 + rounding;
        range.inside = polygon_meets(vertices, expanded(region, 0.0));
        range.boundary = f.boundary[id];
        if (!visit(id, vertices, near, range)) return;
    }
}

MapAnswer ShadowIndex::answer(int face, const TexelRect& taps, const Interval& reference) const {
    if (!faces_[static_cast<size_t>(face)]->everywhere.empty()) return MapAnswer::open_edge;  // through the light
    bool covered = false, edge = false, depth = false;
    each_candidate(face, taps, [&](uint32_t, std::span<const glm::dvec2> vertices, const TexelRect& near,
                                   const SurfaceRange& range) {
        if (!range.bounded) return !(depth = true);
        if (range.nearest > reference.hi) return true;          // behind the receiver's reference: never a shadow
        if (!(range.farthest < reference.lo)) return !(depth = true);  // may be on either side of it
        if (range.inside) covered = true;
        else edge = true;  // it reaches the taps only within its precision
        for (uint32_t e = 0; e < vertices.size() && !edge; ++e)
            if ((range.boundary >> e) & 1u) edge = segment_meets(near, vertices[e], vertices[(e + 1) % vertices.size()]);
        return true;
    });
    if (depth) return MapAnswer::open_depth;
    if (edge) return MapAnswer::open_edge;
    return covered ? MapAnswer::shadowed : MapAnswer::lit;
}

bool ShadowIndex::occluder_edge_within(int face, const TexelRect& footprint, double depth) const {
    if (!faces_[static_cast<size_t>(face)]->everywhere.empty()) return true;
    bool found = false;
    each_candidate(face, footprint, [&](uint32_t, std::span<const glm::dvec2> vertices, const TexelRect& near,
                                        const SurfaceRange& range) {
        if (range.bounded && range.nearest >= depth) return true;  // nothing of it in front of the point
        for (uint32_t e = 0; e < vertices.size() && !found; ++e)
            found = !range.bounded || (((range.boundary >> e) & 1u) &&
                                       segment_meets(near, vertices[e], vertices[(e + 1) % vertices.size()]));
        return !found;
    });
    return found;
}

}  // namespace raster::oracle
