// The screen-space mesh generators: polygon fans, jittered grids and strips, pairs and fans through samples,
// single triangles on any frame or on N x N grid patterns, slivers of aspect 1e6 and sub-pixel triangles.
#include "properties/generators/screen_meshes.h"

#include <algorithm>
#include <cmath>

#include "properties/generators/frames.h"
#include "properties/generators/grid_mesh.h"
#include "properties/generators/primitives.h"

namespace raster::properties {
namespace {

using reference::Point;
using reference::orient;

}  // namespace

Gen<TilingCase> convex_polygon_fans() {
    return gen::exec([] {
        const Frame frame = *coverage_frames();
        const int bits = position_bits(frame);
        const Region region = *regions(frame, bits);
        const int count = *uniform(3, 12);
        const std::vector<Point> hull = convex_hull(*gen::suchThat(
            gen::exec([=] {
                std::vector<Point> points;
                for (int i = 0; i < count; ++i) points.push_back(point_in(region.box));
                return points;
            }),
            [](const std::vector<Point>& points) { return convex_hull(points).size() >= 3; }));
        GridMesh mesh;
        mesh.vertices = hull;
        const int n = static_cast<int>(hull.size());
        for (int i = 0; i < n; ++i) mesh.outline.push_back(i);
        // Fan from an inside point (the rounded centroid, when strictly inside), else from the first corner.
        Point centre{0, 0};
        for (const Point& p : hull) centre = {centre.x + p.x, centre.y + p.y};
        centre = {centre.x / n, centre.y / n};
        bool inside = *gen::weightedElement<int>({{1, 0}, {1, 1}}) == 1;
        for (int i = 0; inside && i < n; ++i) inside = orient(hull[i], hull[(i + 1) % n], centre) > 0;
        if (inside) {
            mesh.vertices.push_back(centre);
            mesh.interior.push_back(n);
            for (int i = 0; i < n; ++i) mesh.triangles.push_back({n, i, (i + 1) % n});
        } else {
            for (int i = 1; i + 1 < n; ++i) mesh.triangles.push_back({0, i, i + 1});
        }
        random_windings(mesh);
        place(mesh, frame, bits);
        return tiling_case("convex polygon in " + region.name + (inside ? ", fan from inside" : ", fan from a corner"),
                           frame, bits, mesh);
    });
}

Gen<TilingCase> jittered_grids() {
    return gen::exec([] {
        const Frame frame = *coverage_frames();
        const int bits = position_bits(frame);
        const Box all = frame_box(frame, bits);
        int n = *uniform(1, 6), m = *uniform(1, 6);
        // Jitter of at most min(cell)/5 per coordinate moves a vertex by at most 0.283 min(cell); a cell's vertex is
        // at least min(cell)/sqrt(2) = 0.707 min(cell) from the opposite diagonal, and a vertex plus the diagonal's
        // ends move it by at most 0.566 min(cell), so every quad stays strictly convex and either diagonal splits it.
        while (n > 1 && all.x1 / n < 5) --n;
        while (m > 1 && all.y1 / m < 5) --m;
        const bool small = *gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1;
        const int64_t cx = small ? *uniform<int64_t>(5, std::max<int64_t>(5, std::min<int64_t>(40, all.x1 / n)))
                                 : *uniform<int64_t>(std::min<int64_t>(5, all.x1 / n), all.x1 / n);
        const int64_t cy = small ? *uniform<int64_t>(5, std::max<int64_t>(5, std::min<int64_t>(40, all.y1 / m)))
                                 : *uniform<int64_t>(std::min<int64_t>(5, all.y1 / m), all.y1 / m);
        const int64_t jitter = std::min(cx, cy) / 5;
        const int64_t x0 = *uniform<int64_t>(0, std::max<int64_t>(0, all.x1 - n * cx));
        const int64_t y0 = *uniform<int64_t>(0, std::max<int64_t>(0, all.y1 - m * cy));
        GridMesh mesh;
        auto index = [&](int i, int j) { return j * (n + 1) + i; };
        for (int j = 0; j <= m; ++j)
            for (int i = 0; i <= n; ++i) {
                Point p{x0 + i * cx, y0 + j * cy};
                if (i > 0 && i < n && j > 0 && j < m) {
                    p = {p.x + *uniform(-jitter, jitter), p.y + *uniform(-jitter, jitter)};
                    mesh.interior.push_back(index(i, j));
                }
                mesh.vertices.push_back(p);
            }
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < n; ++i) {
                const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
                if (coin()) {
                    mesh.triangles.push_back({a, b, c});
                    mesh.triangles.push_back({a, c, d});
                } else {
                    mesh.triangles.push_back({a, b, d});
                    mesh.triangles.push_back({b, c, d});
                }
            }
        mesh.outline = {index(0, 0), index(n, 0), index(n, m), index(0, m)};
        random_windings(mesh);
        place(mesh, frame, bits);
        return tiling_case(small ? "grid of sub-pixel cells" : "grid of pixel cells", frame, bits, mesh);
    });
}

