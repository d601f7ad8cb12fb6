// What the independent exact reference says a frame shows: per scene triangle its facing and view-volume tests, its
// clipped polygon snapped by the reference (properties/reference) into a fan of pieces, and per sample each piece's
// coverage under the top-left rule, its depth-test key interval and its exact interpolation.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "properties/reference/coverage_reference.h"
#include "raster/core/conventions.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster::fuzz {

// u, the unit roundoff of float (round to nearest).
inline constexpr double kFloatRoundoff = 0x1p-24;
// Everything done in double, by raster or by the reference, is bounded by this multiple of the magnitudes involved:
// each value passes through at most a dozen double roundings (2^-53 each), so 2^-47 covers them with room.
inline constexpr double kDoubleSteps = 0x1p-47;

// Does a piece cover a sample? `maybe` where the reference cannot decide what raster decides (float edges near an
// edge, a facing too close to edge-on to call with culling on).
enum class Coverage : uint8_t { no, maybe, yes };

// A vertex of the clipped polygon, as the reference projects it.
struct ReferenceVertex {
    reference::Point at;      // snapped and clamped
    double key = 0;           // the depth test's key, from its clip z and w by the documented formula
    double key_rounding = 0;  // how far raster's vertex key can be from `key` (float or double rounding)
    double w = 0;             // view depth (clip w)
    glm::vec3 bary{0.0f};     // barycentrics in the scene triangle
};

// One snapped triangle of a scene triangle's fan (from the clipped polygon's first vertex), as the reference draws it.
struct ReferencePiece {
    uint32_t triangle = 0;      // the scene triangle
    ReferenceVertex vertex[3];  // wound so that orient(v0, v1, v2) > 0; vertex 0 is the fan's centre
    double area2 = 0;           // orient(v0, v1, v2)
    bool reversed = false;      // vertices 1 and 2 were swapped to wind it so: the polygon's order was the other way
    double edge_error = 0;      // float edges: bound on |raster's edge value - exact|; 0 for fixed-point edges
    bool certain = true;       // false when the facing is undecided with culling on: its coverage is at most maybe
    int min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // the pixels its box touches inside the frame
};

// One scene triangle.
struct ReferenceTriangle {
    uint32_t first_piece = 0, end_piece = 0;  // its pieces in ReferenceFrame::pieces()
    bool inside_volume = false;   // every vertex inside every clip plane: drawn from its own vertices, unclipped
    double min_altitude = 0;      // px, of the projected triangle (inside_volume only)
    uint32_t duplicate_of = kNoTriangle;  // the first earlier triangle with bit-identical clip-space vertices
};

// A piece at one sample.
struct PieceSample {
    Coverage coverage = Coverage::no;
    glm::dvec3 lambda{0.0};  // screen-space barycentrics on the snapped piece (exact ratios, rounded once)
    float key_low = 0, key_high = 0;  // raster's depth key there lies in [key_low, key_high]
};

// Where on its scene triangle a covered sample is, interpolated exactly from the piece, and how far raster's float
// result may be from it (derived in the .cpp).
struct ReferenceHit {
    glm::dvec3 bary{0.0};
    double view_depth = 0;
    double bary_tolerance = 0;   // absolute, per component
    double depth_tolerance = 0;  // absolute
};

class ReferenceFrame {
public:
    // `geometry` is the vertex stage's output for `scene` (the clip-space positions the reference starts from).
    ReferenceFrame(const Scene& scene, const TransformedScene& geometry);

    const std::vector<ReferencePiece>& pieces() const { return pieces_; }
    const std::vector<ReferenceTriangle>& triangles() const { return triangles_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return static_cast<int>(offsets_.size()); }
    int fixed_bits() const { return fixed_bits_; }
    bool float_edges() const { return float_edges_; }

    // Sample s of pixel (px, py) at its documented position on the fixed-point grid.
    reference::Point sample_position(int px, int py, int s) const {
        return {(int64_t{px} << fixed_bits_) + offsets_[static_cast<size_t>(s)].x,
                (int64_t{py} << fixed_bits_) + offsets_[static_cast<size_t>(s)].y};
    }
    // Samples in the pieces' boxes, summed: the reference's work for this frame (and raster's, near enough).
    uint64_t box_samples() const;

