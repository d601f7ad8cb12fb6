// Which samples a correct rasterizer may draw otherwise than the oracle (sample_openness.h): the triangles binned by
// their screen box widened by their radius, then each sample against the triangles of its bin.
#include "oracle/compare/sample_openness.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/core/parallel.h"

namespace raster::oracle {
namespace {

constexpr int kBinPixels = 16;

// A triangle's screen box, widened by its radius, in pixels; empty (min > max) for an empty polygon.
struct ScreenBox {
    double min_x = 0, min_y = 0, max_x = -1, max_y = -1;
    bool contains(const glm::dvec2& p) const { return min_x <= p.x && p.x <= max_x && min_y <= p.y && p.y <= max_y; }
};

ScreenBox widened_box(const ReferenceGeometry& reference, uint32_t id, int width, int height) {
    const ReferencePolygon& polygon = reference.polygon(id);
    ScreenBox box;
    if (polygon.count == 0) return box;
    if (!std::isfinite(polygon.radius)) return {0.0, 0.0, double(width), double(height)};  // anything may happen
    box = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const glm::dvec2& v : reference.screen_vertices(id)) {
        box.min_x = std::min(box.min_x, v.x), box.max_x = std::max(box.max_x, v.x);
        box.min_y = std::min(box.min_y, v.y), box.max_y = std::max(box.max_y, v.y);
    }
    box.min_x -= polygon.radius, box.min_y -= polygon.radius;
    box.max_x += polygon.radius, box.max_y += polygon.radius;
    return box;
}

class TriangleBins {
public:
    TriangleBins(const OpennessInputs& in, int width, int height)
        : columns_((width + kBinPixels - 1) / kBinPixels), rows_((height + kBinPixels - 1) / kBinPixels),
          bins_(size_t(columns_) * size_t(rows_)) {
        const ReferenceGeometry& reference = *in.reference;
        boxes_.resize(reference.size());
        for (uint32_t id = 0; id < reference.size(); ++id) {
            const ReferencePolygon& polygon = reference.polygon(id);
            const bool blended = id < in.transparent.size() && in.transparent[id];
            if (blended || (polygon.culled && !polygon.facing_uncertain)) continue;
            const ScreenBox box = boxes_[id] = widened_box(reference, id, width, height);
            if (box.min_x > box.max_x || box.max_x < 0 || box.max_y < 0 || box.min_x > width || box.min_y > height)
                continue;
            const int x0 = std::clamp(int(std::floor(std::max(box.min_x, 0.0))) / kBinPixels, 0, columns_ - 1);
            const int x1 = std::clamp(int(std::floor(std::min(box.max_x, double(width)))) / kBinPixels, 0, columns_ - 1);
            const int y0 = std::clamp(int(std::floor(std::max(box.min_y, 0.0))) / kBinPixels, 0, rows_ - 1);
            const int y1 = std::clamp(int(std::floor(std::min(box.max_y, double(height)))) / kBinPixels, 0, rows_ - 1);
            for (int by = y0; by <= y1; ++by)
                for (int bx = x0; bx <= x1; ++bx) bins_[size_t(by) * size_t(columns_) + size_t(bx)].push_back(id);
        }
    }
    const std::vector<uint32_t>& at(int px, int py) const {
        return bins_[size_t(py / kBinPixels) * size_t(columns_) + size_t(px / kBinPixels)];
    }
    const ScreenBox& box(uint32_t id) const { return boxes_[id]; }

private:
    int columns_, rows_;
    std::vector<std::vector<uint32_t>> bins_;
    std::vector<ScreenBox> boxes_;
};

// Whether triangle `t` is certainly behind triangle `front` all over the sample's square: t's nearest reversed z
// (larger is nearer) below front's farthest, each widened by its errors.
bool certainly_behind(const ReferenceGeometry& reference, uint32_t t, uint32_t front, const glm::dvec2& screen) {
    const ReversedZInterval it = reversed_z_interval(reference, t, screen);
    const ReversedZInterval ifront = reversed_z_interval(reference, front, screen);
    return it.bounded && ifront.bounded && it.hi < ifront.lo;
}

// The openness of one sample: the first allowance found, in the classifier's order (facing, clip boundary, edge
// band, depth tie), or agree.
SampleClass openness(const ReferenceGeometry& reference, const TriangleBins& bins, int px, int py,
                     const glm::dvec2& screen, uint32_t hit) {
    // The classifier's order of precedence: facing, then clip boundary, then edge band, then depth tie.
    const auto rank = [](SampleClass c) {
        switch (c) {
            case SampleClass::facing: return 4;
            case SampleClass::clip_boundary: return 3;
            case SampleClass::edge_band: return 2;
            case SampleClass::depth_tie: return 1;
            default: return 0;
        }
    };
    SampleClass found = SampleClass::agree;
    const auto note = [&](SampleClass c) {
        if (rank(c) > rank(found)) found = c;
    };
    const bool hit_known = hit != kNoTriangle && hit < reference.size();
    if (hit != kNoTriangle && !hit_known) return SampleClass::edge_band;  // an id no triangle has: nothing is decided
    // Embree's edge-by-edge test may show a triangle that exactly misses the sample, beyond its band too (the
    // classifier's allowance): then a correct rasterizer shows something else.
    if (hit_known && !reference.contains(hit, screen)) note(SampleClass::edge_band);
    for (const uint32_t t : bins.at(px, py)) {
        if (!bins.box(t).contains(screen)) continue;
        const ReferencePolygon& polygon = reference.polygon(t);
        const bool in_band = in_edge_band(reference, t, screen);
        const bool inside = reference.contains(t, screen);
        if (!in_band && !inside) continue;  // t cannot reach the sample
        if (polygon.facing_uncertain) {
            note(SampleClass::facing);
            continue;
        }
        if (on_clip_boundary(reference, t, screen)) note(SampleClass::clip_boundary);
        if (t == hit) {
            if (in_band || !inside) note(SampleClass::edge_band);  // the oracle's own triangle may be missed
            continue;
        }
        // Another triangle reaches the sample: it opens it unless it is certainly behind the oracle's.
        if (hit_known && certainly_behind(reference, t, hit, screen)) continue;
        note(in_band || !hit_known ? SampleClass::edge_band : SampleClass::depth_tie);
    }
    return found;
}

}  // namespace

SampleOpenness open_samples(const OpennessInputs& in) {
    const SampleBuffer& oracle = *in.oracle;
    const int width = oracle.width, height = oracle.height, samples = oracle.samples;
    SampleOpenness result;
    result.classes.assign(oracle.size(), SampleClass::agree);
    if (width <= 0 || height <= 0) return result;
    const TriangleBins bins(in, width, height);
    std::vector<ComparisonCounts> row_counts(static_cast<size_t>(height));
    parallel_for(static_cast<size_t>(height), in.threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        for (int px = 0; px < width; ++px)
            for (int s = 0; s < samples; ++s) {
                const size_t at = oracle.index(px, py, s);
                const glm::dvec2 screen = glm::dvec2(px, py) + in.offsets[static_cast<size_t>(s)];
                const SampleClass c = openness(*in.reference, bins, px, py, screen, oracle.triangle[at]);
                result.classes[at] = c;
                ++row_counts[row].by_class[static_cast<size_t>(c)];
            }
    });
    for (const ComparisonCounts& counts : row_counts)
        for (int c = 0; c < kSampleClassCount; ++c) result.counts.by_class[c] += counts.by_class[c];
    return result;
}

}  // namespace raster::oracle