Gen<TilingCase> triangle_strips() {
    return gen::exec([] {
        const Frame frame = *coverage_frames();
        const int bits = position_bits(frame);
        const Box all = frame_box(frame, bits);
        const int segments = *uniform(1, 10);
        const int64_t max_step = std::max<int64_t>(1, all.x1 / segments);
        std::vector<int64_t> xs = {0};
        for (int i = 0; i < segments; ++i) xs.push_back(xs.back() + *uniform<int64_t>(1, max_step));
        const int64_t start = *uniform<int64_t>(0, std::max<int64_t>(0, all.x1 - xs.back()));
        GridMesh mesh;
        // Column i has its top vertex at 2i and its bottom one at 2i + 1; each column's quad has two vertical sides
        // and so is convex, split along the diagonal from its bottom-left to its top-right.
        for (int64_t x : xs) {
            const int64_t top = *uniform<int64_t>(0, all.y1 - 1);
            mesh.vertices.push_back({start + x, top});
            mesh.vertices.push_back({start + x, top + *uniform<int64_t>(1, all.y1 - top)});
        }
        for (int i = 0; i < segments; ++i) {
            mesh.triangles.push_back({2 * i, 2 * i + 1, 2 * i + 2});
            mesh.triangles.push_back({2 * i + 1, 2 * i + 3, 2 * i + 2});
        }
        random_windings(mesh);
        place(mesh, frame, bits);
        return tiling_case(segments == 1 ? "strip of two triangles" : "strip", frame, bits, mesh);
    });
}

Gen<TilingCase> pairs_sharing_an_edge_through_samples() {
    return gen::exec([] { return pair_through_samples(*sample_aligned_frames()); });
}

Gen<TilingCase> symmetric_pairs_sharing_an_edge() {
    return gen::exec([] { return pair_through_samples(*symmetric_frames()); });
}

Gen<TilingCase> fans_around_a_sample() {
    return gen::exec([] {
        const Frame frame = *gen::suchThat(sample_aligned_frames(), [](const Frame& f) {
            return f.width == f.height && f.width >= 16;
        });
        const int bits = position_bits(frame);
        const Point centre = random_sample_point(frame, bits, 5);
        const bool small = *gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1;
        const int64_t pixel = int64_t{1} << bits;
        // Every ring vertex stays within 4 px of the centre, so inside the frame: the tiling check compares with the
        // unclipped reference, so no triangle may reach past the viewport (a counterexample once did at 1 snap bit,
        // where 40 grid units are 20 px: Regressions.fanAroundASampleReachingPastTheViewportStaysWatertight).
        const int64_t r_lo = small ? std::min<int64_t>(8, pixel) : pixel, r_hi = small ? std::min<int64_t>(40, 4 * pixel) : 4 * pixel;
        const int k = *uniform(3, small ? 6 : 9);
        // Angles 2 pi (i + jitter) / k with |jitter| <= 0.3 keep every gap under pi for k >= 3; rounding the ring
        // vertices to the grid can still fold a small fan, so the ring is checked: every triangle strictly turns the
        // same way and the gaps add up to one full turn.
        const std::vector<Point> ring = *gen::suchThat(
            gen::exec([=] {
                const double phase = unit() * 2.0 * kPi;
                std::vector<Point> points;
                for (int i = 0; i < k; ++i) {
                    const double angle = phase + 2.0 * kPi * (i + 0.6 * unit() - 0.3) / k;
                    const double r = static_cast<double>(*uniform(r_lo, r_hi));
                    points.push_back({centre.x + std::llround(r * std::cos(angle)), centre.y + std::llround(r * std::sin(angle))});
                }
                return points;
            }),
            [=](const std::vector<Point>& points) {
                double turn = 0.0;
                for (int i = 0; i < k; ++i) {
                    const Point a = points[i], b = points[(i + 1) % k];
                    if (orient(centre, a, b) <= 0) return false;
                    const double ta = std::atan2(double(a.y - centre.y), double(a.x - centre.x));
                    const double tb = std::atan2(double(b.y - centre.y), double(b.x - centre.x));
                    double gap = tb - ta;
                    while (gap <= 0) gap += 2.0 * kPi;
                    turn += gap;
                }
                return std::fabs(turn - 2.0 * kPi) < 1e-6;
            });
        GridMesh mesh;
        mesh.vertices.push_back(centre);
        mesh.interior.push_back(0);
        for (const Point& p : ring) mesh.vertices.push_back(p);
        for (int i = 0; i < k; ++i) mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % k});
        random_windings(mesh);
        return tiling_case(small ? "fan around a sample, sub-pixel ring" : "fan around a sample, pixel ring", frame, bits, mesh);
    });
}

Gen<TilingCase> single_triangles() {
    return gen::exec([] {
        const Frame frame = *coverage_frames();
        NamedMesh named = *single_triangle_meshes(frame);
        place(named.mesh, frame, named.bits);
        return tiling_case(named.name, frame, named.bits, named.mesh);
    });
}

