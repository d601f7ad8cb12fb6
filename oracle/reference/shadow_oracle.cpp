// The oracle's shadows: the ray's answer, the map's possible answers, and the verdict that joins them.
#include "oracle/reference/shadow_oracle.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "oracle/reference/precision.h"
#include "oracle/reference/shading_precision.h"
#include "oracle/reference/shadow_precision.h"

namespace raster::oracle {
namespace {

// A surface met closer to the point than this fraction of the way from the light is the receiver itself (its own
// plane, or a neighbour's at a shared edge), not an occluder.
constexpr double kReceiverFraction = 1e-6;

// A box whose points spread over more than this many face pixels is cut when the map's answer over it is open:
// the reference depth's interval then is several times the spread's depth change, and the quarters narrow it.
constexpr double kSplitTexels = 0.125;

}  // namespace

const char* to_string(ShadowVerdict verdict) {
    static const char* const names[kShadowVerdictCount] = {"lit", "shadowed", "open_edge", "open_depth", "inconsistent"};
    return names[static_cast<int>(verdict)];
}

ShadowOracle::ShadowOracle(const Scene& scene, const OracleScene& geometry, int threads)
    : scene_(scene), geometry_(geometry), index_of_light_(scene.lights.size(), -1) {
    // Transparent surfaces cast no shadow (docs/transparency.md): only opaque triangles occlude.
    std::vector<uint8_t> casts(geometry.triangles.size(), 1);
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id)
        casts[id] = !layered_material(triangle_material(scene, geometry.triangles[id]));
    for (size_t light = 0; light < scene.lights.size(); ++light) {
        if (!scene.lights[light].shadows) continue;
        index_of_light_[light] = static_cast<int>(indices_.size());
        indices_.push_back(std::make_unique<ShadowIndex>(scene, geometry, light, casts));
    }
    if (indices_.empty()) return;
    rays_ = std::make_unique<ShadowRays>(geometry, casts, threads);
    face_normal_.resize(geometry.triangles.size());
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
        const auto& v = geometry.triangles[id].vertex;
        glm::dvec3 world[3], error[3];
        for (int k = 0; k < 3; ++k) {
            world[k] = geometry.world[v[k]];
            error[k] = geometry.world_error[v[k]];
        }
        const glm::dvec3 n = glm::cross(world[1] - world[0], world[2] - world[0]);
        const double length = glm::length(n);
        face_normal_[id] = Interval3(length > 0.0 ? n / length : glm::dvec3(0.0)).widened(raster_face_normal_error(world, error));
    }
}

ShadowOracle::~ShadowOracle() = default;

Interval3 ShadowOracle::position_at(uint32_t id, const Interval3& bary) const {
    // raster's barycentrics sum to 1 within 3 float roundings (normalised in double, each rounded to float), so its
    // point is v0 + b1 (v1 - v0) + b2 (v2 - v0) + (sum b - 1) v0: with b1 and b2 free the box is the parallelogram's,
    // which quarters of b1 and b2 shrink, where three independent intervals would keep b0's width. Then raster's
    // float vertices (within their errors) and its 3-term float sum.
    const auto& v = geometry_.triangles[id].vertex;
    const glm::dvec3 &p0 = geometry_.world[v[0]], &p1 = geometry_.world[v[1]], &p2 = geometry_.world[v[2]];
    const Interval b0 = Interval(1.0) - bary.y - bary.z;
    const Interval weights[3] = {b0, bary.y, bary.z};
    Interval3 out;
    for (int c = 0; c < 3; ++c) {
        out[c] = Interval(p0[c]) + bary.y * Interval(p1[c] - p0[c]) + bary.z * Interval(p2[c] - p0[c]);
        double slack = 3.0 * kFloatUnitRoundoff * std::fabs(p0[c]), magnitude = 0.0;
        for (int k = 0; k < 3; ++k) {
            slack += weights[k].magnitude() * geometry_.world_error[v[k]][c];
            magnitude += weights[k].magnitude() * std::fabs(geometry_.world[v[k]][c]);
        }
        out[c] = out[c].widened(slack + float_gamma(kInterpolationRoundings) * magnitude + double_gamma(4) * magnitude);
    }
    return out;
}

bool ShadowOracle::exact_lit(size_t light, uint32_t receiver, const glm::dvec3& bary) const {
    const auto& v = geometry_.triangles[receiver].vertex;
    const glm::dvec3 point = bary.x * geometry_.world[v[0]] + bary.y * geometry_.world[v[1]] + bary.z * geometry_.world[v[2]];
    return !(rays_->first_surface(glm::dvec3(scene_.lights[light].position), point) < 1.0 - kReceiverFraction);
}

