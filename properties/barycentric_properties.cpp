// Barycentric properties on one perspective triangle inside the frustum, drawn with the implementation: on every
// covered sample they sum to 1 and are non-negative within derived bounds, and they reproduce both the sample's
// screen position and the 3D point where its ray meets the triangle's plane.
//
// The bounds, with u = 2^-24. The rasterizer computes exact screen weights l_i = E_i / area2 (integers, then one
// double division), multiplies by the stored 1 / w_i (a float: relative error u), normalises in double and stores
// each barycentric as a float (relative error u). So each barycentric is the exact perspective-correct one for the
// SNAPPED triangle times (1 + e_i) with |e_i| <= 2u + u + O(u^2) = 1.5 * 2^-23 (the normalisation doubles the
// inverse-w error).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/view_volume_reference.h"

namespace raster::properties {
namespace {

// Draws a generated triangle and calls fn(sample, barycentrics, view depth) for every sample it covers.
template <class F>
void for_each_covered_sample(const Implementation& impl, const ClipCase& c, F&& fn) {
    RC_CLASSIFY(true, c.kind);
    const VisibilityBuffer visibility = draw(impl, c.frame, {c.triangle});
    int covered = 0;
    for (const Sample& s : samples_of(c.frame)) {
        if (s.index >= visibility.size() || visibility.triangle[s.index] == kNoTriangle) continue;
        ++covered;
        fn(s, glm::dvec3(visibility.bary[s.index]), static_cast<double>(visibility.view_depth[s.index]));
    }
    RC_CLASSIFY(covered == 0, "no sample covered");
}

std::string show(const glm::dvec3& b) {
    std::ostringstream os;
    os << "(" << double_literal(b.x) << ", " << double_literal(b.y) << ", " << double_literal(b.z) << ")";
    return os.str();
}

}  // namespace

// |b0 + b1 + b2 - 1| <= u (|b0| + |b1| + |b2|) (1 + 2u) + 2^-50: in double the normalised weights sum to 1 within a
// few double ulps; storing each as a float moves it by at most u |b_i|.
RASTER_RENDERER_PROPERTY(Barycentrics, sumToOneWithinTheDerivedBound) {
    for_each_covered_sample(impl, *perspective_triangles_inside(), [](const Sample& s, const glm::dvec3& b, double) {
        const double magnitude = std::fabs(b.x) + std::fabs(b.y) + std::fabs(b.z);
        const double bound = std::ldexp(magnitude, -24) * (1.0 + std::ldexp(1.0, -23)) + std::ldexp(1.0, -50);
        const double error = std::fabs(b.x + b.y + b.z - 1.0);
        if (!(error <= bound))
            fail_case("barycentrics " + show(b) + " at " + describe(s) + " sum to 1 + " + double_literal(b.x + b.y + b.z - 1.0) +
                      ", beyond the bound " + double_literal(bound));
    });
}

// b_i >= 0 exactly (bound 0): a covered sample has every E_i >= 0, the weights are products and sums of
// non-negative numbers, and rounding never turns a non-negative number negative.
RASTER_RENDERER_PROPERTY(Barycentrics, areNonNegativeOnCoveredSamples) {
    for_each_covered_sample(impl, *perspective_triangles_inside(), [](const Sample& s, const glm::dvec3& b, double) {
        if (!(b.x >= 0.0 && b.y >= 0.0 && b.z >= 0.0))
            fail_case("barycentrics " + show(b) + " at covered " + describe(s) + " are negative");
    });
}

// The clip-space point sum b_i v_i projects to within 2^-(snap_bits + 1) + 2^-22 * diameter + 2^-30 pixels of
// the sample in each coordinate: the exact weights reproduce the sample from the snapped vertices, and the
// original vertices are at most half a snap unit away from those (a convex combination keeps that), while the
// relative errors e_i move the projection by at most 2 max|e_i| times the triangle's diameter in pixels.
RASTER_RENDERER_PROPERTY(Barycentrics, reproduceTheSampleScreenPosition) {
    const ClipCase c = *perspective_triangles_inside();
    glm::dvec2 screen[3];
    double diameter = 0.0;
    for (int i = 0; i < 3; ++i) screen[i] = screen_of_ndc(c.frame, ndc_of(glm::dvec4(c.triangle.v[static_cast<size_t>(i)])));
    for (int i = 0; i < 3; ++i) diameter = std::max(diameter, glm::length(screen[i] - screen[(i + 1) % 3]));
    const double bound = std::ldexp(1.0, -(c.frame.snap_bits + 1)) + std::ldexp(diameter, -22) + std::ldexp(1.0, -30);
    for_each_covered_sample(impl, c, [&](const Sample& s, const glm::dvec3& b, double) {
        glm::dvec4 p(0.0);
        for (size_t i = 0; i < 3; ++i) p += b[static_cast<int>(i)] * glm::dvec4(c.triangle.v[i]);
        const glm::dvec2 at = screen_of_ndc(c.frame, ndc_of(p));
        const glm::dvec2 off = glm::abs(at - s.screen);
        if (!(p.w > 0.0 && off.x <= bound && off.y <= bound))
            fail_case("barycentrics " + show(b) + " at " + describe(s) + " (" + literal(s.screen) + ") reproduce " +
                      literal(at) + ", off by more than " + double_literal(bound) + " px");
    });
}

// Lift the snapped triangle back to 3D at the original view depths (its projection is exactly what was drawn):
// then sum b_i V_i is the point R where the sample's ray meets that triangle's plane, within
// 2^-22 (max_i |V_i - R| + |R|) + 2^-40 (max_i |V_i| + |R|) (the errors e_i, then the reference's double solve),
// and the reported view depth is R's within 2^-22 relative (1/w rounded to float, the reciprocal stored as float).
RASTER_RENDERER_PROPERTY(Barycentrics, perspectiveCorrectOnesReproduceTheRayPlaneIntersection) {
    const ClipCase c = *perspective_triangles_inside();
    // The snapped triangle lifted back to (x, y, w) space (a linear image of view space: x and y scaled by the
    // lens, w = -z), each vertex at its original view depth.
    std::array<glm::dvec3, 3> lifted;
    const double unit = std::ldexp(1.0, -c.frame.fixed_bits());
    for (size_t i = 0; i < 3; ++i) {
        const reference::Point p = snapped(c.frame, c.triangle.v[i]);
        const glm::dvec2 ndc = ndc_of_screen(c.frame, {static_cast<double>(p.x) * unit, static_cast<double>(p.y) * unit});
        const double w = c.triangle.v[i].w;
        lifted[i] = {ndc.x * w, ndc.y * w, w};
    }
    const HomogeneousTriangle plane = homogeneous_triangle(lifted);
    for_each_covered_sample(impl, c, [&](const Sample& s, const glm::dvec3& b, double view_depth) {
        const glm::dvec2 ndc = ndc_of_screen(c.frame, s.screen);
        const RayHit h = hit(plane, ndc);
        if (plane.degenerate || !(h.w > 0.0)) fail_case("a covered sample's ray misses the drawn triangle's plane");
        const glm::dvec3 r = h.w * glm::dvec3(ndc, 1.0);
        const glm::dvec3 q = b.x * lifted[0] + b.y * lifted[1] + b.z * lifted[2];
        double spread = 0.0, size = 0.0;
        for (const glm::dvec3& v : lifted) spread = std::max(spread, glm::length(v - r)), size = std::max(size, glm::length(v));
        const double bound = std::ldexp(spread + glm::length(r), -22) + std::ldexp(size + glm::length(r), -40);
        if (!(glm::length(q - r) <= bound))
            fail_case("barycentrics " + show(b) + " at " + describe(s) + " give the point " + show(q) + ", but the ray meets the plane at " +
                      show(r) + ", " + double_literal(glm::length(q - r)) + " away (bound " + double_literal(bound) + ")");
        if (!(std::fabs(view_depth - h.w) <= std::ldexp(h.w, -22)))
            fail_case("view depth " + double_literal(view_depth) + " at " + describe(s) + ", but the ray meets the plane at depth " +
                      double_literal(h.w));
    });
}

}  // namespace raster::properties
