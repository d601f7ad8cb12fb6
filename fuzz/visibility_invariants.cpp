// The raster target's invariants: one pass over each reference piece's samples gathers what the reference knows
// (the nearest certain key, the shown triangle's own coverage, key and interpolation), then one pass over the frame
// checks the buffer against it.
#include "fuzz/visibility_invariants.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"

namespace raster::fuzz {
namespace {

using reference::Point;

// What the piece pass learns about one sample.
struct SampleState {
    float best_key = -std::numeric_limits<float>::infinity();  // the largest key_low of a piece certainly covering it
    uint32_t best_triangle = kNoTriangle;                      // the earliest triangle with that key_low
    float shown_key_high = -std::numeric_limits<float>::infinity();  // the shown triangle's largest key_high here
    bool shown_covers = false;        // a piece of the shown triangle covers the sample, certainly or maybe
    bool shown_certain = false;       // one covers it certainly
    bool shown_interpolated = false;  // one of those matches the buffer's barycentrics and view depth
};

const char* to_string(Coverage coverage) {
    return coverage == Coverage::yes ? "yes" : coverage == Coverage::maybe ? "maybe" : "no";
}

bool matches(const ReferenceHit& hit, const glm::vec3& bary, float view_depth) {
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(double(bary[i]) - hit.bary[i]) <= hit.bary_tolerance)) return false;
    return std::fabs(double(view_depth) - hit.view_depth) <= hit.depth_tolerance;
}

// Triangle `id`'s pieces as the reference sees them at sample p.
std::string describe_triangle(const ReferenceFrame& reference, uint32_t id, Point p) {
    std::ostringstream text;
    text << std::setprecision(9);
    if (id == kNoTriangle) return "  triangle none\n";
    if (id >= reference.triangles().size()) {
        text << "  triangle " << id << ": no such triangle\n";
        return text.str();
    }
    const ReferenceTriangle& triangle = reference.triangles()[id];
    text << "  triangle " << id << (triangle.inside_volume ? " (unclipped)" : " (clipped)") << ", "
         << triangle.end_piece - triangle.first_piece << " pieces:\n";
    for (uint32_t k = triangle.first_piece; k < triangle.end_piece; ++k) {
        const ReferencePiece& piece = reference.pieces()[k];
        const PieceSample here = reference.at(piece, p);
        text << "    snapped";
        for (const ReferenceVertex& v : piece.vertex) text << " (" << v.at.x << ", " << v.at.y << ")";
        text << " area2 " << piece.area2 << (piece.certain ? "" : " (facing undecided)") << ": coverage "
             << to_string(here.coverage) << ", key in [" << here.key_low << ", " << here.key_high << "]";
        if (here.coverage != Coverage::no) {
            const ReferenceHit hit = reference.hit(piece, here.lambda);
            text << ", bary (" << hit.bary.x << ", " << hit.bary.y << ", " << hit.bary.z << ") +- "
                 << hit.bary_tolerance << ", view depth " << hit.view_depth << " +- " << hit.depth_tolerance;
        }
        text << "\n";
    }
    return text.str();
}

std::string describe_sample(const ReferenceFrame& reference, const VisibilityBuffer& buffer, const Scene& scene,
                            int px, int py, int s, uint32_t other) {
    const size_t index = buffer.index(px, py, s);
    const Point p = reference.sample_position(px, py, s);
    std::ostringstream text;
    text << std::setprecision(9) << "pixel (" << px << ", " << py << ") sample " << s << " at (" << p.x << ", " << p.y
         << ") in units of 1/" << (int64_t{1} << reference.fixed_bits()) << " px\n  raster shows ";
    const uint32_t shown = buffer.triangle[index];
    if (shown == kNoTriangle) {
        text << "nothing\n";
    } else {
        const glm::vec3 bary = buffer.bary[index];
        text << "triangle " << shown << ", bary (" << bary.x << ", " << bary.y << ", " << bary.z << "), view depth "
             << buffer.view_depth[index] << "\n" << describe_triangle(reference, shown, p);
    }
    if (other != shown) text << describe_triangle(reference, other, p);
    return text.str() + "scene:\n" + describe_scene(scene);
}

