// The clipping checks on one case, against the derived bound (clip_checks.h) and the homogeneous reference.
#include "properties/clip_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "properties/failure.h"
#include "properties/printing.h"
#include "properties/view_volume_reference.h"

namespace raster::properties {
namespace {

double largest_coordinate(const ClipTriangle& t) {
    double m = 0.0;
    for (const glm::vec4& v : t.v)
        m = std::max({m, std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z)), std::fabs(double(v.w))});
    return m;
}

}  // namespace

void check_clipped_vertices(const Implementation& impl, const ClipCase& c) {
    const ClipVolume& volume = c.frame.volume;
    const ClippedPolygon polygon = impl.stages.clip(c.triangle.v[0], c.triangle.v[1], c.triangle.v[2], volume);
    const ClippingScale scale = clipping_scale(c.triangle, volume);
    const double e = clipped_coordinate_error(scale);
    const double e_bary = std::ldexp(scale.largest + largest_coordinate(c.triangle), -18);
    RC_CLASSIFY(polygon.count == 0, "nothing left");
    for (int i = 0; i < polygon.count; ++i) {
        const glm::dvec4 p(polygon.vertices[static_cast<size_t>(i)].position);
        const glm::dvec3 b(polygon.vertices[static_cast<size_t>(i)].bary);
        const std::string which = "clipped vertex " + std::to_string(i) + " " + literal(glm::vec4(p));
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
            fail_case(which + " is not finite");
        if (!(p.w >= volume.near - e && p.w <= volume.far + e)) fail_case(which + " is outside near or far beyond " + double_literal(e));
        if (!(std::fabs(p.x) <= p.w + e && std::fabs(p.y) <= p.w + e)) fail_case(which + " is outside a side plane beyond " + double_literal(e));
        if (!(std::fabs(b.x + b.y + b.z - 1.0) <= std::ldexp(1.0, -18))) fail_case(which + "'s barycentrics do not sum to 1");
        const glm::dvec4 rebuilt = b.x * glm::dvec4(c.triangle.v[0]) + b.y * glm::dvec4(c.triangle.v[1]) + b.z * glm::dvec4(c.triangle.v[2]);
        const glm::dvec4 miss = glm::abs(rebuilt - p);
        // w may have been pinned up to near by at most e; x, y, z within e_bary.
        if (!(std::max({miss.x, miss.y, miss.z, miss.w}) <= e_bary + e))
            fail_case(which + " is not the original triangle at its barycentrics (off by " +
                      double_literal(std::max({miss.x, miss.y, miss.z, miss.w})) + ")");
    }
}

void check_every_clipped_w_is_at_least_near(const Implementation& impl, const ClipCase& c) {
    const ClipVolume& volume = c.frame.volume;
    const ClippedPolygon polygon = impl.stages.clip(c.triangle.v[0], c.triangle.v[1], c.triangle.v[2], volume);
    for (int i = 0; i < polygon.count; ++i) {
        const glm::vec4& p = polygon.vertices[static_cast<size_t>(i)].position;
        if (!(p.w >= volume.near) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
            fail_case("clipped vertex " + literal(p) + " would reach setup's divide with w below near " + float_literal(volume.near));
    }
}

void check_clip_then_rasterize(const Implementation& impl, const ClipCase& c) {
    const Frame& frame = c.frame;
    const HomogeneousTriangle reference = homogeneous_triangle(c.triangle);
    RC_PRE(!reference.degenerate);  // a triangle edge-on to the eye: every sample is on its boundary
    const ClippingScale scale = clipping_scale(c.triangle, frame.volume);
    const double snap = std::sqrt(2.0) * std::ldexp(1.0, -(frame.snap_bits + 1));
    const double margin = scale.count == 0 ? snap
                                           : snap + std::max(frame.width, frame.height) * clipped_coordinate_error(scale) / scale.nearest;
    const VisibilityBuffer visibility = draw(impl, frame, {c.triangle});
    int compared = 0, ambiguous = 0, covered = 0;
    for (const Sample& s : samples_of(frame)) {
        if (boundary_distance_px(reference, frame, s.screen) <= margin) {
            ++ambiguous;
            continue;
        }
        ++compared;
        const bool expected = covers_in_volume(reference, frame.volume, ndc_of_screen(frame, s.screen));
        const bool actual = s.index < visibility.size() && visibility.triangle[s.index] != kNoTriangle;
        covered += expected;
        if (expected != actual)
            fail_case(describe(s) + " is " +
                      (actual ? "covered" : "not covered") + " but its ray " + (expected ? "meets" : "misses") +
                      " the triangle inside the volume (margin " + double_literal(margin) + " px)");
    }
    RC_CLASSIFY(compared > 0 && ambiguous * 10 <= compared, "under 10% of samples within the margin");
    RC_CLASSIFY(compared == 0, "every sample within the margin");
    RC_CLASSIFY(covered > 0, "covers samples");
}

}  // namespace raster::properties
