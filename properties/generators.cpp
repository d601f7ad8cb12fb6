// The generators: frames, screen-space meshes, clip-space and view-space triangles, cameras, lenses, models,
// scenes and lights. Sizes are drawn uniformly (not scaled by RapidCheck's size), so every case is a full draw;
// the hand-picked extremes come in through weightedOneOf and every case names its kind.
#include "properties/generators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <glm/geometric.hpp>

#include "properties/reference/documented_samples.h"
#include "properties/printing.h"
#include "raster/pipeline/render.h"
#include "raster/scene/validation.h"

namespace raster::properties {
namespace {

namespace gen = rc::gen;
using rc::Gen;
using reference::orient;
using reference::Point;

constexpr double kPi = 3.14159265358979323846;

// --- primitives ------------------------------------------------------------------------------------------------

// Uniform in [lo, hi], inclusive, at full size whatever RapidCheck's current size; shrinks towards lo.
template <class T>
Gen<T> uniform(T lo, T hi) {
    return gen::resize(100, gen::inRange<T>(lo, static_cast<T>(hi + 1)));
}

// Uniform in [0, 1) on a grid of 2^-24.
double unit() { return std::ldexp(static_cast<double>(*uniform<int64_t>(0, (int64_t{1} << 24) - 1)), -24); }

// Log-uniform in [lo, hi] (lo > 0).
double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }

bool coin() { return *uniform<int>(0, 1) == 1; }

// --- frames --------------------------------------------------------------------------------------------------

struct SampleChoice {
    int samples;
    SamplePattern pattern;
};

Gen<SampleChoice> sample_choices() {
    return gen::weightedElement<SampleChoice>({{3, {1, SamplePattern::standard}},
                                               {1, {2, SamplePattern::standard}},
                                               {2, {4, SamplePattern::standard}},
                                               {1, {8, SamplePattern::standard}},
                                               {1, {16, SamplePattern::standard}},
                                               {1, {4, SamplePattern::grid}},
                                               {1, {9, SamplePattern::grid}},
                                               {1, {25, SamplePattern::grid}}});
}

Frame frame_of(int width, int height, SampleChoice choice, int snap_bits) {
    Frame frame;
    frame.width = width;
    frame.height = height;
    frame.samples = choice.samples;
    frame.pattern = choice.pattern;
    frame.snap_bits = snap_bits;
    return frame;
}

// Small square frames at the default precision, coarse and fine snapping, and extents at the limit of the
// fixed-point range: 16384 pixels along one side at 16 sub-pixel bits is 2^30 fixed-point units (conventions.h).
Gen<Frame> coverage_frames() {
    return gen::weightedOneOf<Frame>({
        {6, gen::exec([] {
             const int side = *gen::element(16, 32, 64);
             return frame_of(side, side, *sample_choices(), kDefaultSnapBits);
         })},
        {1, gen::exec([] { return frame_of(32, 32, *sample_choices(), *uniform(1, 4)); })},
        {1, gen::exec([] { return frame_of(32, 32, *sample_choices(), *gen::element(12, 16)); })},
        {1, gen::exec([] {
             const int snap = *gen::element(8, 16);
             const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard},
                                                       SampleChoice{4, SamplePattern::standard});
             return coin() ? frame_of(16384, 4, choice, snap) : frame_of(4, 16384, choice, snap);
         })},
    });
}

// Bits of the grid vertices are placed on: the snap grid, unless floats cannot hold it exactly.
int position_bits(const Frame& frame) { return std::min(frame.snap_bits, frame.exact_bits()); }

// Do the frame's documented sample positions lie on its position grid (so a vertex can be put on a sample)?
bool samples_on_position_grid(const Frame& frame) {
    const int shift = frame.fixed_bits() - position_bits(frame);
    if (shift < 0) return false;
    const int64_t mask = (int64_t{1} << shift) - 1;
    for (const Point& o : documented_fixed_offsets(frame.samples, frame.pattern, frame.fixed_bits()))
        if ((o.x & mask) || (o.y & mask)) return false;
    return true;
}

Gen<Frame> sample_aligned_frames() { return gen::suchThat(coverage_frames(), samples_on_position_grid); }

// Square frames whose sample pattern maps onto itself under mirrors and quarter turns: one sample at the pixel
// centre, or an N x N grid at 8 or more bits (no offset rounds half-way, so the rounded grid stays symmetric).
Gen<Frame> symmetric_frames() {
    return gen::exec([] {
        const int side = *gen::element(16, 32);
        const int n = *gen::weightedElement<int>({{3, 1}, {2, 2}, {2, 3}, {1, 4}, {1, 5}, {1, 16}});
        return frame_of(side, side, {n * n, n == 1 ? SamplePattern::standard : SamplePattern::grid},
                        *gen::element(8, 12, 16));
    });
}

