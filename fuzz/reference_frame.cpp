// The exact reference's frame: facing, view volume, snapping, fan pieces, per-sample coverage, depth keys and
// interpolation, each from the conventions (conventions.h, setup.h's documented formulas), with raster's float
// error bounded where raster rounds and the reference does not.
#include "fuzz/reference_frame.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "properties/reference/documented_samples.h"
#include "raster/geometry/clip.h"

namespace raster::fuzz {
namespace {

using reference::Point;

// The fixed24 key's scale: z/w in [0, 1] becomes -(1 - z/w)(2^24 - 1) (setup.h, depth_key).
constexpr double kFixed24Levels = 16777215.0;

enum class Facing { front, back, undecided };

// The documented facing test (setup.h, faces_front): det[x y w] of the three clip-space vertices, > 0 is front.
// Raster evaluates it in double from exact 2x2 products, so within 2^-50 of the sum of the terms' magnitudes; the
// reference evaluates it in long double. A determinant within 2^-48 of those magnitudes is undecided.
Facing facing_of(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
    using Wide = long double;
    const Wide m0 = Wide(b.y) * c.w - Wide(b.w) * c.y, m1 = Wide(b.x) * c.w - Wide(b.w) * c.x;
    const Wide m2 = Wide(b.x) * c.y - Wide(b.y) * c.x;
    const Wide determinant = Wide(a.x) * m0 - Wide(a.y) * m1 + Wide(a.w) * m2;
    const Wide magnitude = std::fabs(Wide(a.x)) * (std::fabs(Wide(b.y) * c.w) + std::fabs(Wide(b.w) * c.y)) +
                           std::fabs(Wide(a.y)) * (std::fabs(Wide(b.x) * c.w) + std::fabs(Wide(b.w) * c.x)) +
                           std::fabs(Wide(a.w)) * (std::fabs(Wide(b.x) * c.y) + std::fabs(Wide(b.y) * c.x));
    const Wide bound = magnitude * Wide(0x1p-48);
    if (determinant > bound) return Facing::front;
    if (determinant < -bound) return Facing::back;
    return Facing::undecided;
}

// FNV-1a of the three vertices' bytes: equal for bit-identical triangles, so only equal hashes need comparing.
uint64_t bits_hash(const glm::vec4 (&v)[3]) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, v, sizeof v);
    uint64_t hash = 0xcbf29ce484222325u;
    for (const unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3u;
    return hash;
}

enum class Volume { inside, crossing, outside };

// The clip planes of clip.h (w >= near, w <= far, |x|, |y| <= side w), tested in double: side is a multiple of 1/4
// and w a float, so side w is exact and each sum keeps the exact sum's sign.
Volume volume_of(const glm::vec4 (&v)[3], double near, double far, double side) {
    unsigned common = 0x3F, any = 0;
    for (const glm::vec4& p : v) {
        const double x = p.x, y = p.y, w = p.w;
        const unsigned outside = (w < near ? 1u : 0u) | (w > far ? 2u : 0u) | (x < -side * w ? 4u : 0u) |
                                 (x > side * w ? 8u : 0u) | (y < -side * w ? 16u : 0u) | (y > side * w ? 32u : 0u);
        common &= outside;
        any |= outside;
    }
    return common ? Volume::outside : any ? Volume::crossing : Volume::inside;
}

bool finite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// The smallest altitude, in pixels, of the triangle the three clip-space vertices project to.
double min_altitude_px(const glm::vec4 (&v)[3], int width, int height) {
    glm::dvec2 p[3];
    for (int i = 0; i < 3; ++i)
        p[i] = {(double(v[i].x) / v[i].w + 1.0) * 0.5 * width, (1.0 - double(v[i].y) / v[i].w) * 0.5 * height};
    const double area2 = std::fabs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
    double altitude = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 edge = p[(i + 2) % 3] - p[(i + 1) % 3];
        altitude = std::min(altitude, area2 / std::hypot(edge.x, edge.y));
    }
    return altitude;
}

}  // namespace