void ShadowOracle::map_answers(const ShadowIndex& index, const glm::dvec3& light, uint32_t receiver,
                               const Interval3& bary, int splits, MapAnswers& out) const {
    const std::vector<ShadowLookup> lookups =
        shadow_lookups(scene_.settings.shadows, light, position_at(receiver, bary), face_normal_[receiver]);
    if (lookups.empty()) {  // the point may be the light's own position
        out.depth = true;
        return;
    }
    MapAnswers here;
    here.lowest_reference = lookups[0].reference.lo;
    bool wide = false;  // the box's points reach over more than kSplitTexels of the face
    for (const ShadowLookup& lookup : lookups) {
        switch (index.answer(lookup.face, lookup.taps, lookup.reference)) {
            case MapAnswer::lit: here.lit = true; break;
            case MapAnswer::shadowed: here.shadowed = true; break;
            case MapAnswer::open_edge: here.edge = true; break;
            case MapAnswer::open_depth: here.depth = true; break;
        }
        here.lowest_reference = std::min(here.lowest_reference, lookup.reference.lo);
        here.deepest = std::max(here.deepest, lookup.depth.hi);
        wide = wide || lookup.x.hi - lookup.x.lo > kSplitTexels || lookup.y.hi - lookup.y.lo > kSplitTexels;
    }
    const bool open = here.edge || here.depth || (here.lit && here.shadowed);
    if (open && wide && splits > 0) {
        // Cut b1 and b2 (the free ones of position_at) in halves: four quarters.
        for (int quarter = 0; quarter < 4; ++quarter) {
            Interval3 piece = bary;
            for (int cut = 0; cut < 2; ++cut) {
                Interval& b = piece[1 + cut];
                const double middle = 0.5 * (b.lo + b.hi);
                b = (quarter >> cut) & 1 ? Interval(middle, b.hi) : Interval(b.lo, middle);
            }
            map_answers(index, light, receiver, piece, splits - 1, out);
        }
        return;
    }
    if (!out.lit && !out.shadowed && !out.edge && !out.depth) {
        out.lowest_reference = here.lowest_reference;
        out.deepest = here.deepest;
    }
    out.lit |= here.lit;
    out.shadowed |= here.shadowed;
    out.edge |= here.edge;
    out.depth |= here.depth;
    out.lowest_reference = std::min(out.lowest_reference, here.lowest_reference);
    out.deepest = std::max(out.deepest, here.deepest);
}

bool ShadowOracle::edge_near(size_t light, uint32_t receiver, const Interval3& bary) const {
    const ShadowIndex& index = *indices_[static_cast<size_t>(index_of_light_[light])];
    for (const ShadowLookup& lookup : shadow_lookups(scene_.settings.shadows, glm::dvec3(scene_.lights[light].position),
                                                     position_at(receiver, bary), face_normal_[receiver]))
        if (index.occluder_edge_within(lookup.face, lookup.footprint, lookup.depth.hi)) return true;
    return false;
}

LightVisibility ShadowOracle::visibility(size_t light, uint32_t receiver, const Interval3& bary) const {
    const glm::dvec3 light_position(scene_.lights[light].position);
    const glm::dvec3 centre_bary(0.5 * (bary.x.lo + bary.x.hi), 0.5 * (bary.y.lo + bary.y.hi),
                                 0.5 * (bary.z.lo + bary.z.hi));
    const auto& v = geometry_.triangles[receiver].vertex;
    const glm::dvec3 centre = centre_bary.x * geometry_.world[v[0]] + centre_bary.y * geometry_.world[v[1]] +
                              centre_bary.z * geometry_.world[v[2]];
    const double first = rays_->first_surface(light_position, centre);
    LightVisibility out;
    out.exact_lit = !(first < 1.0 - kReceiverFraction);
    out.allowed = Interval(0.0, 1.0);
    MapAnswers map;
    map_answers(*indices_[static_cast<size_t>(index_of_light_[light])], light_position, receiver, bary, kShadowSplits,
                map);
    if (map.depth || map.edge || (map.lit && map.shadowed)) {
        out.verdict = map.depth ? ShadowVerdict::open_depth : ShadowVerdict::open_edge;
        return out;
    }
    if (map.lit == out.exact_lit) {
        out.allowed = Interval(map.lit ? 1.0 : 0.0);
        out.verdict = map.lit ? ShadowVerdict::lit : ShadowVerdict::shadowed;
        return out;
    }
    // The taps and the ray disagree. Allowed where the ray's occluder lies within the bias of the receiver (the
    // map is built to miss it) or where an occluder's edge passes between the point's direction and the taps; else
    // the oracle's two views of the scene disagree.
    out.verdict = ShadowVerdict::inconsistent;
    if (map.lit && first * map.deepest >= map.lowest_reference) out.verdict = ShadowVerdict::open_depth;
    else if (edge_near(light, receiver, bary)) out.verdict = ShadowVerdict::open_edge;
    return out;
}

}  // namespace raster::oracle