    // Inline (below): called for every sample of every piece's box, in loops that keep the piece in registers.
    PieceSample at(const ReferencePiece& piece, reference::Point p) const;
    ReferenceHit hit(const ReferencePiece& piece, const glm::dvec3& lambda) const;

private:
    void add_polygon(uint32_t triangle, const glm::vec4* positions, const glm::vec3* barys, int count, bool certain);

    int width_ = 0, height_ = 0, snap_bits_ = 0, fixed_bits_ = 0;
    int64_t low_x_ = 0, high_x_ = 0, low_y_ = 0, high_y_ = 0;  // the snapped range: the viewport or the guard band
    DepthFormat depth_format_ = DepthFormat::reversed_z;
    bool affine_ = false, float_edges_ = false;
    std::vector<reference::Point> offsets_;
    std::vector<ReferencePiece> pieces_;
    std::vector<ReferenceTriangle> triangles_;
};

// The key's rounding to what the depth test compares (setup.h): float, or the nearest fixed24 level as a float.
// Both are monotone, so the interval [low, high] of the double value maps onto the interval of the key.
inline float depth_key_of(double value, DepthFormat format) {
    return static_cast<float>(format == DepthFormat::fixed24 ? std::floor(value + 0.5) : value);
}

[[gnu::always_inline]] inline PieceSample ReferenceFrame::at(const ReferencePiece& piece, reference::Point p) const {
    PieceSample out;
    // Edge i is opposite vertex i. With fixed-point edges the signs settle every sample off the piece's edges and
    // the reference's top-left rule decides those on one; raster's float edge values are each within edge_error
    // of these exact ones. Either way a sample outside one edge needs no other.
    const double margin = piece.edge_error;
    __int128 edge[3];
    bool certain_inside = true, on_edge = false;
    for (int i = 0; i < 3; ++i) {
        edge[i] = reference::orient(piece.vertex[(i + 1) % 3].at, piece.vertex[(i + 2) % 3].at, p);
        if (float_edges_) {
            if (static_cast<double>(edge[i]) < -(margin + 1.0)) return out;
            certain_inside = certain_inside && static_cast<double>(edge[i]) > margin;
        } else {
            if (edge[i] < 0) return out;
            on_edge = on_edge || edge[i] == 0;
        }
    }
    if (on_edge && !reference::reference_covers(piece.vertex[0].at, piece.vertex[1].at, piece.vertex[2].at, p))
        return out;
    out.coverage = certain_inside ? Coverage::yes : Coverage::maybe;
    if (!piece.certain) out.coverage = Coverage::maybe;
    for (int i = 0; i < 3; ++i) out.lambda[i] = static_cast<double>(edge[i]) / piece.area2;

    // Raster's key: the vertex keys (each off by its rounding) interpolated in double from the edge values as
    // k0 + e1 (k1 - k0) / A + e2 (k2 - k0) / A, then rounded (depth_key_of). Its distance from the exact interpolation:
    // the vertex roundings weighted by |lambda|, the double evaluation on both sides, and with float edges the
    // edge values' error over the area on each difference.
    const glm::dvec3& l = out.lambda;
    const double k0 = piece.vertex[0].key, d1 = piece.vertex[1].key - k0, d2 = piece.vertex[2].key - k0;
    const double exact = k0 + l[1] * d1 + l[2] * d2;
    double error = kDoubleSteps * (std::fabs(k0) + std::fabs(l[1] * d1) + std::fabs(l[2] * d2)) +
                   piece.edge_error / piece.area2 * (std::fabs(d1) + std::fabs(d2));
    for (int i = 0; i < 3; ++i) error += std::fabs(l[i]) * piece.vertex[i].key_rounding;
    if (std::isfinite(exact) && std::isfinite(error)) {
        out.key_low = depth_key_of(exact - error, depth_format_);
        out.key_high = depth_key_of(exact + error, depth_format_);
    } else {
        out.key_low = -std::numeric_limits<float>::infinity();
        out.key_high = std::numeric_limits<float>::infinity();
    }
    return out;
}

}  // namespace raster::fuzz
