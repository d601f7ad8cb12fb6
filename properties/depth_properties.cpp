// Depth properties: reversed-Z float depth (the one depth mode raster has; conventions.h) is strictly monotone in
// view distance over [near, far] (the projection's depth row), the z-buffer keeps the nearest surface (against an
// exact nearest-surface reference), without ties the image does not depend on draw order, and exact ties keep the
// earlier triangle.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <glm/mat4x4.hpp>

#include "properties/depth_precision.h"
#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/lens_projection.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {
namespace {

// The depth setup stores for a view-space point: fl(z * (1 / w)) of its clip-space position.
float stored_depth(const glm::mat4& projection, const glm::vec3& view) {
    const glm::vec4 clip = projection * glm::vec4(view, 1.0f);
    return static_cast<float>(static_cast<double>(clip.z) * (1.0 / static_cast<double>(clip.w)));
}

}  // namespace

// For near <= w1 < w2 <= far with w2 >= w1 (1 + 2^-19) (depth_precision.h), the depth setup stores, fl(z / w)
// from the implementation's projection matrix, is strictly larger (nearer) at w1, at every lens from typical to
// near = 1e-6, far = 1e9 and far = near (1 + 2^-10).
RASTER_PROPERTY(Depth, isMonotoneInViewDistanceOverNearToFar) {
    const LensCase c = *lenses();
    RC_CLASSIFY(true, c.kind);
    const glm::mat4 projection = impl.blocks.perspective(c.fov_y_degrees, c.aspect, c.near, c.far);
    const double half = std::tan(static_cast<double>(c.fov_y_degrees) * 3.14159265358979323846 / 360.0);
    auto depth_at = [&](float w) {
        const glm::vec3 view(static_cast<float>(c.across.x * w * half * c.aspect), static_cast<float>(c.across.y * w * half), -w);
        return stored_depth(projection, view);
    };
    const float nearer = depth_at(c.depth), farther = depth_at(c.farther);
    if (!(nearer > farther))
        fail_case("stored depth " + float_literal(nearer) + " at view depth " + float_literal(c.depth) + " is not above " +
                  float_literal(farther) + " at " + float_literal(c.farther));
}

// Overlapping triangles (flat layers, tilted, intersecting) projected with the implementation's lens: every sample
// shows the triangle nearest along its ray, found exactly on the snapped triangles (1/w is affine in screen
// space); samples where the two nearest depths are within the derived error of the compared depth
// (depth_precision.h) are ties and may show either.
RASTER_RENDERER_PROPERTY(Depth, zBufferKeepsTheNearestSurface) {
    const LayeredCase c = *overlapping_triangles();
    RC_CLASSIFY(true, c.kind);
    const Frame& frame = c.frame;
    const std::vector<ClipTriangle> triangles = project(impl, c);
    const VisibilityBuffer visibility = draw(impl, frame, triangles);

    // The reference: each triangle's snapped vertices, its 1/w at the vertices, and the documented depth there.
    const double n = frame.volume.near, f = frame.volume.far;
    struct Reference {
        reference::Point v[3];
        double inv_w[3];
        double error;  // interpolated_depth_error for this triangle
    };
    std::vector<Reference> refs;
    for (const ClipTriangle& t : triangles) {
        Reference r;
        double largest = 0.0;
        for (int i = 0; i < 3; ++i) {
            r.v[i] = snapped(frame, t.v[static_cast<size_t>(i)]);
            r.inv_w[i] = 1.0 / static_cast<double>(t.v[static_cast<size_t>(i)].w);
            largest = std::max(largest, reversed_z_depth(t.v[static_cast<size_t>(i)].w, n, f));
        }
        r.error = interpolated_depth_error(n, f, largest);
        refs.push_back(r);
    }
    int ties = 0, decided = 0;
    for (const Sample& s : samples_of(frame)) {
        // The nearest two candidates by exact depth: d = m32 / w - m22 with 1/w = sum(l_i / w_i).
        double best = -INFINITY, second = -INFINITY, best_error = 0.0, second_error = 0.0;
        int winner = -1;
        for (size_t k = 0; k < refs.size(); ++k) {
            const Reference& r = refs[k];
            if (!reference::reference_covers(r.v[0], r.v[1], r.v[2], s.fixed)) continue;
            const double area = static_cast<double>(reference::orient(r.v[0], r.v[1], r.v[2]));
            double inv_w = 0.0;
            for (int i = 0; i < 3; ++i)
                inv_w += static_cast<double>(reference::orient(r.v[(i + 1) % 3], r.v[(i + 2) % 3], s.fixed)) / area * r.inv_w[i];
            const double d = n * f / (f - n) * inv_w - n / (f - n);
            if (d > best) {
                second = best, second_error = best_error;
                best = d, best_error = r.error, winner = static_cast<int>(k);
            } else if (d > second) {
                second = d, second_error = r.error;
            }
        }
        const uint32_t shown = s.index < visibility.size() ? visibility.triangle[s.index] : kNoTriangle;
        if (winner < 0) {
            if (shown != kNoTriangle)
                fail_case(describe(s) + " shows triangle " + std::to_string(shown) + " but no triangle covers it");
            continue;
        }
        if (best - second <= best_error + second_error) {
            ++ties;
            continue;
        }
        ++decided;
        if (shown != static_cast<uint32_t>(winner))
            fail_case(describe(s) + " shows " + (shown == kNoTriangle ? std::string("nothing") : "triangle " + std::to_string(shown)) +
                      "; the nearest is triangle " + std::to_string(winner) + " (depth " + double_literal(best) +
                      " against " + double_literal(second) + ")");
    }
    RC_CLASSIFY(ties > 0, "some samples tie");
    RC_CLASSIFY(decided == 0, "no sample decided");
}

