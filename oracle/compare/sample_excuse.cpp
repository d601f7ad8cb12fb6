// Why a sample got its class, in figures (sample_excuse.h).
#include "oracle/compare/sample_excuse.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/common.hpp>


namespace raster::oracle {
namespace {

std::string triangle_name(uint32_t id) { return "triangle " + std::to_string(id); }

SampleExcuse figure(std::string rule, double measured, double bound) { return {std::move(rule), true, measured, bound}; }

SampleExcuse yes_or_no(std::string rule) { return {std::move(rule), false, 0.0, 0.0}; }

// The triangles a disagreement involves: the ids either renderer saw, the empty one left out.
std::vector<uint32_t> involved(const SampleEntry& raster, const SampleEntry& oracle) {
    std::vector<uint32_t> ids;
    for (uint32_t id : {raster.triangle, oracle.triangle})
        if (id != kNoTriangle) ids.push_back(id);
    return ids;
}

// The same triangle on both sides: the gap that decided (or came nearest to deciding) the class, against the bound
// the classifier held it to: both renderers' rounding first, then the full agreement tolerance.
SampleExcuse same_triangle(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                           const SampleEntry& oracle, SampleClass klass) {
    const uint32_t id = raster.triangle;
    const glm::dvec3 bary_gap = glm::abs(glm::dvec3(raster.bary) - glm::dvec3(oracle.bary));
    const double worst_bary = std::max({bary_gap.x, bary_gap.y, bary_gap.z});
    const double depth_gap = std::fabs(double(raster.view_depth) - double(oracle.view_depth));
    const RoundingAllowance rounding = rounding_allowance(reference, id, raster, oracle);
    if (klass == SampleClass::agree && worst_bary <= rounding.bary && depth_gap <= rounding.view_depth)
        return figure("barycentric gap on " + triangle_name(id) + " within both renderers' rounding", worst_bary,
                      rounding.bary);
    const AgreementTolerance tolerance = agreement_tolerance(reference, id, screen);
    // The component furthest past (or nearest to) its tolerance.
    int worst = 0;
    double worst_ratio = -1.0;
    for (int k = 0; k < 3; ++k) {
        const double ratio = bary_gap[k] / std::max(tolerance.bary[k], 1e-300);
        if (!(ratio <= worst_ratio)) worst = k, worst_ratio = ratio;  // a NaN gap is the worst
    }
    const SampleExcuse bary = figure("barycentric " + std::to_string(worst) + " gap on " + triangle_name(id),
                                     bary_gap[worst], tolerance.bary[worst]);
    const SampleExcuse depth = figure("view depth gap on " + triangle_name(id), depth_gap, tolerance.view_depth);
    if (klass == SampleClass::barycentrics) return bary;
    if (klass == SampleClass::depth) return depth;
    return depth_gap / std::max(tolerance.view_depth, 1e-300) > worst_ratio ? depth : bary;
}

SampleExcuse edge_band(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                       const SampleEntry& oracle) {
    for (uint32_t id : involved(raster, oracle)) {
        const double distance = reference.boundary_distance(id, screen), radius = reference.polygon(id).radius;
        if (distance <= radius) return figure("distance to an edge of " + triangle_name(id) + " (px)", distance, radius);
    }
    return yes_or_no(oracle.triangle != kNoTriangle && !reference.contains(oracle.triangle, screen)
                         ? "Embree's edge-by-edge test may show " + triangle_name(oracle.triangle) + ", which misses"
                         : "Embree's edge-by-edge test may miss " + triangle_name(raster.triangle) + ", which covers");
}

SampleExcuse clip_boundary(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                           const SampleEntry& oracle) {
    for (uint32_t id : involved(raster, oracle)) {
        if (!on_clip_boundary(reference, id, screen)) continue;
        const ReferencePolygon& polygon = reference.polygon(id);
        const SquareRange range = reference.range_around(id, screen, polygon.radius);
        if (!range.bounded) return yes_or_no(triangle_name(id) + "'s plane is grazed within the sample's square");
        const double low = range.min_view_depth - polygon.depth_error, high = range.max_view_depth + polygon.depth_error;
        const double middle = (low + high) / 2, half = (high - low) / 2;
        const bool near = std::fabs(reference.near() - middle) <= std::fabs(reference.far() - middle);
        const double plane = near ? reference.near() : reference.far();
        return figure(std::string(near ? "near" : "far") + " plane's distance from the middle of " +
                          triangle_name(id) + "'s view depths about the sample",
                      std::fabs(plane - middle), half);
    }
    return yes_or_no("a clip plane meets a triangle involved");
}

SampleExcuse depth_tie(const ReferenceGeometry& reference, const glm::dvec2& screen, uint32_t a, uint32_t b) {
    const ReversedZInterval ia = reversed_z_interval(reference, a, screen), ib = reversed_z_interval(reference, b, screen);
    const std::string rule = "reversed-z gap of " + triangle_name(a) + " and " + triangle_name(b);
    if (!ia.bounded || !ib.bounded) return yes_or_no(rule + ": a plane is grazed within the sample's square");
    // Two intervals overlap when their middles are no further apart than their half-widths together.
    return figure(rule, std::fabs((ia.lo + ia.hi) / 2 - (ib.lo + ib.hi) / 2), (ia.hi - ia.lo) / 2 + (ib.hi - ib.lo) / 2);
}

// No allowance held: the nearest edge of the triangles involved, beyond its band.
SampleExcuse no_allowance(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                          const SampleEntry& oracle) {
    SampleExcuse nearest = yes_or_no("no allowance");
    double best = std::numeric_limits<double>::infinity();
    for (uint32_t id : involved(raster, oracle)) {
        if (id >= reference.size()) return yes_or_no("triangle id " + std::to_string(id) + " is no scene triangle");
        const double distance = reference.boundary_distance(id, screen), radius = reference.polygon(id).radius;
        if (distance - radius < best) {
            best = distance - radius;
            nearest = figure("distance to an edge of " + triangle_name(id) + " (px), outside its band", distance, radius);
        }
    }
    return nearest;
}

}  // namespace

SampleExcuse sample_excuse(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                           const SampleEntry& oracle, SampleClass klass) {
    if (raster.triangle == oracle.triangle) {
        if (raster.triangle == kNoTriangle) return yes_or_no("no triangle on either side");
        if (raster.triangle >= reference.size()) return no_allowance(reference, screen, raster, oracle);
        return same_triangle(reference, screen, raster, oracle, klass);
    }
    switch (klass) {
        case SampleClass::edge_band: return edge_band(reference, screen, raster, oracle);
        case SampleClass::clip_boundary: return clip_boundary(reference, screen, raster, oracle);
        case SampleClass::depth_tie: return depth_tie(reference, screen, raster.triangle, oracle.triangle);
        case SampleClass::facing:
            for (uint32_t id : involved(raster, oracle))
                if (reference.polygon(id).facing_uncertain)
                    return yes_or_no(triangle_name(id) + " is within float error of edge-on: its facing is uncertain");
            return yes_or_no("a triangle's facing is uncertain");
        default: return no_allowance(reference, screen, raster, oracle);
    }
}

}  // namespace raster::oracle