// The piece pass: each piece's samples, in draw order. The states are reused from frame to frame (a fuzz target
// checks thousands of frames a second).
const std::vector<SampleState>& gather(const ReferenceFrame& reference, const VisibilityBuffer& buffer) {
    static std::vector<SampleState> states;
    states.assign(buffer.size(), SampleState{});
    for (const ReferencePiece& piece : reference.pieces()) {
        for (int py = piece.min_y; py <= piece.max_y; ++py)
            for (int px = piece.min_x; px <= piece.max_x; ++px)
                for (int s = 0; s < buffer.samples; ++s) {
                    const PieceSample here = reference.at(piece, reference.sample_position(px, py, s));
                    if (here.coverage == Coverage::no) continue;
                    const size_t index = buffer.index(px, py, s);
                    SampleState& state = states[index];
                    const bool certain = here.coverage == Coverage::yes;
                    // Strictly larger: on equal keys the earlier triangle stays, as in the depth test.
                    if (certain && (state.best_triangle == kNoTriangle || here.key_low > state.best_key)) {
                        state.best_key = here.key_low;
                        state.best_triangle = piece.triangle;
                    }
                    if (piece.triangle != buffer.triangle[index]) continue;
                    state.shown_covers = true;
                    state.shown_key_high = std::max(state.shown_key_high, here.key_high);
                    if (!certain) continue;
                    state.shown_certain = true;
                    if (!reference.float_edges() && !state.shown_interpolated)
                        state.shown_interpolated = matches(reference.hit(piece, here.lambda), buffer.bary[index],
                                                           buffer.view_depth[index]);
                }
    }
    return states;
}

}  // namespace

void check_visibility(const ReferenceFrame& reference, const VisibilityBuffer& buffer, const Scene& scene) {
    const std::vector<SampleState>& states = gather(reference, buffer);
    const size_t triangle_count = reference.triangles().size();
    for (int py = 0; py < buffer.height; ++py)
        for (int px = 0; px < buffer.width; ++px)
            for (int s = 0; s < buffer.samples; ++s) {
                const size_t index = buffer.index(px, py, s);
                const SampleState& state = states[index];
                const uint32_t shown = buffer.triangle[index];
                const auto context = [&] {
                    return describe_sample(reference, buffer, scene, px, py, s, state.best_triangle);
                };
                if (shown == kNoTriangle) {
                    // 1: the reference covers it certainly (best_triangle), raster left it empty.
                    FUZZ_CHECK_EQ(state.best_triangle, kNoTriangle, context);
                    continue;
                }
                FUZZ_CHECK_OP(size_t{shown}, <, triangle_count, context);
                // 1: the triangle shown covers the sample.
                FUZZ_CHECK_EQ(state.shown_covers, true, context);
                // 2: nothing certainly covering it is certainly nearer, or as near and earlier.
                if (state.best_triangle != kNoTriangle) {
                    FUZZ_CHECK_LE(state.best_key, state.shown_key_high, context);
                    if (state.best_key == state.shown_key_high) FUZZ_CHECK_GE(state.best_triangle, shown, context);
                }
                // 3: an exact copy of an earlier triangle never wins.
                FUZZ_CHECK_EQ(reference.triangles()[shown].duplicate_of, kNoTriangle, context);
                // 4: where it is certain, the interpolation.
                if (state.shown_certain && !reference.float_edges())
                    FUZZ_CHECK_EQ(state.shown_interpolated, true, context);
            }
}

void check_fan(const ReferenceFrame& reference, const VisibilityBuffer& buffer, uint32_t first, uint32_t end,
               const Scene& scene) {
    std::vector<uint8_t> count(buffer.size(), 0), interior(buffer.size(), 0);
    for (uint32_t t = first; t < end; ++t) {
        const ReferencePiece& piece = reference.pieces()[reference.triangles()[t].first_piece];
        // Each piece's vertex 0 is the fan's centre (the triangle's first vertex, kept first), so edge 0 (v1 -> v2)
        // is its part of the rim and edges 1 and 2 are spokes, shared with its neighbours.
        for (int py = piece.min_y; py <= piece.max_y; ++py)
            for (int px = piece.min_x; px <= piece.max_x; ++px)
                for (int s = 0; s < buffer.samples; ++s) {
                    const Point p = reference.sample_position(px, py, s);
                    const size_t index = buffer.index(px, py, s);
                    count[index] += reference.at(piece, p).coverage == Coverage::yes;
                    const Point centre = piece.vertex[0].at;
                    const Point rim_start = piece.vertex[1].at, rim_end = piece.vertex[2].at;
                    interior[index] |= reference::orient(rim_start, rim_end, p) > 0 &&
                                       reference::orient(rim_end, centre, p) >= 0 &&
                                       reference::orient(centre, rim_start, p) >= 0;
                }
    }
    for (int py = 0; py < buffer.height; ++py)
        for (int px = 0; px < buffer.width; ++px)
            for (int s = 0; s < buffer.samples; ++s) {
                const size_t index = buffer.index(px, py, s);
                const auto context = [&] {
                    return "(fan of triangles " + std::to_string(first) + ".." + std::to_string(end - 1) + ") " +
                           describe_sample(reference, buffer, scene, px, py, s, kNoTriangle);
                };
                FUZZ_CHECK_LE(int{count[index]}, 1, context);
                if (!interior[index]) continue;
                FUZZ_CHECK_EQ(int{count[index]}, 1, context);
                FUZZ_CHECK_OP(buffer.triangle[index], !=, kNoTriangle, context);
            }
}

}  // namespace raster::fuzz
