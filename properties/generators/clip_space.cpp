// The clip-space generators: one triangle on a frame with a clip volume, inside it, on its planes, across it, far
// off screen, with w near zero or with non-finite coordinates.
#include "properties/generators/clip_space.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "properties/generators/frames.h"
#include "properties/generators/primitives.h"

namespace raster::properties {
namespace {

// A clip-space vertex inside the volume at view depth w: x = a w, y = b w with a, b in [-1, 1].
glm::vec4 inside_vertex(float w, double a, double b) {
    return {static_cast<float>(a * w), static_cast<float>(b * w), 0.5f * w, w};
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

std::ostream& operator<<(std::ostream& os, const ClipCase& c) {
    return os << "ClipCase{\"" << c.kind << "\", " << c.frame << ", " << c.triangle << "}";
}

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

}  // namespace raster::properties
