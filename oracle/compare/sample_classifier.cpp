// The sample classifier: per-sample classification, row by row over threads, with per-row counts summed in order.
#include "oracle/compare/sample_classifier.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>

#include "oracle/reference/precision.h"
#include "raster/core/parallel.h"

namespace raster::oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool is_triangle(const ReferenceGeometry& reference, uint32_t id) { return id != kNoTriangle && id < reference.size(); }

}  // namespace

const char* to_string(SampleClass c) {
    switch (c) {
        case SampleClass::agree: return "agree";
        case SampleClass::edge_band: return "edge_band";
        case SampleClass::depth_tie: return "depth_tie";
        case SampleClass::clip_boundary: return "clip_boundary";
        case SampleClass::facing: return "facing";
        case SampleClass::visibility: return "visibility";
        case SampleClass::barycentrics: return "barycentrics";
        case SampleClass::depth: return "depth";
    }
    return "?";
}

SampleEntry sample_entry(const RasterSamples& buffer, size_t index) {
    return {buffer.triangle[index], buffer.bary[index], buffer.view_depth[index]};
}

SampleEntry sample_entry(const SampleBuffer& buffer, size_t index) {
    return {buffer.triangle[index], buffer.bary[index], buffer.view_depth[index]};
}

uint64_t ComparisonCounts::ambiguous_total() const {
    return count(SampleClass::edge_band) + count(SampleClass::depth_tie) + count(SampleClass::clip_boundary) +
           count(SampleClass::facing);
}

uint64_t ComparisonCounts::genuine_total() const {
    return count(SampleClass::visibility) + count(SampleClass::barycentrics) + count(SampleClass::depth);
}

namespace {

// An orthographic frame's view depth is interpolated affinely from raster's vertex depths, each off by at most
// the polygon's depth error (absolute; weights summing to 1): an absolute term the relative roundings miss.
double orthographic_depth_error(const ReferenceGeometry& reference, const ReferencePolygon& polygon) {
    return reference.orthographic() ? polygon.depth_error : 0.0;
}

// The barycentric tolerance with the triangle's r-square range already found.
glm::dvec3 barycentric_tolerance(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen,
                                 const SquareRange& range) {
    const double bary_rounding = barycentric_rounding(reference.polygon(id).relative_depth_error);
    if (!range.bounded || !std::isfinite(bary_rounding)) return glm::dvec3(kInfinity);
    // Both renderers round: twice the per-renderer rounding; and Embree's own evaluation error.
    return (range.max_bary - range.min_bary) + glm::dvec3(2.0 * bary_rounding) +
           reference.embree_barycentric_error(id, screen);
}

}  // namespace

glm::dvec3 barycentric_tolerance(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    return barycentric_tolerance(reference, id, screen, reference.range_around(id, screen, reference.polygon(id).radius));
}

AgreementTolerance agreement_tolerance(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    const ReferencePolygon& polygon = reference.polygon(id);
    const SquareRange range = reference.range_around(id, screen, polygon.radius);
    const double depth_rounding = view_depth_rounding(polygon.relative_depth_error);
    const glm::dvec3 bary = barycentric_tolerance(reference, id, screen, range);
    if (!range.bounded || !std::isfinite(depth_rounding) || !std::isfinite(bary.x))
        return {glm::dvec3(kInfinity), kInfinity};
    AgreementTolerance tolerance;
    tolerance.bary = bary;
    tolerance.view_depth = (range.max_view_depth - range.min_view_depth) + 2.0 * depth_rounding * range.max_view_depth +
                           reference.embree_view_depth_error(id, screen) + orthographic_depth_error(reference, polygon);
    return tolerance;
}

bool in_edge_band(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    return reference.boundary_distance(id, screen) <= reference.polygon(id).radius;
}

bool on_clip_boundary(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    const ReferencePolygon& polygon = reference.polygon(id);
    const SquareRange range = reference.range_around(id, screen, polygon.radius);
    if (!range.bounded) return true;  // the plane is grazed within the square: anything may happen there
    // The square must reach the triangle: some corner on the inner side of every edge (an outer estimate).
    if (range.max_bary.x < 0.0 || range.max_bary.y < 0.0 || range.max_bary.z < 0.0) return false;
    const double low = range.min_view_depth - polygon.depth_error, high = range.max_view_depth + polygon.depth_error;
    return (low <= reference.near() && reference.near() <= high) || (low <= reference.far() && reference.far() <= high);
}

ReversedZInterval reversed_z_interval(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    const SquareRange range = reference.range_around(id, screen, reference.polygon(id).radius);
    if (!range.bounded) return {};
    // The triangle's reversed-Z error, and Embree's own at this sample (the oracle's choice rests on its t).
    const double error = reference.polygon(id).reversed_z_error + reference.embree_reversed_z_error(id, screen);
    return {true, range.min_reversed_z - error, range.max_reversed_z + error};
}

bool depth_tie(const ReferenceGeometry& reference, uint32_t a, uint32_t b, const glm::dvec2& screen) {
    for (uint32_t id : {a, b}) {
        const ReferencePolygon& p = reference.polygon(id);
        if (p.culled || !reference.contains(id, screen)) return false;  // then one of them should not be there
    }
    const ReversedZInterval ia = reversed_z_interval(reference, a, screen), ib = reversed_z_interval(reference, b, screen);
    if (!ia.bounded || !ib.bounded) return true;
    return ia.lo <= ib.hi && ib.lo <= ia.hi;
}