// --- integer-grid mesh building --------------------------------------------------------------------------------

struct Box {
    int64_t x0, y0, x1, y1;  // inclusive, in grid units
};

Box frame_box(const Frame& frame, int bits) {
    return {0, 0, int64_t{frame.width} << bits, int64_t{frame.height} << bits};
}

// A box inside the frame: the whole frame, a few pixels, or a few grid units.
struct Region {
    std::string name;
    Box box;
};

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

// A triangulated region on the integer grid (units of 2^-bits pixel).
struct GridMesh {
    std::vector<Point> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> outline, interior;
};

// Strictly convex hull (Andrew's monotone chain, collinear points dropped), counter-clockwise in y-up terms.
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

// Each triangle's winding flipped at random (setup must handle both).
void random_windings(GridMesh& mesh) {
    for (auto& t : mesh.triangles)
        if (coin()) std::swap(t[1], t[2]);
}

// The eight symmetries of the square (identity first).
const std::vector<FrameSymmetry>& all_symmetries() {
    static const std::vector<FrameSymmetry> list = {
        {"identity", {1, 0, 0, 1}},        {"mirror x", {-1, 0, 0, 1}},      {"mirror y", {1, 0, 0, -1}},
        {"half turn", {-1, 0, 0, -1}},     {"quarter turn", {0, -1, 1, 0}},  {"three-quarter turn", {0, 1, -1, 0}},
        {"transpose", {0, 1, 1, 0}},       {"anti-transpose", {0, -1, -1, 0}}};
    return list;
}

// Puts the mesh in a random orientation (any symmetry of a square frame; mirrors and the half turn otherwise)
// and shifts it by up to a pixel, staying inside the frame.
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

// View depths for the vertices: all at w = 1, or each at its own power of two in [1/8, 64] (inside the default
// clip volume, and exact: a power-of-two w moves no vertex).
std::vector<float> vertex_depths(size_t count, bool& perspective) {
    perspective = *gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1;
    std::vector<float> w(count, 1.0f);
    if (perspective)
        for (float& x : w) x = std::ldexp(1.0f, *uniform(-3, 6));
    return w;
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

// A documented sample position of pixel (x, y), in grid units (the frame must be sample-aligned).
Point sample_point(const Frame& frame, int bits, int x, int y, int s) {
    const int shift = frame.fixed_bits() - bits;
    const Point o = documented_fixed_offsets(frame.samples, frame.pattern, frame.fixed_bits())[static_cast<size_t>(s)];
    return {(int64_t{x} << bits) + (o.x >> shift), (int64_t{y} << bits) + (o.y >> shift)};
}

// A random sample of the frame at least `margin` pixels from its border (where the frame allows), in grid units.
Point random_sample_point(const Frame& frame, int bits, int margin) {
    const int mx = std::min(margin, (frame.width - 1) / 2), my = std::min(margin, (frame.height - 1) / 2);
    return sample_point(frame, bits, *uniform(mx, frame.width - 1 - mx), *uniform(my, frame.height - 1 - my),
                        *uniform(0, frame.samples - 1));
}

// Two triangles A B C and B A D sharing edge A-B, with C and D on opposite sides, inside `bounds`.
GridMesh pair_sharing(Point a, Point b, const Box& bounds) {
    // Generators are run again while shrinking, after this function returns: everything they use is captured by
    // value (so it is in every generator of this file).
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

// A pair sharing an edge that runs from one sample through further samples of the same index.
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

// One triangle of the given kind, in grid units.
GridMesh one_triangle(Point a, Point b, Point c) {
    GridMesh mesh;
    mesh.vertices = {a, b, c};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

struct NamedMesh {
    std::string name;
    GridMesh mesh;
    int bits;
};

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

std::string describe_points(const std::vector<glm::dvec2>& points) {
    std::string s = "{";
    for (size_t i = 0; i < points.size(); ++i) s += (i ? ", " : "") + literal(points[i]);
    return s + "}";
}

// A clip-space vertex inside the volume at view depth w: x = a w, y = b w with a, b in [-1, 1].
glm::vec4 inside_vertex(float w, double a, double b) {
    return {static_cast<float>(a * w), static_cast<float>(b * w), 0.5f * w, w};
}

double signed_unit() { return 2.0 * unit() - 1.0; }

// View depths for clip tests: log-uniform over the volume (capped at 1e4 times near, where near is tiny).
float depth_in(const ClipVolume& v) {
    return static_cast<float>(std::min<double>(v.far, log_uniform(v.near, std::min<double>(v.far, v.near * 1e4 + 1.0))));
}

Gen<ClipVolume> volumes() {
    return gen::weightedOneOf<ClipVolume>({
        {3, gen::just(ClipVolume{0.1f, 100.0f})},
        {1, gen::just(ClipVolume{1e-6f, 1e9f})},
        {2, gen::exec([] {
             const float near = static_cast<float>(log_uniform(1e-3, 1.0));
             return ClipVolume{near, static_cast<float>(near * log_uniform(10.0, 1e4))};
         })},
    });
}

Gen<Frame> clip_frames() {
    return gen::exec([] {
        const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard},
                                                  SampleChoice{4, SamplePattern::standard},
                                                  SampleChoice{9, SamplePattern::grid});
        Frame frame = frame_of(*gen::element(16, 32), 0, choice, kDefaultSnapBits);
        frame.height = frame.width;
        frame.volume = *volumes();
        return frame;
    });
}

ClipCase clip_case(std::string kind, const Frame& frame, glm::vec4 a, glm::vec4 b, glm::vec4 c) {
    // The drawing order of the vertices is random too (which one comes first matters to clipping).
    ClipTriangle t{{a, b, c}};
    const int rotate = *uniform(0, 2);
    std::rotate(t.v.begin(), t.v.begin() + rotate, t.v.end());
    if (coin()) std::swap(t.v[1], t.v[2]);
    return {std::move(kind), frame, t};
}

// A view-space point that a 90-degree lens with the frame's aspect projects onto `screen` at view depth w.
glm::vec3 view_point(const Frame& frame, const glm::dvec2& screen, double w) {
    const glm::dvec2 ndc = ndc_of_screen(frame, screen);
    const double aspect = static_cast<double>(frame.width) / frame.height;
    return {static_cast<float>(ndc.x * w * aspect), static_cast<float>(ndc.y * w), static_cast<float>(-w)};
}

glm::dvec2 screen_point_inside(const Frame& frame, double margin) {
    return {margin + unit() * (frame.width - 2 * margin), margin + unit() * (frame.height - 2 * margin)};
}

glm::vec3 random_vector(double scale) {
    return {static_cast<float>(scale * signed_unit()), static_cast<float>(scale * signed_unit()),
            static_cast<float>(scale * signed_unit())};
}

glm::vec3 random_direction() {
    const double z = signed_unit(), phi = 2.0 * kPi * unit(), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z)};
}

}  // namespace

