// Barycentric properties on one perspective triangle inside the frustum, drawn with the implementation.
#include "properties/barycentric_properties.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"
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

void check_barycentrics_sum_to_one_within_the_derived_bound(const Implementation& impl) {
    for_each_covered_sample(impl, *perspective_triangles_inside(), [](const Sample& s, const glm::dvec3& b, double) {
        const double magnitude = std::fabs(b.x) + std::fabs(b.y) + std::fabs(b.z);
        const double bound = std::ldexp(magnitude, -24) * (1.0 + std::ldexp(1.0, -23)) + std::ldexp(1.0, -50);
        const double error = std::fabs(b.x + b.y + b.z - 1.0);
        if (!(error <= bound))
            fail_case("barycentrics " + show(b) + " at " + describe(s) + " sum to 1 + " + double_literal(b.x + b.y + b.z - 1.0) +
                      ", beyond the bound " + double_literal(bound));
    });
}

void check_barycentrics_are_non_negative_on_covered_samples(const Implementation& impl) {
    for_each_covered_sample(impl, *perspective_triangles_inside(), [](const Sample& s, const glm::dvec3& b, double) {
        if (!(b.x >= 0.0 && b.y >= 0.0 && b.z >= 0.0))
            fail_case("barycentrics " + show(b) + " at covered " + describe(s) + " are negative");
    });
}

void check_barycentrics_reproduce_the_sample_screen_position(const Implementation& impl) {
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

void check_perspective_correct_barycentrics_reproduce_the_ray_plane_intersection(const Implementation& impl) {
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
