// The sample classifier: classes every sample of raster's visibility against the oracle's as agree, ambiguous
// (edge band, depth tie, clip boundary, facing) or genuine (visibility, barycentrics, depth), with the bounds of
// precision.h measured on the exact geometry of reference_geometry.h. Colour is judged per pixel (colour_check.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "oracle/compare/raster_output.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_buffer.h"
#include "raster/core/conventions.h"

namespace raster::oracle {

enum class SampleClass : uint8_t {
    agree,          // same triangle (within the barycentric, depth and colour bounds), or both empty
    edge_band,      // ambiguous: within the radius of an edge of a triangle involved, or where Embree's edge-by-edge
                    // test may show a triangle that exactly misses the sample (precision.h, section 5)
    depth_tie,      // ambiguous: both triangles cover the sample and their depths are within the tie bound
    clip_boundary,  // ambiguous: the sample is where a triangle involved meets the near or far plane
    facing,         // ambiguous: culling is on and a triangle involved is too close to edge-on to call its facing
    visibility,     // genuine: a different triangle (or none) outside every allowance
    barycentrics,   // genuine: same triangle, barycentrics apart by more than their bound
    depth,          // genuine: same triangle, view depths apart by more than their bound
};
inline constexpr int kSampleClassCount = 8;
const char* to_string(SampleClass c);  // "agree", "edge_band", ..., "depth"
inline bool is_ambiguous(SampleClass c) { return c >= SampleClass::edge_band && c <= SampleClass::facing; }
inline bool is_genuine(SampleClass c) { return c >= SampleClass::visibility; }

// One sample of a visibility buffer.
struct SampleEntry {
    uint32_t triangle = kNoTriangle;
    glm::vec3 bary{0.0f};
    float view_depth = 0.0f;
};
SampleEntry sample_entry(const RasterSamples& buffer, size_t index);
SampleEntry sample_entry(const SampleBuffer& buffer, size_t index);

// How far raster's and the oracle's barycentrics and view depth may be apart for triangle `id` at `screen`: the
// spread of the exact values over the square of half-side `radius`, plus both renderers' float rounding, plus
// Embree's own evaluation error of its barycentrics and depth at the sample.
// Unbounded (infinite) where the ray grazes the triangle's plane within the square.
struct AgreementTolerance {
    glm::dvec3 bary{0.0};
    double view_depth = 0;
};
AgreementTolerance agreement_tolerance(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen);
// Its barycentric part alone (what the colour check needs).
glm::dvec3 barycentric_tolerance(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen);

// The three allowances for a disagreement, one triangle (or a pair) at a time.
bool in_edge_band(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen);
bool on_clip_boundary(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen);
bool depth_tie(const ReferenceGeometry& reference, uint32_t a, uint32_t b, const glm::dvec2& screen);

// The reversed-z values triangle `id` may take over the sample's square (its exact extremes over the square of its
// radius, widened by its reversed-z error and Embree's at the sample); unbounded where the ray grazes its plane
// there. Larger is nearer. Two triangles tie where their intervals overlap.
struct ReversedZInterval {
    bool bounded = false;
    double lo = 0, hi = 0;
};
ReversedZInterval reversed_z_interval(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen);

// What both renderers' float rounding alone allows a sample that both show on triangle `id`: a barycentric gap and a
// view depth gap. Most samples are settled by it, before the agreement tolerance's spread is measured.
struct RoundingAllowance {
    double bary = 0, view_depth = 0;
};
RoundingAllowance rounding_allowance(const ReferenceGeometry& reference, uint32_t id, const SampleEntry& raster,
                                     const SampleEntry& oracle);

// Classes one sample at screen position `screen` from visibility alone (everything but colour).
SampleClass classify_sample(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                            const SampleEntry& oracle);

struct ComparisonCounts {
    std::array<uint64_t, kSampleClassCount> by_class{};
    uint64_t count(SampleClass c) const { return by_class[static_cast<size_t>(c)]; }
    uint64_t ambiguous_total() const;
    uint64_t genuine_total() const;
};

struct CompareInputs {
    RasterSamples raster;
    const SampleBuffer* oracle = nullptr;
    const ReferenceGeometry* reference = nullptr;
    std::vector<glm::dvec2> offsets;  // the sample positions inside a pixel (sample_positions.h)
    int threads = 0;
};

struct VisibilityComparison {
    ComparisonCounts counts;
    std::vector<SampleClass> classes;  // per sample, in visibility-buffer order
};

// Classes every sample (both buffers must have the same size, else std::invalid_argument). Deterministic for any
// thread count.
VisibilityComparison compare_visibility(const CompareInputs& inputs);

}  // namespace raster::oracle