// --- printing ------------------------------------------------------------------------------------------------

std::ostream& operator<<(std::ostream& os, const TilingCase& c) {
    os << "TilingCase{\"" << c.kind << "\", " << c.frame << ", ScreenMesh{" << describe_points(c.mesh.vertices) << ", {";
    for (size_t i = 0; i < c.mesh.w.size(); ++i) os << (i ? ", " : "") << float_literal(c.mesh.w[i]);
    os << "}, {";
    for (size_t i = 0; i < c.mesh.triangles.size(); ++i)
        os << (i ? ", " : "") << "{" << c.mesh.triangles[i][0] << ", " << c.mesh.triangles[i][1] << ", "
           << c.mesh.triangles[i][2] << "}";
    os << "}, {";
    for (size_t i = 0; i < c.mesh.outline.size(); ++i) os << (i ? ", " : "") << c.mesh.outline[i];
    os << "}, {";
    for (size_t i = 0; i < c.mesh.interior.size(); ++i) os << (i ? ", " : "") << c.mesh.interior[i];
    return os << "}}}";
}

std::ostream& operator<<(std::ostream& os, const FrameSymmetry& g) { return os << g.name; }

std::ostream& operator<<(std::ostream& os, const ClipCase& c) {
    return os << "ClipCase{\"" << c.kind << "\", " << c.frame << ", " << c.triangle << "}";
}

std::ostream& operator<<(std::ostream& os, const LayeredCase& c) {
    os << "LayeredCase{\"" << c.kind << "\", " << c.frame << ", {";
    for (size_t i = 0; i < c.triangles.size(); ++i)
        os << (i ? ", " : "") << "{" << literal(c.triangles[i].v[0]) << ", " << literal(c.triangles[i].v[1]) << ", "
           << literal(c.triangles[i].v[2]) << "}";
    os << "}, {";
    for (size_t i = 0; i < c.order.size(); ++i) os << (i ? ", " : "") << c.order[i];
    return os << "}}";
}

std::ostream& operator<<(std::ostream& os, const CameraCase& c) {
    return os << "CameraCase{\"" << c.kind << "\", " << literal(c.eye) << ", " << literal(c.target) << ", "
              << literal(c.up) << "}";
}

std::ostream& operator<<(std::ostream& os, const LensCase& c) {
    return os << "LensCase{\"" << c.kind << "\", " << float_literal(c.fov_y_degrees) << ", " << float_literal(c.aspect)
              << ", " << float_literal(c.near) << ", " << float_literal(c.far) << ", " << c.width << ", " << c.height
              << ", " << float_literal(c.depth) << ", " << float_literal(c.farther) << ", glm::vec2("
              << float_literal(c.across.x) << ", " << float_literal(c.across.y) << ")}";
}

