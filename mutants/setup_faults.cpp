// The setup stage's faulty variants of the bug catalogue (and the culling test's), each around the real
// setup_polygon or faces_front.
#include "mutants/setup_faults.h"

#include "raster/core/conventions.h"

namespace raster::mutants {
namespace {

// Runs the real setup, then lets `fault` alter each triangle it appended: the shape of most setup mutants.
template <class Fault>
int setup_then(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params, std::vector<TriangleSetup>& out,
               Fault fault) {
    const size_t first = out.size();
    const int added = setup_polygon(polygon, id, params, out);
    for (size_t k = first; k < out.size(); ++k) fault(out[k]);
    return added;
}

}  // namespace

// "no fill rule": samples exactly on an edge are inside for every triangle, so shared edges are covered twice.
int setup_without_fill_rule(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                            std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int64_t& bias : t.bias) bias = 0;
    });
}

// "cracks on shared edges": samples exactly on an edge are outside for every triangle.
int setup_with_cracks(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                      std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int64_t& bias : t.bias) bias = -1;
    });
}

// "float edge functions": the edge equations are set up in float (24-bit mantissa), so c = dy * x - dx * y is
// rounded; two triangles sharing an edge round it differently and the edge cracks or doubles. That is the
// EdgeArithmetic::float32 mode, forced on whatever the scene asks for.
int setup_with_float_edges(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                           std::vector<TriangleSetup>& out) {
    FrameParams float_edges = params;
    float_edges.edges = EdgeArithmetic::float32;
    return setup_polygon(polygon, id, float_edges, out);
}

// "fill rule inverted (bottom-right)": samples on an edge belong to the triangle when the edge is a bottom or right
// edge. Still watertight, but every shared sample goes to the other triangle.
int setup_with_bottom_right_rule(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                                 std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int i = 0; i < 3; ++i) {
            const int s = (i + 1) % 3, e = (i + 2) % 3;
            t.bias[i] = is_top_left(t.x[e] - t.x[s], t.y[e] - t.y[s]) ? -1 : 0;
        }
    });
}

// "sub-pixel triangles discarded (det < 1)": triangles smaller than one square pixel are thrown away.
int setup_discarding_sub_pixel(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                               std::vector<TriangleSetup>& out) {
    const size_t first = out.size();
    setup_polygon(polygon, id, params, out);
    const int fixed_bits = params.fixed_bits;
    const int64_t one_pixel_area2 = int64_t{2} << (2 * fixed_bits);
    size_t kept = first;
    for (size_t i = first; i < out.size(); ++i)
        if (out[i].area2 >= one_pixel_area2) out[kept++] = out[i];
    out.resize(kept);
    return static_cast<int>(kept - first);
}

// "y not flipped": NDC y goes to screen y unflipped, so the image comes out upside down.
int setup_without_y_flip(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                         std::vector<TriangleSetup>& out) {
    ClippedPolygon flipped = polygon;
    for (int i = 0; i < flipped.count; ++i) flipped.vertices[i].position.y = -flipped.vertices[i].position.y;
    return setup_polygon(flipped, id, params, out);
}

// "front faces culled (winding inverted)": culling keeps the faces turned away from the eye, so a closed mesh shows
// its inside.
bool faces_front_inverted(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) { return !faces_front(a, b, c); }

}  // namespace raster::mutants
