// Sampling properties: a triangle's N x N-grid coverage converges to its exact area within a perimeter bound, and
// the standard patterns are the documented positions.
#include <cmath>
#include <string>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/reference/coverage_reference.h"
#include "properties/reference/documented_samples.h"

namespace raster::properties {

// With h = 1/N px the samples form a lattice of spacing h (offsets rounded to the fixed-point grid move each by
// at most 2^-(fixed_bits + 1) per coordinate, under h/2 for N <= 16, so each stays inside its own h-cell). Give
// each sample its h-cell: a cell away from the boundary counts exactly its area, so only cells meeting the
// boundary err, by at most h^2 each. A segment meets at most 3 + (|dx| + |dy|) / h cells, and |dx| + |dy| <=
// sqrt(2) length, so for the snapped triangle's area A and perimeter P (pixels):
//     |covered / N^2 - A| <= sqrt(2) P / N + 9 / N^2.
RASTER_RENDERER_PROPERTY(Sampling, gridCoverageConvergesToTheExactAreaWithinAPerimeterBound) {
    const TilingCase c = *grid_sampled_triangles();
    RC_CLASSIFY(true, c.kind);
    const Frame& frame = c.frame;
    const std::vector<ClipTriangle> triangles = clip_triangles(frame, c.mesh);
    const VisibilityBuffer visibility = draw(impl, frame, triangles);
    double covered = 0.0;
    for (size_t i = 0; i < visibility.size(); ++i) covered += visibility.triangle[i] != kNoTriangle;

    reference::Point v[3];
    for (size_t i = 0; i < 3; ++i) v[i] = snapped(frame, triangles[0].v[i]);
    const double unit = std::ldexp(1.0, -frame.fixed_bits());
    const double area = std::fabs(static_cast<double>(reference::orient(v[0], v[1], v[2]))) * 0.5 * unit * unit;
    double perimeter = 0.0;
    for (int i = 0; i < 3; ++i)
        perimeter += std::hypot(double(v[(i + 1) % 3].x - v[i].x), double(v[(i + 1) % 3].y - v[i].y)) * unit;
    const double n = std::sqrt(static_cast<double>(frame.samples));
    const double estimate = covered / frame.samples, bound = std::sqrt(2.0) * perimeter / n + 9.0 / (n * n);
    RC_CLASSIFY(area < 1.0, "area under one pixel");
    if (!(std::fabs(estimate - area) <= bound))
        fail_case("coverage " + double_literal(estimate) + " px^2 of a triangle of area " + double_literal(area) +
                  " and perimeter " + double_literal(perimeter) + " is off by more than " + double_literal(bound));
}

// The implementation's offsets for 1, 2, 4, 8 and 16 standard samples equal the documented tables exactly, and
// its N x N grids (N = 1 .. 16) equal ((i + 0.5) / N, (j + 0.5) / N) within one float rounding (2^-25). Every
// pattern is checked in every case: there are few enough to enumerate.
RASTER_PROPERTY(Sampling, standardPatternsAreTheDocumentedPositions) {
    // Every documented pattern, every case: 1, 2, 4, 8 and 16 standard samples and the 1x1 to 16x16 grids.
    for (int n = 1; n <= 16 + 5; ++n) {
        const bool grid = n <= 16;
        const int standard[] = {1, 2, 4, 8, 16};
        const int samples = grid ? n * n : standard[n - 17];
        const SamplePattern pattern = grid ? SamplePattern::grid : SamplePattern::standard;
        const std::vector<glm::dvec2> documented = documented_sample_offsets(samples, pattern);
        const std::vector<glm::vec2> offsets = impl.stages.sample_offsets(samples, pattern);
        const std::string which = std::to_string(samples) + " " + to_string(pattern) + " samples";
        if (offsets.size() != documented.size()) fail_case(std::to_string(offsets.size()) + " offsets for " + which);
        const double bound = grid ? std::ldexp(1.0, -25) : 0.0;
        for (size_t i = 0; i < offsets.size(); ++i)
            if (!(std::fabs(offsets[i].x - documented[i].x) <= bound && std::fabs(offsets[i].y - documented[i].y) <= bound))
                fail_case("sample " + std::to_string(i) + " of " + which + " is at (" + float_literal(offsets[i].x) + ", " +
                          float_literal(offsets[i].y) + "), documented (" + double_literal(documented[i].x) + ", " +
                          double_literal(documented[i].y) + ")");
    }
}

}  // namespace raster::properties