std::ostream& operator<<(std::ostream& os, const ModelCase& c) {
    return os << "ModelCase{\"" << c.kind << "\", {" << literal(c.chain.scale) << ", " << float_literal(c.chain.degrees)
              << ", " << literal(c.chain.axis) << ", " << literal(c.chain.offset) << "}, {" << literal(c.triangle[0])
              << ", " << literal(c.triangle[1]) << ", " << literal(c.triangle[2]) << "}}";
}

std::ostream& operator<<(std::ostream& os, const DepthPairCase& c) {
    return os << "DepthPairCase{\"" << c.kind << "\", " << float_literal(c.near_depth) << ", "
              << float_literal(c.far_depth) << ", " << (c.nearer_first ? "true" : "false") << "}";
}

std::ostream& operator<<(std::ostream& os, const ScaledSceneCase& c) {
    return os << "ScaledSceneCase{\"" << c.kind << "\", " << c.exponent << ", {" << literal(c.triangle[0]) << ", "
              << literal(c.triangle[1]) << ", " << literal(c.triangle[2]) << "}, " << literal(c.eye) << ", "
              << literal(c.target) << ", " << float_literal(c.near) << ", " << float_literal(c.far) << "}";
}

std::ostream& operator<<(std::ostream& os, const LightCase& c) {
    return os << "LightCase{\"" << c.kind << "\", " << literal(c.normal) << ", " << literal(c.direction) << ", "
              << float_literal(c.distance) << ", " << literal(c.color) << "}";
}

// --- screen-space meshes ---------------------------------------------------------------------------------------

std::vector<reference::Point> snapped_vertices(const Frame& frame, const ScreenMesh& mesh) {
    std::vector<reference::Point> v;
    for (size_t i = 0; i < mesh.vertices.size(); ++i) v.push_back(snapped(frame, clip_from_screen(frame, mesh.vertices[i], mesh.w[i])));
    return v;
}

std::vector<ClipTriangle> clip_triangles(const Frame& frame, const ScreenMesh& mesh) {
    std::vector<ClipTriangle> out;
    for (const auto& t : mesh.triangles) {
        ClipTriangle c;
        for (int i = 0; i < 3; ++i) {
            const auto v = static_cast<size_t>(t[static_cast<size_t>(i)]);
            c.v[static_cast<size_t>(i)] = clip_from_screen(frame, mesh.vertices[v], mesh.w[v]);
        }
        out.push_back(c);
    }
    return out;
}

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

const std::vector<FrameSymmetry>& square_symmetries() {
    static const std::vector<FrameSymmetry> list(all_symmetries().begin() + 1, all_symmetries().end());
    return list;
}

glm::dvec2 apply(const FrameSymmetry& g, const Frame& frame, const glm::dvec2& p) {
    const double cx = 0.5 * frame.width, cy = 0.5 * frame.height;
    const double dx = p.x - cx, dy = p.y - cy;
    return {g.m[0] * dx + g.m[1] * dy + cx, g.m[2] * dx + g.m[3] * dy + cy};
}

// --- clip space ------------------------------------------------------------------------------------------------

Gen<ClipCase> perspective_triangles_inside() {
    return gen::exec([] {
        Frame frame = *coverage_frames();
        if (frame.width > 64 || frame.height > 64) frame = frame_of(32, 32, {4, SamplePattern::standard}, kDefaultSnapBits);
        frame.volume = *gen::weightedElement<ClipVolume>({{3, {0.1f, 100.0f}}, {1, {1e-6f, 1e9f}}});
        const ClipVolume v = frame.volume;
        struct Kind {
            const char* name;
            int id;
        };
        const Kind kind = *gen::weightedElement<Kind>(
            {{3, {"random depths", 0}}, {1, {"one vertex 1000x nearer", 1}}, {1, {"equal depths", 2}}, {1, {"sliver", 3}}});
        glm::dvec2 p[3] = {screen_point_inside(frame, 0.0), screen_point_inside(frame, 0.0), screen_point_inside(frame, 0.0)};
        float w[3] = {depth_in(v), depth_in(v), depth_in(v)};
        if (kind.id == 1) {
            w[0] = std::max(v.near, std::min(w[1], w[2]) / 1000.0f);
        } else if (kind.id == 2) {
            w[1] = w[2] = w[0];
        } else if (kind.id == 3) {
            const double t = unit();
            p[2] = p[0] + t * (p[1] - p[0]) + glm::dvec2(0.01 * signed_unit(), 0.01 * signed_unit());
            p[2] = glm::clamp(p[2], glm::dvec2(0.0), glm::dvec2(frame.width, frame.height));
        }
        auto vertex = [&](int i) {
            // Reversed-Z depth of conventions.h, d = near (far - w) / (w (far - near)).
            const double d = double(v.near) * (double(v.far) - w[i]) / (double(w[i]) * (double(v.far) - v.near));
            return clip_from_screen(frame, p[i], w[i], static_cast<float>(d));
        };
        return clip_case(kind.name, frame, vertex(0), vertex(1), vertex(2));
    });
}

