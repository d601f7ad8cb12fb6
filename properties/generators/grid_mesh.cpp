// Meshes built on the integer grid of a frame: boxes and regions, convex hulls, random windings and placements,
// samples as grid points, pairs sharing an edge through samples, and the kinds of single triangle.
#include "properties/generators/grid_mesh.h"

#include <algorithm>
#include <cmath>

#include "properties/generators/primitives.h"
#include "properties/generators/square_symmetries.h"
#include "properties/reference/documented_samples.h"

namespace raster::properties {
namespace {

using reference::orient;
using reference::Point;

// View depths for the vertices: all at w = 1, or each at its own power of two in [1/8, 64] (inside the default
// clip volume, and exact: a power-of-two w moves no vertex).
std::vector<float> vertex_depths(size_t count, bool& perspective) {
    perspective = *gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1;
    std::vector<float> w(count, 1.0f);
    if (perspective)
        for (float& x : w) x = std::ldexp(1.0f, *uniform(-3, 6));
    return w;
}

// Two triangles A B C and B A D sharing edge A-B, with C and D on opposite sides, inside `bounds`.
GridMesh pair_sharing(Point a, Point b, const Box& bounds) {
    // Generators are run again while shrinking, after this function returns: everything they use is captured by
    // value (so it is in every generator of properties/generators/).
    auto on_side = [=](int sign) {
        return *gen::suchThat(gen::exec([=] { return point_in(bounds); }),
                              [=](Point p) { return orient(a, b, p) * sign > 0; });
    };
    GridMesh mesh;
    mesh.vertices = {a, b, on_side(1), on_side(-1)};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
    random_windings(mesh);
    return mesh;
}

}  // namespace

Box frame_box(const Frame& frame, int bits) {
    return {0, 0, int64_t{frame.width} << bits, int64_t{frame.height} << bits};
}

Gen<Region> regions(const Frame& frame, int bits) {
    const Box all = frame_box(frame, bits);
    auto sub_box = [all](const char* name, int64_t min_size, int64_t max_size) {
        return gen::exec([=] {
            const int64_t w = std::min(*uniform(min_size, max_size), all.x1);
            const int64_t h = std::min(*uniform(min_size, max_size), all.y1);
            const int64_t x0 = *uniform<int64_t>(0, all.x1 - w), y0 = *uniform<int64_t>(0, all.y1 - h);
            return Region{name, {x0, y0, x0 + w, y0 + h}};
        });
    };
    const int64_t pixel = int64_t{1} << bits;
    return gen::weightedOneOf<Region>({{3, gen::just(Region{"whole frame", all})},
                                       {2, sub_box("a few pixels", pixel, 8 * pixel)},
                                       {1, sub_box("a few grid units", 2, 40)}});
}

Point point_in(const Box& box) { return {*uniform(box.x0, box.x1), *uniform(box.y0, box.y1)}; }

std::vector<Point> convex_hull(std::vector<Point> points) {
    std::sort(points.begin(), points.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return {};
    std::vector<Point> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && orient(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && orient(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull.size() >= 3 ? hull : std::vector<Point>{};
}

void random_windings(GridMesh& mesh) {
    for (auto& t : mesh.triangles)
        if (coin()) std::swap(t[1], t[2]);
}

void place(GridMesh& mesh, const Frame& frame, int bits) {
    const Box all = frame_box(frame, bits);
    const auto& symmetries = all_symmetries();
    const size_t choices = frame.width == frame.height ? symmetries.size() : 4;
    const FrameSymmetry& g = symmetries[static_cast<size_t>(*uniform<int>(0, static_cast<int>(choices) - 1))];
    // p' = M (p - c) + c with c the frame's centre, exact in integers (2c = (x1, y1)).
    for (Point& p : mesh.vertices) {
        const int64_t dx = 2 * p.x - all.x1, dy = 2 * p.y - all.y1;
        p = {(g.m[0] * dx + g.m[1] * dy + all.x1) / 2, (g.m[2] * dx + g.m[3] * dy + all.y1) / 2};
    }
    int64_t min_x = all.x1, min_y = all.y1, max_x = 0, max_y = 0;
    for (const Point& p : mesh.vertices) {
        min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
    const int64_t pixel = int64_t{1} << bits;
    const int64_t sx = *uniform(std::max(-pixel, -min_x), std::min(pixel, all.x1 - max_x));
    const int64_t sy = *uniform(std::max(-pixel, -min_y), std::min(pixel, all.y1 - max_y));
    for (Point& p : mesh.vertices) p = {p.x + sx, p.y + sy};
}

TilingCase tiling_case(std::string kind, const Frame& frame, int bits, const GridMesh& grid) {
    TilingCase c;
    c.frame = frame;
    bool perspective = false;
    c.mesh.w = vertex_depths(grid.vertices.size(), perspective);
    c.kind = std::move(kind) + (perspective ? ", in perspective" : "");
    const double unit = std::ldexp(1.0, -bits);
    for (const Point& p : grid.vertices) c.mesh.vertices.push_back({static_cast<double>(p.x) * unit, static_cast<double>(p.y) * unit});
    c.mesh.triangles = grid.triangles;
    c.mesh.outline = grid.outline;
    c.mesh.interior = grid.interior;
    return c;
}

Point sample_point(const Frame& frame, int bits, int x, int y, int s) {
    const int shift = frame.fixed_bits() - bits;
    const Point o = documented_fixed_offsets(frame.samples, frame.pattern, frame.fixed_bits())[static_cast<size_t>(s)];
    return {(int64_t{x} << bits) + (o.x >> shift), (int64_t{y} << bits) + (o.y >> shift)};
}

Point random_sample_point(const Frame& frame, int bits, int margin) {
    const int mx = std::min(margin, (frame.width - 1) / 2), my = std::min(margin, (frame.height - 1) / 2);
    return sample_point(frame, bits, *uniform(mx, frame.width - 1 - mx), *uniform(my, frame.height - 1 - my),
                        *uniform(0, frame.samples - 1));
}

TilingCase pair_through_samples(const Frame& frame) {
    const int bits = position_bits(frame);
    struct Direction {
        const char* name;
        int dx, dy;
    };
    const Direction d = *gen::weightedOneOf<Direction>({
        {2, gen::exec([] { return Direction{"horizontal", coin() ? 1 : -1, 0}; })},
        {2, gen::exec([] { return Direction{"vertical", 0, coin() ? 1 : -1}; })},
        {1, gen::exec([] { return Direction{"diagonal", coin() ? 1 : -1, coin() ? 1 : -1}; })},
        {2, gen::suchThat(gen::exec([] { return Direction{"any slope", *uniform(-3, 3), *uniform(-3, 3)}; }),
                          [](const Direction& x) { return x.dx != 0 || x.dy != 0; })},
    });
    // Steps of one direction vector from pixel to pixel; at least two so the open edge holds a sample.
    auto fits = [&](int steps) {
        return std::abs(d.dx) * steps <= frame.width - 3 && std::abs(d.dy) * steps <= frame.height - 3;
    };
    int steps = *uniform(2, 5);
    while (steps > 2 && !fits(steps)) --steps;
    Direction dir = d;
    if (!fits(steps)) {  // along the frame's long side, which always has room for two steps
        dir = frame.width >= frame.height ? Direction{"horizontal", 1, 0} : Direction{"vertical", 0, 1};
        steps = 2;
    }
    const int x_lo = 1 + std::max(0, -dir.dx * steps), x_hi = frame.width - 2 - std::max(0, dir.dx * steps);
    const int y_lo = 1 + std::max(0, -dir.dy * steps), y_hi = frame.height - 2 - std::max(0, dir.dy * steps);
    const int px = *uniform(x_lo, x_hi), py = *uniform(y_lo, y_hi), s = *uniform(0, frame.samples - 1);
    const Point a = sample_point(frame, bits, px, py, s);
    const Point b = sample_point(frame, bits, px + dir.dx * steps, py + dir.dy * steps, s);
    const int64_t reach = int64_t{*uniform(1, 4)} << bits;
    const Box all = frame_box(frame, bits);
    const Box bounds{std::max<int64_t>(0, std::min(a.x, b.x) - reach), std::max<int64_t>(0, std::min(a.y, b.y) - reach),
                     std::min(all.x1, std::max(a.x, b.x) + reach), std::min(all.y1, std::max(a.y, b.y) + reach)};
    return tiling_case(std::string("shared ") + dir.name + " edge through samples", frame, bits,
                       pair_sharing(a, b, bounds));
}

GridMesh one_triangle(Point a, Point b, Point c) {
    GridMesh mesh;
    mesh.vertices = {a, b, c};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

Gen<NamedMesh> single_triangle_meshes(const Frame& frame) {
    const int bits = position_bits(frame);
    const Box all = frame_box(frame, bits);
    auto named = [bits](const char* name, auto make) {
        return gen::exec([=] { return NamedMesh{name, make(), bits}; });
    };
    return gen::weightedOneOf<NamedMesh>({
        {4, gen::exec([=] {
             const Region r = *regions(frame, bits);
             return NamedMesh{"random in " + r.name, one_triangle(point_in(r.box), point_in(r.box), point_in(r.box)), bits};
         })},
        {2, named("axis-aligned edges", [=] {
             const Region r = *regions(frame, bits);
             const Point a = point_in(r.box), b = point_in(r.box);
             return one_triangle(a, {b.x, a.y}, {a.x, b.y});
         })},
        {1, named("sliver", [=] {
             const Point a = point_in(all), b = point_in(all);
             const double t = unit();
             const Point c{a.x + std::llround(t * static_cast<double>(b.x - a.x)) + *uniform(-2, 2),
                           a.y + std::llround(t * static_cast<double>(b.y - a.y)) + *uniform(-2, 2)};
             return one_triangle(a, b, {std::clamp<int64_t>(c.x, 0, all.x1), std::clamp<int64_t>(c.y, 0, all.y1)});
         })},
        {1, named("tiny", [=] {
             const Point a = point_in(all);
             const Box near_a{a.x, a.y, std::min(all.x1, a.x + 4), std::min(all.y1, a.y + 4)};
             return one_triangle(a, point_in(near_a), point_in(near_a));
         })},
        {1, named("vertices on pixel centres", [=] {
             auto centre = [&] {
                 return Point{(int64_t{*uniform(0, frame.width - 1)} << bits) + (int64_t{1} << bits >> 1),
                              (int64_t{*uniform(0, frame.height - 1)} << bits) + (int64_t{1} << bits >> 1)};
             };
             return one_triangle(centre(), centre(), centre());
         })},
        {1, gen::exec([=] {
             // On the finer exact grid, so setup's snapping (round half up) is exercised too.
             const int fine = frame.exact_bits();
             const Box fine_all = frame_box(frame, fine);
             const Point a = point_in(fine_all);
             const int64_t reach = int64_t{*uniform(1, 8)} << fine;  // up to 8 px
             const Box around{std::max<int64_t>(0, a.x - reach), std::max<int64_t>(0, a.y - reach),
                              std::min(fine_all.x1, a.x + reach), std::min(fine_all.y1, a.y + reach)};
             return NamedMesh{"off the snap grid", one_triangle(a, point_in(around), point_in(around)), fine};
         })},
    });
}

}  // namespace raster::properties