RoundingAllowance rounding_allowance(const ReferenceGeometry& reference, uint32_t id, const SampleEntry& raster,
                                     const SampleEntry& oracle) {
    const ReferencePolygon& polygon = reference.polygon(id);
    return {2.0 * barycentric_rounding(polygon.relative_depth_error),
            2.0 * view_depth_rounding(polygon.relative_depth_error) *
                    std::min(double(raster.view_depth), double(oracle.view_depth)) +
                orthographic_depth_error(reference, polygon)};
}

SampleClass classify_sample(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                            const SampleEntry& oracle) {
    if (raster.triangle == oracle.triangle) {
        if (raster.triangle == kNoTriangle) return SampleClass::agree;
        if (!is_triangle(reference, raster.triangle)) return SampleClass::visibility;  // an id no scene triangle has
        const uint32_t id = raster.triangle;
        const glm::dvec3 bary_gap = glm::abs(glm::dvec3(raster.bary) - glm::dvec3(oracle.bary));
        const double depth_gap = std::fabs(double(raster.view_depth) - double(oracle.view_depth));
        // The rounding alone is a lower bound of the tolerance: most samples are settled without the spread.
        const RoundingAllowance rounding = rounding_allowance(reference, id, raster, oracle);
        if (std::max({bary_gap.x, bary_gap.y, bary_gap.z}) <= rounding.bary && depth_gap <= rounding.view_depth)
            return SampleClass::agree;
        const AgreementTolerance tolerance = agreement_tolerance(reference, id, screen);
        if (bary_gap.x > tolerance.bary.x || bary_gap.y > tolerance.bary.y || bary_gap.z > tolerance.bary.z ||
            !std::isfinite(bary_gap.x + bary_gap.y + bary_gap.z))
            return SampleClass::barycentrics;
        if (depth_gap > tolerance.view_depth || !std::isfinite(depth_gap)) return SampleClass::depth;
        return SampleClass::agree;
    }
    uint32_t involved[2];
    int count = 0;
    for (uint32_t id : {raster.triangle, oracle.triangle}) {
        if (id == kNoTriangle) continue;
        if (!is_triangle(reference, id)) return SampleClass::visibility;
        involved[count++] = id;
    }
    // A triangle whose facing is uncertain may be missing altogether (or present) wherever it covers the sample,
    // exactly or within its edge band; beyond that its facing changes nothing.
    for (int i = 0; i < count; ++i)
        if (reference.polygon(involved[i]).facing_uncertain &&
            (reference.contains(involved[i], screen) || in_edge_band(reference, involved[i], screen)))
            return SampleClass::facing;
    for (int i = 0; i < count; ++i)
        if (on_clip_boundary(reference, involved[i], screen)) return SampleClass::clip_boundary;
    for (int i = 0; i < count; ++i)
        if (in_edge_band(reference, involved[i], screen)) return SampleClass::edge_band;
    // Embree tests edge by edge, so beyond the band it may still show a triangle that exactly misses the sample.
    if (oracle.triangle != kNoTriangle && !reference.contains(oracle.triangle, screen) &&
        reference.embree_may_cover(oracle.triangle, screen))
        return SampleClass::edge_band;
    // ... and it may miss one that exactly covers the sample, where an edge's sign is within Embree's error.
    if (raster.triangle != kNoTriangle && reference.contains(raster.triangle, screen) &&
        reference.embree_may_miss(raster.triangle, screen))
        return SampleClass::edge_band;
    if (count == 2 && depth_tie(reference, involved[0], involved[1], screen)) return SampleClass::depth_tie;
    return SampleClass::visibility;
}

VisibilityComparison compare_visibility(const CompareInputs& in) {
    const RasterSamples& raster = in.raster;
    const SampleBuffer& oracle = *in.oracle;
    if (raster.width != oracle.width || raster.height != oracle.height || raster.samples != oracle.samples)
        throw std::invalid_argument("compare_visibility: the two visibility buffers have different sizes");
    VisibilityComparison result;
    result.classes.assign(oracle.size(), SampleClass::agree);
    const int height = oracle.height, width = oracle.width, samples = oracle.samples;
    std::vector<ComparisonCounts> row_counts(static_cast<size_t>(height));
    parallel_for(static_cast<size_t>(height), in.threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        ComparisonCounts& counts = row_counts[row];
        for (int px = 0; px < width; ++px) {
            for (int s = 0; s < samples; ++s) {
                const size_t at = oracle.index(px, py, s);
                const glm::dvec2 screen = glm::dvec2(px, py) + in.offsets[static_cast<size_t>(s)];
                const SampleClass verdict =
                    classify_sample(*in.reference, screen, sample_entry(raster, at), sample_entry(oracle, at));
                result.classes[at] = verdict;
                ++counts.by_class[static_cast<size_t>(verdict)];
            }
        }
    });
    for (const ComparisonCounts& counts : row_counts)
        for (int c = 0; c < kSampleClassCount; ++c) result.counts.by_class[c] += counts.by_class[c];
    return result;
}

}  // namespace raster::oracle