Gen<ClipCase> triangles_inside_the_volume() {
    return gen::exec([] {
        const Frame frame = *clip_frames();
        const ClipVolume v = frame.volume;
        auto random_inside = [&] { return inside_vertex(depth_in(v), signed_unit(), signed_unit()); };
        // Hand-picked vertices exactly on the planes: w = near, w = far, x = +-w, y = +-w, and the corners.
        auto on_plane = [&] {
            const int plane = *uniform(0, 5);
            const float w = plane == 0 ? v.near : plane == 1 ? v.far : depth_in(v);
            glm::vec4 p = inside_vertex(w, signed_unit(), signed_unit());
            if (plane == 2) p.x = w;
            if (plane == 3) p.x = -w;
            if (plane == 4) p.y = w;
            if (plane == 5) p.y = -w;
            if (coin()) p.x = coin() ? w : -w, p.y = coin() ? w : -w;  // a corner of that plane
            return p;
        };
        const int on = *gen::weightedElement<int>({{2, 0}, {1, 1}, {1, 2}, {1, 3}});
        glm::vec4 q[3];
        for (int i = 0; i < 3; ++i) q[i] = i < on ? on_plane() : random_inside();
        const char* names[] = {"inside", "a vertex on a plane", "two vertices on planes", "three vertices on planes"};
        return clip_case(names[on], frame, q[0], q[1], q[2]);
    });
}

namespace {

// A vertex outside the volume of the given kind.
glm::vec4 outside_vertex(const ClipVolume& v, int kind) {
    switch (kind) {
        case 0: {  // behind the eye
            const float w = -static_cast<float>(log_uniform(1e-3, std::max<double>(1.0, v.far)));
            return {static_cast<float>(4 * signed_unit()), static_cast<float>(4 * signed_unit()), 0.0f, w};
        }
        case 1: {  // between the eye and the near plane
            const float w = static_cast<float>(v.near * unit());
            return inside_vertex(w, signed_unit(), signed_unit());
        }
        case 2: {  // beyond far
            const float w = static_cast<float>(v.far * log_uniform(1.0 + 1e-6, 10.0));
            return inside_vertex(w, signed_unit(), signed_unit());
        }
        default: {  // off to a side, up to 4 times the half-width
            const float w = depth_in(v);
            return inside_vertex(w, 4 * signed_unit(), 4 * signed_unit());
        }
    }
}

}  // namespace

Gen<ClipCase> triangles_crossing_the_volume() {
    return gen::exec([] {
        const Frame frame = *clip_frames();
        const ClipVolume v = frame.volume;
        struct Kind {
            const char* name;
            int outside_kind, outside_count;
        };
        const Kind kind = *gen::weightedElement<Kind>({{2, {"one vertex behind the eye", 0, 1}},
                                                       {2, {"two vertices behind the eye", 0, 2}},
                                                       {1, {"a vertex before the near plane", 1, 1}},
                                                       {1, {"a vertex beyond far", 2, 1}},
                                                       {3, {"across the side planes", 3, 2}},
                                                       {1, {"all outside", 3, 3}}});
        glm::vec4 q[3];
        for (int i = 0; i < 3; ++i)
            q[i] = i < kind.outside_count ? outside_vertex(v, kind.outside_kind)
                                          : inside_vertex(depth_in(v), signed_unit(), signed_unit());
        return clip_case(kind.name, frame, q[0], q[1], q[2]);
    });
}

Gen<ClipCase> triangles_far_off_screen() {
    return gen::exec([] {
        const Frame frame = *clip_frames();
        const ClipVolume v = frame.volume;
        // 2^20 pixels off screen is 2^20 / (width / 2) in NDC.
        const double reach = std::ldexp(1.0, 20) / (0.5 * frame.width);
        const int count = *uniform(1, 2);
        auto far_vertex = [&] {
            const double a = (coin() ? 1 : -1) * log_uniform(1.0, reach), b = signed_unit() * (coin() ? reach : 1.0);
            return inside_vertex(depth_in(v), coin() ? a : b, coin() ? b : a);
        };
        glm::vec4 q[3];
        for (int i = 0; i < 3; ++i) q[i] = i < count ? far_vertex() : inside_vertex(depth_in(v), signed_unit(), signed_unit());
        return clip_case(count == 1 ? "a vertex up to 2^20 px off screen" : "two vertices up to 2^20 px off screen", frame, q[0],
                         q[1], q[2]);
    });
}