ReferenceFrame::ReferenceFrame(const Scene& scene, const TransformedScene& geometry) {
    const RenderSettings& settings = scene.settings;
    width_ = settings.width;
    height_ = settings.height;
    snap_bits_ = settings.snap_bits;
    fixed_bits_ = fixed_bits_for(snap_bits_);
    depth_format_ = settings.modes.depth;
    affine_ = settings.modes.interpolation == Interpolation::affine;
    float_edges_ = settings.modes.edges == EdgeArithmetic::float32;
    offsets_ = properties::documented_fixed_offsets(settings.samples, settings.pattern, fixed_bits_);
    // Guard band (conventions.h): the side planes at +-g w, and snapped coordinates clamped to
    // [-(g - 1)/2 E, (g + 1)/2 E] for an extent E; full clipping is g = 1, the viewport. (g - 1)/2 is a multiple of
    // 1/8 and E of 16, so the bounds are exact integers.
    const double side = settings.modes.clipping == Clipping::guard_band
                            ? guard_band_factor(width_, height_, fixed_bits_) : 1.0;
    const int64_t extent_x = int64_t{width_} << fixed_bits_, extent_y = int64_t{height_} << fixed_bits_;
    low_x_ = -static_cast<int64_t>((side - 1.0) * 0.5 * double(extent_x));
    low_y_ = -static_cast<int64_t>((side - 1.0) * 0.5 * double(extent_y));
    high_x_ = extent_x - low_x_;
    high_y_ = extent_y - low_y_;
    const ClipVolume volume{scene.camera.near, scene.camera.far, side};

    triangles_.resize(geometry.triangles.size());
    pieces_.reserve(geometry.triangles.size());
    std::vector<uint64_t> hashes(geometry.triangles.size());  // of each triangle's clip-space bits, to find copies
    for (size_t t = 0; t < geometry.triangles.size(); ++t) {
        ReferenceTriangle& triangle = triangles_[t];
        const TriangleIndices& index = geometry.triangles[t];
        const glm::vec4 v[3] = {geometry.clip[index.v[0]], geometry.clip[index.v[1]], geometry.clip[index.v[2]]};
        hashes[t] = bits_hash(v);
        for (size_t earlier = 0; earlier < t && triangle.duplicate_of == kNoTriangle; ++earlier) {
            if (hashes[earlier] != hashes[t]) continue;
            const TriangleIndices& other = geometry.triangles[earlier];
            const glm::vec4 u[3] = {geometry.clip[other.v[0]], geometry.clip[other.v[1]], geometry.clip[other.v[2]]};
            if (std::memcmp(u, v, sizeof v) == 0) triangle.duplicate_of = static_cast<uint32_t>(earlier);
        }
        triangle.first_piece = triangle.end_piece = static_cast<uint32_t>(pieces_.size());
        // clip.h: a triangle with a non-finite coordinate is rejected.
        if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) continue;
        bool certain = true;
        if (settings.cull_backfaces) {
            const Facing facing = facing_of(v[0], v[1], v[2]);
            if (facing == Facing::back) continue;
            certain = facing == Facing::front;
        }
        const Volume where = volume_of(v, volume.near, volume.far, side);
        if (where == Volume::outside) continue;
        if (where == Volume::inside) {
            // Untouched by clipping: the reference starts from the vertex stage's own vertices.
            triangle.inside_volume = true;
            triangle.min_altitude = min_altitude_px(v, width_, height_);
            const glm::vec3 barys[3] = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
            add_polygon(static_cast<uint32_t>(t), v, barys, 3, certain);
        } else {
            // A triangle that crosses a plane is drawn from the clip stage's polygon (clip.h; the clip properties
            // check that stage): setup, traversal and depth are what this reference checks.
            const ClippedPolygon polygon = clip_triangle(v[0], v[1], v[2], volume);
            glm::vec4 positions[kMaxClippedVertices];
            glm::vec3 barys[kMaxClippedVertices];
            for (int i = 0; i < polygon.count; ++i) {
                positions[i] = polygon.vertices[static_cast<size_t>(i)].position;
                barys[i] = polygon.vertices[static_cast<size_t>(i)].bary;
            }
            add_polygon(static_cast<uint32_t>(t), positions, barys, polygon.count, certain);
        }
        triangle.end_piece = static_cast<uint32_t>(pieces_.size());
    }
}

