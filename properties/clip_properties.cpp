// Clipping properties: output vertices satisfy every plane within a derived bound (clip_checks.h), a triangle
// inside the frustum passes untouched, clip-then-rasterize covers exactly the samples of the unclipped triangle
// inside the frustum (against the homogeneous reference), and no w <= 0 reaches a divide.
#include <string>

#include "properties/clip_checks.h"
#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"
#include "properties/property_registry.h"

namespace raster::properties {
namespace {

// Crossing triangles, far off screen, and w near zero, in one mix.
rc::Gen<ClipCase> clipped_triangles() {
    return rc::gen::weightedOneOf<ClipCase>({{4, triangles_crossing_the_volume()},
                                             {1, triangles_far_off_screen()},
                                             {1, triangles_with_w_near_zero()},
                                             {1, triangles_inside_the_volume()}});
}

}  // namespace

// Every output vertex is finite, has w >= near - e and w <= far + e, |x| <= w + e and |y| <= w + e with
// e = 2^-18 S; and is the original triangle at its barycentrics within 2^-18 (S + the originals' largest
// coordinate) (the barycentrics ride the same cuts, with errors relative to 1), which sum to 1 within 2^-18.
RASTER_PROPERTY(Clip, outputVerticesSatisfyEveryPlaneWithinTheBound) {
    const ClipCase c = *clipped_triangles();
    RC_CLASSIFY(true, c.kind);
    check_clipped_vertices(impl, c);
}

// A triangle inside the volume or exactly on its planes (w = near, w = far, x = +-w, y = +-w) comes back as
// itself: three vertices, bit for bit, with unit barycentrics, not marked clipped.
RASTER_PROPERTY(Clip, triangleInsideTheFrustumIsUntouched) {
    const ClipCase c = *triangles_inside_the_volume();
    RC_CLASSIFY(true, c.kind);
    const ClippedPolygon polygon = impl.stages.clip(c.triangle.v[0], c.triangle.v[1], c.triangle.v[2], c.frame.volume);
    if (polygon.count != 3 || polygon.clipped)
        fail_case("a triangle inside the volume came back with " + std::to_string(polygon.count) + " vertices" +
                  (polygon.clipped ? ", marked clipped" : ""));
    for (size_t i = 0; i < 3; ++i) {
        glm::vec3 unit(0.0f);
        unit[static_cast<int>(i)] = 1.0f;
        if (polygon.vertices[i].position != c.triangle.v[i] || polygon.vertices[i].bary != unit)
            fail_case("vertex " + std::to_string(i) + " came back as " + literal(polygon.vertices[i].position) + " with barycentrics " +
                      literal(polygon.vertices[i].bary));
    }
}

// Drawn through clip, setup and rasterize, a triangle covers exactly the samples whose ray meets it at a view depth
// in [near, far] (view_volume_reference.h), except samples within the derived distance of a line where that
// changes: half a sub-pixel unit diagonally (snapping) plus max(W, H) 2^-18 S / w_min pixels (the clipped
// vertices' error e over their smallest w, doubled for x/w, in NDC halves).
RASTER_DRAWING_PROPERTY(Clip, clipThenRasterizeCoversExactlyTheInFrustumSamplesOfTheUnclippedTriangle) {
    const ClipCase c = *clipped_triangles();
    RC_CLASSIFY(true, c.kind);
    check_clip_then_rasterize(impl, c);
}

// No clipped vertex has w <= 0, or w < near, or a non-finite coordinate: setup divides by every w it is given.
RASTER_PROPERTY(Clip, noVertexWithWAtMostZeroReachesADivide) {
    const ClipCase c = *clipped_triangles();
    RC_CLASSIFY(true, c.kind);
    check_every_clipped_w_is_at_least_near(impl, c);
}

}  // namespace raster::properties