Gen<ClipCase> triangles_with_w_near_zero() {
    return gen::exec([] {
        const Frame frame = *clip_frames();
        const ClipVolume v = frame.volume;
        struct Small {
            const char* name;
            float w;
        };
        const Small w = *gen::element(Small{"w = 0", 0.0f}, Small{"w = +denormal", 1e-40f}, Small{"w = -denormal", -1e-40f},
                                      Small{"w = 1e-30", 1e-30f}, Small{"w = -1e-30", -1e-30f},
                                      Small{"w = near * 1e-7", v.near * 1e-7f}, Small{"w = -near * 1e-7", -v.near * 1e-7f});
        const glm::vec4 zero{static_cast<float>(2 * signed_unit()), static_cast<float>(2 * signed_unit()), 0.0f, w.w};
        return clip_case(std::string("a vertex at ") + w.name, frame, zero,
                         inside_vertex(depth_in(v), signed_unit(), signed_unit()),
                         inside_vertex(depth_in(v), signed_unit(), signed_unit()));
    });
}

Gen<ClipCase> triangles_with_non_finite_coordinates() {
    return gen::exec([] {
        ClipCase c = *triangles_inside_the_volume();
        const int count = *uniform(1, 3);
        bool nan = false, inf = false;
        for (int k = 0; k < count; ++k) {
            const float bad = *gen::element(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                                            -std::numeric_limits<float>::infinity());
            const int vertex = *uniform(0, 2), axis = *uniform(0, 3);
            c.triangle.v[static_cast<size_t>(vertex)][axis] = bad;
            (std::isnan(bad) ? nan : inf) = true;
        }
        c.kind = std::string(nan && inf ? "NaN and Inf" : nan ? "NaN" : "Inf") + (count == 1 ? " in one coordinate" : " in several coordinates");
        return c;
    });
}

// --- view space ------------------------------------------------------------------------------------------------

namespace {

Frame depth_frame() {
    const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard}, SampleChoice{4, SamplePattern::standard},
                                              SampleChoice{4, SamplePattern::grid});
    Frame frame = frame_of(*gen::element(16, 32), 0, choice, kDefaultSnapBits);
    frame.height = frame.width;
    frame.volume = *gen::weightedElement<ClipVolume>({{3, {0.1f, 100.0f}}, {1, {1e-6f, 1e9f}}});
    return frame;
}

ViewTriangle view_triangle(const Frame& frame, const float (&w)[3]) {
    ViewTriangle t;
    for (int i = 0; i < 3; ++i) t.v[static_cast<size_t>(i)] = view_point(frame, screen_point_inside(frame, 0.0), w[i]);
    return t;
}

}  // namespace

Gen<LayeredCase> overlapping_triangles() {
    return gen::exec([] {
        LayeredCase c;
        c.frame = depth_frame();
        const ClipVolume v = c.frame.volume;
        const int n = *uniform(2, 6);
        struct Kind {
            const char* name;
            int id;
        };
        const Kind kind = *gen::weightedElement<Kind>({{2, {"flat layers", 0}}, {2, {"tilted", 1}}, {1, {"intersecting", 2}}});
        c.kind = kind.name;
        for (int k = 0; k < n; ++k) {
            float w[3];
            w[0] = depth_in(v);
            if (kind.id == 0) {
                w[1] = w[2] = w[0];
            } else {
                w[1] = depth_in(v);
                w[2] = depth_in(v);
            }
            if (kind.id == 2 && k % 2 == 1) std::swap(w[0], w[2]);  // pairs leaning opposite ways cross each other
            c.triangles.push_back(view_triangle(c.frame, w));
        }
        c.order = *permutations(n);
        return c;
    });
}

Gen<LayeredCase> fronto_parallel_layers() {
    return gen::exec([] {
        LayeredCase c;
        c.frame = depth_frame();
        c.frame.volume = {0.1f, 100.0f};
        const int n = *uniform(2, 6);
        // Distinct powers of two in [1/8, 64]: every pair of layers differs by a factor of 2 or more in depth.
        std::vector<int> exponents(10);
        std::iota(exponents.begin(), exponents.end(), -3);
        const std::vector<int> order = *permutations(10);
        c.kind = n == 2 ? "two layers" : "three to six layers";
        for (int k = 0; k < n; ++k) {
            const float w = std::ldexp(1.0f, exponents[static_cast<size_t>(order[static_cast<size_t>(k)])]);
            const float ws[3] = {w, w, w};
            c.triangles.push_back(view_triangle(c.frame, ws));
        }
        c.order = *permutations(n);
        return c;
    });
}