// Fronto-parallel triangles at distinct power-of-two depths (no two surfaces ever tie) drawn in two orders give the
// same visibility buffer, bit for bit: the same triangle, barycentrics and depth at every sample.
RASTER_RENDERER_PROPERTY(Depth, imageDoesNotDependOnDrawOrderWithoutTies) {
    const LayeredCase c = *fronto_parallel_layers();
    RC_CLASSIFY(true, c.kind);
    const std::vector<ClipTriangle> triangles = project(impl, c);
    std::vector<ClipTriangle> shuffled;
    for (int k : c.order) shuffled.push_back(triangles[static_cast<size_t>(k)]);
    const VisibilityBuffer first = draw(impl, c.frame, triangles), second = draw(impl, c.frame, shuffled);
    if (first.size() != second.size()) fail_case("the two orders give visibility buffers of different sizes");
    int overlaps = 0;
    for (size_t i = 0; i < first.size(); ++i) {
        const uint32_t a = first.triangle[i];
        const uint32_t b = second.triangle[i] == kNoTriangle ? kNoTriangle : static_cast<uint32_t>(c.order[second.triangle[i]]);
        const bool same = a == b && (a == kNoTriangle || (first.bary[i] == second.bary[i] && first.view_depth[i] == second.view_depth[i]));
        if (!same)
            fail_case("sample " + std::to_string(i) + " shows triangle " + std::to_string(a) + " in the first order and " +
                      std::to_string(b) + " in the second (or different barycentrics or depth)");
        overlaps += a != kNoTriangle;
    }
    RC_CLASSIFY(overlaps == 0, "nothing visible");
}

// The same triangle drawn twice, then a copy through the same vertices in the other winding: every depth key ties,
// and the documented rule (per_sample.h: "on an exact tie the earlier one stays") leaves each covered sample to
// the first triangle drawn.
RASTER_RENDERER_PROPERTY(Depth, exactTiesKeepTheEarlierTriangle) {
    const ClipCase c = *perspective_triangles_inside();
    RC_CLASSIFY(true, c.kind);
    const ClipTriangle& t = c.triangle;
    const ClipTriangle reversed{{t.v[0], t.v[2], t.v[1]}};
    const VisibilityBuffer visibility = draw(impl, c.frame, {t, t, reversed});
    int covered = 0;
    for (size_t i = 0; i < visibility.size(); ++i) {
        if (visibility.triangle[i] == kNoTriangle) continue;
        ++covered;
        if (visibility.triangle[i] != 0)
            fail_case("sample " + std::to_string(i) + " shows triangle " + std::to_string(visibility.triangle[i]) +
                      ", drawn after triangle 0 at exactly the same depth");
    }
    RC_CLASSIFY(covered == 0, "covers no sample");
}

}  // namespace raster::properties
