// The frames the generators draw on, and the points and view depths they draw inside one.
#include "properties/generators/frames.h"

#include <algorithm>

#include "properties/generators/primitives.h"
#include "properties/reference/documented_samples.h"

namespace raster::properties {
namespace {

using reference::Point;

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

// Do the frame's documented sample positions lie on its position grid (so a vertex can be put on a sample)?
bool samples_on_position_grid(const Frame& frame) {
    const int shift = frame.fixed_bits() - position_bits(frame);
    if (shift < 0) return false;
    const int64_t mask = (int64_t{1} << shift) - 1;
    for (const Point& o : documented_fixed_offsets(frame.samples, frame.pattern, frame.fixed_bits()))
        if ((o.x & mask) || (o.y & mask)) return false;
    return true;
}

}  // namespace

Frame frame_of(int width, int height, SampleChoice choice, int snap_bits) {
    Frame frame;
    frame.width = width;
    frame.height = height;
    frame.samples = choice.samples;
    frame.pattern = choice.pattern;
    frame.snap_bits = snap_bits;
    return frame;
}

Gen<Frame> coverage_frames() {
    return gen::weightedOneOf<Frame>({
        {6, gen::exec([] {
             const int side = *gen::element(16, 32, 64);
             return frame_of(side, side, *sample_choices(), kDefaultSnapBits);
         })},
        {1, gen::exec([] { return frame_of(32, 32, *sample_choices(), *uniform(1, 4)); })},
        {1, gen::exec([] { return frame_of(32, 32, *sample_choices(), *gen::element(12, 16)); })},
        // Four 64-pixel tiles of the tiled renderer, so that triangles cross tile edges.
        {1, gen::exec([] {
             const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard},
                                                       SampleChoice{4, SamplePattern::standard});
             return frame_of(128, 128, choice, kDefaultSnapBits);
         })},
        {1, gen::exec([] {
             const int snap = *gen::element(8, 16);
             const SampleChoice choice = *gen::element(SampleChoice{1, SamplePattern::standard},
                                                       SampleChoice{4, SamplePattern::standard});
             return coin() ? frame_of(16384, 4, choice, snap) : frame_of(4, 16384, choice, snap);
         })},
    });
}

int position_bits(const Frame& frame) { return std::min(frame.snap_bits, frame.exact_bits()); }

Gen<Frame> sample_aligned_frames() { return gen::suchThat(coverage_frames(), samples_on_position_grid); }

Gen<Frame> symmetric_frames() {
    return gen::exec([] {
        const int side = *gen::element(16, 32);
        const int n = *gen::weightedElement<int>({{3, 1}, {2, 2}, {2, 3}, {1, 4}, {1, 5}, {1, 16}});
        return frame_of(side, side, {n * n, n == 1 ? SamplePattern::standard : SamplePattern::grid},
                        *gen::element(8, 12, 16));
    });
}

float depth_in(const ClipVolume& v) {
    return static_cast<float>(std::min<double>(v.far, log_uniform(v.near, std::min<double>(v.far, v.near * 1e4 + 1.0))));
}

glm::dvec2 screen_point_inside(const Frame& frame, double margin) {
    return {margin + unit() * (frame.width - 2 * margin), margin + unit() * (frame.height - 2 * margin)};
}

}  // namespace raster::properties