Gen<LayeredCase> triangles_touching_the_near_plane() {
    return gen::exec([] {
        LayeredCase c;
        c.frame = depth_frame();
        const ClipVolume v = c.frame.volume;
        const int on = *uniform(1, 3);
        c.kind = std::to_string(on) + (on == 1 ? " vertex" : " vertices") + " exactly on the near plane";
        ViewTriangle t;
        for (int i = 0; i < 3; ++i) {
            const double w = i < on ? double(v.near) : double(depth_in(v));
            // A pixel from the border, so rounding in the projection cannot push a vertex across a side plane.
            t.v[static_cast<size_t>(i)] = view_point(c.frame, screen_point_inside(c.frame, 1.0), w);
            if (i < on) t.v[static_cast<size_t>(i)].z = -v.near;
        }
        c.triangles.push_back(t);
        c.order = {0};
        return c;
    });
}

// --- matrices and lenses ---------------------------------------------------------------------------------------

Gen<CameraCase> cameras() {
    auto valid = [](const CameraCase& c) {
        Camera camera;
        camera.eye = c.eye;
        camera.target = c.target;
        camera.up = c.up;
        return !camera_problem(camera);
    };
    return gen::suchThat(
        gen::weightedOneOf<CameraCase>({
            {4, gen::exec([] { return CameraCase{"random", random_vector(100), random_vector(100), random_vector(1)}; })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(1e5);
                 return CameraCase{"far from the origin", eye, eye + random_vector(100), random_vector(1)};
             })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(10);
                 return CameraCase{"target 1e-3 away", eye, eye + 1e-3f * random_direction(), random_vector(1)};
             })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(10), direction = random_direction();
                 // Up within 1e-3 to 1e-2 radians of the view direction.
                 glm::vec3 side = glm::cross(direction, random_direction());
                 side /= std::sqrt(glm::dot(side, side));
                 const float angle = static_cast<float>(log_uniform(1e-3, 1e-2));
                 return CameraCase{"up nearly parallel", eye, eye + 5.0f * direction,
                                   (coin() ? 1.0f : -1.0f) * direction + angle * side};
             })},
            {1, gen::exec([] {
                 return CameraCase{"up 1e-3 or 1e3 long", random_vector(10), random_vector(10),
                                   (coin() ? 1e-3f : 1e3f) * random_direction()};
             })},
            {1, gen::exec([] {
                 const int axis = *uniform(0, 2);
                 glm::vec3 direction(0.0f), up(0.0f);
                 direction[axis] = coin() ? 1.0f : -1.0f;
                 up[(axis + 1) % 3] = 1.0f;
                 const glm::vec3 eye = glm::round(random_vector(10));
                 return CameraCase{"along an axis", eye, eye + 3.0f * direction, up};
             })},
        }),
        valid);
}

Gen<LensCase> lenses() {
    return gen::exec([] {
        LensCase c;
        std::string kind;
        c.fov_y_degrees = *gen::weightedOneOf<float>({{4, gen::exec([] { return static_cast<float>(10 + 110 * unit()); })},
                                                      {1, gen::just(1.0f)},
                                                      {1, gen::just(179.0f)}});
        if (c.fov_y_degrees == 1.0f || c.fov_y_degrees == 179.0f) kind += "fov " + float_literal(c.fov_y_degrees) + ", ";
        c.width = *uniform(1, 4096);
        c.height = *uniform(1, 4096);
        c.aspect = static_cast<float>(c.width) / static_cast<float>(c.height);
        const int range = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        if (range == 0) {
            c.near = static_cast<float>(log_uniform(1e-3, 1.0));
            c.far = static_cast<float>(c.near * log_uniform(10.0, 1e5));
            kind += "typical near and far";
        } else if (range == 1) {
            c.near = 1e-6f;
            c.far = 1e9f;
            kind += "near 1e-6, far 1e9";
        } else {
            c.near = static_cast<float>(log_uniform(1e-3, 10.0));
            c.far = c.near * (1.0f + std::ldexp(1.0f, -10));
            kind += "far = near (1 + 2^-10)";
        }
        // Two view depths in [near, far], the second at least 2^-19 relatively farther (see the depth properties).
        const double gap = std::ldexp(1.0, -19);
        const double top = double(c.far) / (1.0 + gap);
        c.depth = static_cast<float>(*gen::weightedOneOf<double>({{4, gen::exec([near = c.near, top] { return log_uniform(near, top); })},
                                                                 {1, gen::just(double(c.near))}}));
        const double ratio = log_uniform(1.0 + 2 * gap, std::max(1.0 + 2 * gap, double(c.far) / c.depth));
        c.farther = static_cast<float>(std::min<double>(c.far, c.depth * ratio));
        if (c.farther <= c.depth * (1.0 + gap)) c.farther = c.far;
        c.across = {static_cast<float>(signed_unit()), static_cast<float>(signed_unit())};
        c.kind = kind;
        return c;
    });
}

