// The tiling check: reference counts accumulated triangle by triangle over their bounding boxes, then one pass
// over the frame comparing them with what the implementation drew.
#include "properties/tiling_check.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>

#include "properties/reference/documented_samples.h"
#include "properties/failure.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {
namespace {

using reference::Point;

// The frame's samples by pixel, at their documented fixed-point positions.
struct SampleGrid {
    int width, height, samples, fixed_bits;
    std::vector<Point> offsets;

    explicit SampleGrid(const Frame& f)
        : width(f.width), height(f.height), samples(f.samples), fixed_bits(f.fixed_bits()),
          offsets(documented_fixed_offsets(f.samples, f.pattern, f.fixed_bits())) {}

    size_t index(int x, int y, int s) const {
        return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * static_cast<size_t>(samples) +
               static_cast<size_t>(s);
    }
    Point at(int x, int y, int s) const {
        return {(int64_t{x} << fixed_bits) + offsets[static_cast<size_t>(s)].x,
                (int64_t{y} << fixed_bits) + offsets[static_cast<size_t>(s)].y};
    }
    // Calls fn(index, position) for every sample of the pixels that the fixed-point box touches.
    template <class F>
    void for_each_in(int64_t x0, int64_t y0, int64_t x1, int64_t y1, F&& fn) const {
        const int px0 = static_cast<int>(std::clamp<int64_t>(x0 >> fixed_bits, 0, width - 1));
        const int px1 = static_cast<int>(std::clamp<int64_t>(x1 >> fixed_bits, 0, width - 1));
        const int py0 = static_cast<int>(std::clamp<int64_t>(y0 >> fixed_bits, 0, height - 1));
        const int py1 = static_cast<int>(std::clamp<int64_t>(y1 >> fixed_bits, 0, height - 1));
        for (int y = py0; y <= py1; ++y)
            for (int x = px0; x <= px1; ++x)
                for (int s = 0; s < samples; ++s) fn(index(x, y, s), at(x, y, s));
    }
    template <class F>
    void for_each_in(const std::vector<Point>& points, F&& fn) const {
        int64_t x0 = points[0].x, y0 = points[0].y, x1 = x0, y1 = y0;
        for (const Point& p : points) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        for_each_in(x0, y0, x1, y1, fn);
    }
};

std::string describe(const SampleGrid& grid, size_t index) {
    const size_t s = index % static_cast<size_t>(grid.samples), pixel = index / static_cast<size_t>(grid.samples);
    const int x = static_cast<int>(pixel % static_cast<size_t>(grid.width)), y = static_cast<int>(pixel / static_cast<size_t>(grid.width));
    const Point p = grid.at(x, y, static_cast<int>(s));
    std::ostringstream os;
    os << "sample " << s << " of pixel (" << x << ", " << y << ") at fixed (" << p.x << ", " << p.y << ")";
    return os.str();
}

}  // namespace

std::vector<uint32_t> coverage_owners(const Implementation& impl, const Frame& frame,
                                      const std::vector<ClipTriangle>& triangles) {
    std::vector<uint32_t> owners(static_cast<size_t>(frame.width) * frame.height * frame.samples, 0);
    for (size_t t = 0; t < triangles.size() && t < 32; ++t) {
        const VisibilityBuffer visibility = draw(impl, frame, {triangles[t]});
        for (size_t i = 0; i < visibility.size() && i < owners.size(); ++i)
            if (visibility.triangle[i] != kNoTriangle) owners[i] |= 1u << t;
    }
    return owners;
}

void check_tiling(const Implementation& impl, const TilingCase& c) {
    RC_CLASSIFY(true, c.kind);
    const Frame& frame = c.frame;
    const ScreenMesh& mesh = c.mesh;
    const std::vector<ClipTriangle> triangles = clip_triangles(frame, mesh);
    const std::vector<int> counts = coverage_counts(impl, frame, triangles);
    const SampleGrid grid(frame);

    const std::vector<Point> v = snapped_vertices(frame, mesh);

    // The reference, accumulated over each triangle's bounding box.
    std::vector<int> expected(counts.size(), 0);
    for (const auto& t : mesh.triangles) {
        const Point a = v[static_cast<size_t>(t[0])], b = v[static_cast<size_t>(t[1])], d = v[static_cast<size_t>(t[2])];
        grid.for_each_in({a, b, d}, [&](size_t i, Point p) { expected[i] += reference::reference_covers(a, b, d, p); });
    }

    // Samples exactly on a shared edge (two triangles name the same two vertices) or on an inside vertex.
    std::vector<char> shared(counts.size(), 0);
    std::map<std::pair<int, int>, int> edge_uses;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<size_t>(k)], b = t[static_cast<size_t>((k + 1) % 3)];
            ++edge_uses[{std::min(a, b), std::max(a, b)}];
        }
    int on_shared_edge = 0, on_shared_vertex = 0;
    for (const auto& [edge, uses] : edge_uses) {
        if (uses != 2) continue;
        const Point a = v[static_cast<size_t>(edge.first)], b = v[static_cast<size_t>(edge.second)];
        grid.for_each_in({a, b}, [&](size_t i, Point p) {
            if (reference::on_open_segment(a, b, p)) shared[i] = 1, ++on_shared_edge;
        });
    }
    for (int k : mesh.interior) {
        const Point a = v[static_cast<size_t>(k)];
        grid.for_each_in({a}, [&](size_t i, Point p) {
            if (p == a) shared[i] = 1, ++on_shared_vertex;
        });
    }
    RC_CLASSIFY(on_shared_edge > 0, "a sample exactly on a shared edge");
    RC_CLASSIFY(on_shared_vertex > 0, "a sample exactly on a shared vertex");

    std::vector<char> inside_outline;
    if (!mesh.outline.empty()) {
        std::vector<Point> outline;
        for (int k : mesh.outline) outline.push_back(v[static_cast<size_t>(k)]);
        inside_outline.assign(counts.size(), 0);
        grid.for_each_in(outline, [&](size_t i, Point p) { inside_outline[i] = reference::reference_polygon_covers(outline, p); });
    }

    int covered = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
        if (expected[i] > 1) fail_case("the reference covers " + describe(grid, i) + " twice: the generated triangles overlap");
        if (counts[i] != expected[i])
            fail_case(describe(grid, i) + " is covered " + std::to_string(counts[i]) + " times; the exact reference says " +
                    std::to_string(expected[i]));
        if (shared[i] && counts[i] != 1)
            fail_case(describe(grid, i) + " lies on a shared edge or vertex and is covered " + std::to_string(counts[i]) +
                    " times");
        if (!inside_outline.empty() && counts[i] != inside_outline[i])
            fail_case(describe(grid, i) + " is " + (inside_outline[i] ? "inside" : "outside") +
                    " the union's outline but covered " + std::to_string(counts[i]) + " times");
        covered += counts[i];
    }
    RC_CLASSIFY(covered == 0, "no sample covered");
}

}  // namespace raster::properties