Gen<TilingCase> grid_sampled_triangles() {
    return gen::exec([] {
        const int n = *gen::weightedOneOf<int>({{3, uniform(1, 6)}, {1, uniform(7, 16)}});
        const int side = *gen::element(16, 32);
        const Frame frame = frame_of(side, side, {n * n, SamplePattern::grid}, kDefaultSnapBits);
        NamedMesh named = *single_triangle_meshes(frame);
        place(named.mesh, frame, named.bits);
        return tiling_case(named.name + (n <= 6 ? ", grid up to 6x6" : ", grid 7x7 to 16x16"), frame, named.bits, named.mesh);
    });
}

Gen<TilingCase> sliver_pairs() {
    return gen::exec([] {
        // Along the long side of a 16384 x 4 frame, or across a 32 x 32 one, at 16 sub-pixel bits.
        const bool wide = *gen::weightedElement<int>({{2, 1}, {1, 0}}) == 1;
        const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard},
                                                  SampleChoice{4, SamplePattern::standard});
        Frame frame = wide ? frame_of(16384, 4, choice, 16) : frame_of(32, 32, choice, 16);
        const int bits = position_bits(frame);
        const Box all = frame_box(frame, bits);
        const bool through_samples = coin();
        Point a{*uniform<int64_t>(0, all.x1 / 8), 0}, b{*uniform<int64_t>(all.x1 * 7 / 8, all.x1), 0};
        if (through_samples) {
            // A horizontal long edge along a row of samples.
            const Point s = sample_point(frame, bits, 0, *uniform(1, frame.height - 2), *uniform(0, frame.samples - 1));
            a.y = b.y = s.y;
        } else {
            a.y = *uniform<int64_t>(all.y1 / 4, all.y1 * 3 / 4);
            b.y = *uniform<int64_t>(all.y1 / 4, all.y1 * 3 / 4);
        }
        // Third vertices about length / 1e6 off the edge on either side: aspect ratio ~1e6.
        const double length = std::hypot(double(b.x - a.x), double(b.y - a.y));
        auto off_edge = [=](int sign) {
            return *gen::suchThat(gen::exec([=] {
                                      const double t = 0.05 + 0.9 * unit();
                                      const int64_t h = std::max<int64_t>(2, std::llround(length / 1e6 * (0.5 + 1.5 * unit())));
                                      return Point{a.x + std::llround(t * double(b.x - a.x)),
                                                   a.y + std::llround(t * double(b.y - a.y)) + sign * h};
                                  }),
                                  [=](Point p) { return orient(a, b, p) * sign > 0 && p.y >= 0 && p.y <= all.y1; });
        };
        GridMesh mesh;
        mesh.vertices = {a, b, off_edge(1), off_edge(-1)};
        mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
        random_windings(mesh);
        if (wide && (!through_samples || frame.samples == 1) && coin()) {  // the same in a 4 x 16384 frame
            frame = frame_of(4, 16384, choice, 16);
            for (Point& p : mesh.vertices) p = {p.y, p.x};
        }
        return tiling_case(std::string("slivers of aspect 1e6 ") + (wide ? "16384 px long" : "32 px long") +
                               (through_samples ? ", edge along a sample row" : ""),
                           frame, bits, mesh);
    });
}

Gen<TilingCase> sub_pixel_triangles() {
    return gen::exec([] {
        const Frame frame = *sample_aligned_frames();
        const int bits = position_bits(frame);
        const Point s = random_sample_point(frame, bits, 1);
        return *gen::weightedOneOf<TilingCase>({
            {2, gen::exec([=] {
                 // Within one snap unit (under 1/2^snap_bits px), on the finer exact grid.
                 const int fine = frame.exact_bits(), shift = std::max(0, fine - bits);
                 const Box box{s.x << shift, s.y << shift, (s.x << shift) + (int64_t{1} << shift),
                               (s.y << shift) + (int64_t{1} << shift)};
                 GridMesh mesh = one_triangle(point_in(box), point_in(box), point_in(box));
                 return tiling_case("smaller than one sub-pixel unit, at a sample", frame, fine, mesh);
             })},
            {2, gen::exec([=] {
                 auto near_s = [&] { return Point{s.x + *uniform(-2, 2), s.y + *uniform(-2, 2)}; };
                 return tiling_case("a few sub-pixel units around a sample", frame, bits,
                                    one_triangle(near_s(), near_s(), near_s()));
             })},
            {1, gen::exec([=] {
                 const int64_t reach = std::max<int64_t>(1, (int64_t{1} << bits) * 45 / 100);
                 auto near_s = [&] { return Point{s.x + *uniform(-reach, reach), s.y + *uniform(-reach, reach)}; };
                 return tiling_case("under one square pixel around a sample", frame, bits,
                                    one_triangle(near_s(), near_s(), near_s()));
             })},
        });
    });
}

}  // namespace raster::properties
