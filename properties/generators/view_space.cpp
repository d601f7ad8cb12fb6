// The view-space generators: layered, tilted and intersecting triangles seen through a 90 degree lens, fronto-
// parallel layers at distinct depths, and triangles touching the near plane.
#include "properties/generators/view_space.h"

#include <algorithm>
#include <numeric>

#include "properties/generators/frames.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"

namespace raster::properties {
namespace {

// A view-space point that a 90-degree lens with the frame's aspect projects onto `screen` at view depth w.
glm::vec3 view_point(const Frame& frame, const glm::dvec2& screen, double w) {
    const glm::dvec2 ndc = ndc_of_screen(frame, screen);
    const double aspect = static_cast<double>(frame.width) / frame.height;
    return {static_cast<float>(ndc.x * w * aspect), static_cast<float>(ndc.y * w), static_cast<float>(-w)};
}

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

std::ostream& operator<<(std::ostream& os, const LayeredCase& c) {
    os << "LayeredCase{\"" << c.kind << "\", " << c.frame << ", {";
    for (size_t i = 0; i < c.triangles.size(); ++i)
        os << (i ? ", " : "") << "{" << literal(c.triangles[i].v[0]) << ", " << literal(c.triangles[i].v[1]) << ", "
           << literal(c.triangles[i].v[2]) << "}";
    os << "}, {";
    for (size_t i = 0; i < c.order.size(); ++i) os << (i ? ", " : "") << c.order[i];
    return os << "}}";
}

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

}  // namespace raster::properties