Gen<ModelCase> models() {
    return gen::exec([] {
        ModelCase c;
        const int kind = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        for (int i = 0; i < 3; ++i) {
            const double magnitude = kind == 1 ? log_uniform(1e-3, 1e3) : log_uniform(0.1, 10.0);
            c.chain.scale[i] = static_cast<float>((coin() ? 1 : -1) * magnitude);
        }
        if (kind == 2) c.chain.scale = glm::vec3(c.chain.scale.x);
        c.kind = kind == 0 ? "scales 0.1 to 10" : kind == 1 ? "scales 1e-3 to 1e3" : "uniform scale";
        c.chain.degrees = static_cast<float>(720 * unit() - 360);
        c.chain.axis = *gen::suchThat(gen::exec([] { return random_vector(1); }),
                                      [](const glm::vec3& a) { return glm::dot(a, a) > 1e-2f; });
        const int where = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        c.chain.offset = where == 0 ? random_vector(100) : where == 1 ? random_vector(1e4) : glm::vec3(0.0f);
        if (where == 1) c.kind += ", far away";
        c.triangle = *gen::suchThat(gen::exec([] { return std::array<glm::vec3, 3>{random_vector(1), random_vector(1), random_vector(1)}; }),
                                    [](const std::array<glm::vec3, 3>& t) {
                                        const glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
                                        return glm::dot(n, n) > 0.01f;
                                    });
        return c;
    });
}

// --- extremes of whole scenes ----------------------------------------------------------------------------------

Gen<DepthPairCase> depth_pairs_over_extreme_range() {
    return gen::exec([] {
        const double near = 1e-6, far = 1e9, gap = std::ldexp(1.0, -19);
        const int kind = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}, {1, 3}});
        double a = log_uniform(near, far / (1.0 + 4 * gap)), b = a * log_uniform(1.0 + 2 * gap, far / a);
        if (kind == 1) a = near, b = near * log_uniform(1.0 + 2 * gap, 10.0);
        if (kind == 2) b = far, a = far / log_uniform(1.0 + 2 * gap, 10.0);
        if (kind == 3) b = a * (1.0 + gap * (2.0 + 2.0 * unit()));
        const float fa = static_cast<float>(a);
        float fb = static_cast<float>(std::min(b, far));
        if (!(double(fb) >= double(fa) * (1.0 + gap))) fb = std::nextafter(static_cast<float>(double(fa) * (1.0 + 2 * gap)), INFINITY);
        const char* names[] = {"anywhere", "at the near plane", "at the far plane", "2^-19 apart"};
        return DepthPairCase{names[kind], fa, std::min(fb, 1e9f), coin()};
    });
}

Gen<ScaledSceneCase> scenes_scaled_towards_float_limits() {
    return gen::exec([] {
        ScaledSceneCase c;
        // Exactness of the scaling (derived in the property): every intermediate stays a normal float when
        // 2^-100 * 2^-8 and 20 * 2.5 * 2^120 are representable, and 1 / (20 * 2^120) is still normal.
        c.exponent = *gen::weightedOneOf<int>({{2, uniform(80, 120)}, {1, uniform(-100, -60)}, {1, uniform(-10, 10)}});
        c.kind = c.exponent >= 80 ? "scaled towards FLT_MAX" : c.exponent <= -60 ? "scaled towards FLT_MIN" : "moderate";
        auto grid = [](double lo, double hi) {
            return static_cast<float>(std::ldexp(std::round(std::ldexp(lo + (hi - lo) * unit(), 8)), -8));
        };
        for (auto& p : c.triangle) p = {grid(-4, 4), grid(-4, 4), grid(-16, -1)};
        c.eye = glm::vec3(0.0f);
        c.target = {0.0f, 0.0f, -1.0f};
        c.near = 0.5f;
        c.far = 20.0f;
        return c;
    });
}

Gen<LightCase> lights() {
    return gen::exec([] {
        LightCase c;
        c.normal = random_direction();
        c.direction = *gen::suchThat(gen::exec([] { return random_direction(); }),
                                     [normal = c.normal](const glm::vec3& d) { return glm::dot(d, normal) > 0.1f; });
        const int kind = *gen::weightedElement<int>({{4, 0}, {1, 1}, {1, 2}});
        c.distance = kind == 0 ? static_cast<float>(log_uniform(0.1, 100.0)) : kind == 1 ? 1e-3f : 1e3f;
        c.kind = kind == 0 ? "random distance" : kind == 1 ? "1e-3 away" : "1e3 away";
        c.color = {static_cast<float>(0.1 + unit()), static_cast<float>(0.1 + unit()), static_cast<float>(0.1 + unit())};
        return c;
    });
}

Gen<std::vector<int>> permutations(int n) {
    return gen::exec([n] {
        std::vector<int> order(static_cast<size_t>(n));
        std::iota(order.begin(), order.end(), 0);
        for (int i = n - 1; i > 0; --i) std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(*uniform(0, i))]);
        return order;
    });
}

}  // namespace raster::properties