void ReferenceFrame::add_polygon(uint32_t triangle, const glm::vec4* positions, const glm::vec3* barys, int count,
                                 bool certain) {
    const double key_scale = depth_format_ == DepthFormat::fixed24 ? kFixed24Levels : 1.0;
    ReferenceVertex vertex[kMaxClippedVertices];
    for (int i = 0; i < count; ++i) {
        const glm::vec4& p = positions[i];
        const Point at =
            reference::snapped_vertex(p, width_, height_, snap_bits_, {low_x_, low_y_}, {high_x_, high_y_});
        // setup.h, depth_key: reversed-Z d = z/w; float_z -(1 - d); fixed24 -(1 - d)(2^24 - 1). Raster rounds the
        // float formats' vertex keys to float (2^-24 relative); every format also carries double rounding.
        const double d = double(p.z) / double(p.w);
        const double key = depth_format_ == DepthFormat::reversed_z ? d : -(1.0 - d) * key_scale;
        const double float_rounding = depth_format_ == DepthFormat::fixed24 ? 0.0 : kFloatRoundoff * std::fabs(key);
        vertex[i] = {at, key, float_rounding + kDoubleSteps * key_scale * (1.0 + std::fabs(d)), double(p.w), barys[i]};
    }
    const int64_t coordinate_limit = std::max(int64_t{width_}, int64_t{height_}) << fixed_bits_;
    for (int k = 1; k + 1 < count; ++k) {
        const ReferenceVertex* v[3] = {&vertex[0], &vertex[k], &vertex[k + 1]};
        __int128 area2 = reference::orient(v[0]->at, v[1]->at, v[2]->at);
        if (area2 == 0) continue;  // covers nothing under the fill rule
        if (area2 < 0) {
            std::swap(v[1], v[2]);
            area2 = -area2;
        }
        ReferencePiece piece;
        piece.triangle = triangle;
        piece.reversed = v[1] != &vertex[k];
        piece.area2 = static_cast<double>(area2);
        piece.certain = certain;
        int64_t min_x = v[0]->at.x, max_x = min_x, min_y = v[0]->at.y, max_y = min_y, magnitude = coordinate_limit;
        for (int i = 0; i < 3; ++i) {
            piece.vertex[i] = *v[i];
            min_x = std::min(min_x, v[i]->at.x), max_x = std::max(max_x, v[i]->at.x);
            min_y = std::min(min_y, v[i]->at.y), max_y = std::max(max_y, v[i]->at.y);
            magnitude = std::max({magnitude, std::abs(v[i]->at.x), std::abs(v[i]->at.y)});
        }
        if (float_edges_) {
            // setup.cpp's float edges: the vertex coordinates (|x| <= M) rounded to float, their differences, the
            // two products and their difference, each one rounding of u = 2^-24. Then |a' - a|, |b' - b| <= 4uM
            // and |c' - c| <= 20uM^2 (first order), so at a sample within M of the origin the edge value is off by
            // at most 28uM^2; 32uM^2 + 2 keeps the second-order terms and the integer rounding inside.
            const double m = static_cast<double>(magnitude);
            piece.edge_error = 32.0 * kFloatRoundoff * m * m + 2.0;
        }
        // The pixels whose samples can lie in the box: each sample of pixel p is in [p << F, (p + 1) << F).
        piece.min_x = static_cast<int>(std::max<int64_t>(min_x >> fixed_bits_, 0));
        piece.min_y = static_cast<int>(std::max<int64_t>(min_y >> fixed_bits_, 0));
        piece.max_x = static_cast<int>(std::min<int64_t>(max_x >> fixed_bits_, width_ - 1));
        piece.max_y = static_cast<int>(std::min<int64_t>(max_y >> fixed_bits_, height_ - 1));
        pieces_.push_back(piece);
    }
}

uint64_t ReferenceFrame::box_samples() const {
    uint64_t total = 0;
    for (const ReferencePiece& piece : pieces_)
        if (piece.min_x <= piece.max_x && piece.min_y <= piece.max_y)
            total += uint64_t(piece.max_x - piece.min_x + 1) * uint64_t(piece.max_y - piece.min_y + 1) *
                     uint64_t(offsets_.size());
    return total;
}

ReferenceHit ReferenceFrame::hit(const ReferencePiece& piece, const glm::dvec3& lambda) const {
    // per_sample.h, interpolate_hit: perspective weights lambda_i / w_i, affine weights lambda_i, normalised; the
    // barycentrics are the weighted vertex barycentrics, the view depth 1 / sum(lambda_i / w_i) or sum(lambda_i w_i).
    double weight[3], total = 0.0, affine_depth = 0.0;
    for (int i = 0; i < 3; ++i) {
        weight[i] = affine_ ? lambda[i] : lambda[i] / piece.vertex[i].w;
        affine_depth += lambda[i] * piece.vertex[i].w;
        total += weight[i];
    }
    ReferenceHit out;
    for (int i = 0; i < 3; ++i) out.bary += (weight[i] / total) * glm::dvec3(piece.vertex[i].bary);
    out.view_depth = affine_ ? affine_depth / total : 1.0 / total;
    // Raster's float steps, for a covered sample (every lambda_i >= 0, vertex barycentrics in [0, 1]). Each
    // vertex's 1/w_i is rounded to float: off by a relative u, or by up to 2^-150 absolutely where it is subnormal
    // (w_i > 2^126), so by a relative eta = u + 2^-150 max w_i. (The fuzzer found that with far planes near
    // FLT_MAX, before validation kept far <= 2^126; the term then stays under u, and keeps the bound true.)
    //  - perspective: each weight is off by a relative eta, which moves each normalised weight m_i by at most
    //    m_i 2 eta / (1 - eta), so the barycentrics by 2 eta / (1 - eta); their rounding to float adds u. The view
    //    depth 1 / sum is off by a relative eta / (1 - eta) from the weights, then rounded: + u.
    //  - affine: the weights are exact up to double rounding, so the barycentrics are off by their rounding, u; the
    //    view depth sum(lambda_i / float(1 / w_i)) / sum(lambda_i) by a relative eta, then rounded: + u.
    // Both sides' double steps stay under 2^-44 (absolute on barycentrics in [0, 1], relative on the depth).
    const double largest_w = std::max({piece.vertex[0].w, piece.vertex[1].w, piece.vertex[2].w});
    const double eta = kFloatRoundoff + 0x1p-150 * largest_w;
    const double weight_drift = affine_ ? 0.0 : 2.0 * eta / (1.0 - eta);
    const double depth_drift = affine_ ? eta : eta / (1.0 - eta);
    out.bary_tolerance = weight_drift + kFloatRoundoff + 0x1p-44;
    out.depth_tolerance = (depth_drift + kFloatRoundoff + 0x1p-44) * out.view_depth;
    return out;
}

}  // namespace raster::fuzz
