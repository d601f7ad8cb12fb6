// The layer check: a grid of the transparent polygons for the near misses, then per sample its layers' verdicts.
#include "oracle/compare/layer_check.h"

#include <algorithm>
#include <cmath>

#include "oracle/compare/sample_classifier.h"
#include "raster/core/parallel.h"

namespace raster::oracle {
namespace {

constexpr int kCell = 16;  // pixels per side of a grid cell

// Per cell of kCell x kCell pixels, the transparent triangles whose polygon, grown by its radius and a pixel,
// reaches the cell.
class PolygonGrid {
public:
    PolygonGrid(const ReferenceGeometry& reference, const std::vector<uint32_t>& triangles, int width, int height)
        : columns_((width + kCell - 1) / kCell), rows_((height + kCell - 1) / kCell),
          cells_(static_cast<size_t>(columns_) * static_cast<size_t>(rows_)) {
        for (uint32_t id : triangles) {
            const auto vertices = reference.screen_vertices(id);
            if (vertices.empty()) continue;
            glm::dvec2 lo(INFINITY), hi(-INFINITY);
            for (const glm::dvec2& v : vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
            const double grow = reference.polygon(id).radius + 1.0;
            const int x0 = cell_of(lo.x - grow, columns_), x1 = cell_of(hi.x + grow, columns_);
            const int y0 = cell_of(lo.y - grow, rows_), y1 = cell_of(hi.y + grow, rows_);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) cells_[static_cast<size_t>(y) * columns_ + x].push_back(id);
        }
    }
    const std::vector<uint32_t>& near(int px, int py) const {
        return cells_[static_cast<size_t>(py / kCell) * columns_ + px / kCell];
    }

private:
    static int cell_of(double pixel, int cells) {
        if (!(pixel > 0.0)) return 0;
        return static_cast<int>(std::min<double>(cells - 1, std::floor(pixel / kCell)));
    }
    int columns_, rows_;
    std::vector<std::vector<uint32_t>> cells_;
};

// Whether raster may cover the sample with the triangle or not: within the radius of an edge, where it meets the
// near or far plane, or (culling on) where its facing is within the float error.
bool edge_open(const ReferenceGeometry& reference, uint32_t id, const glm::dvec2& screen) {
    return in_edge_band(reference, id, screen) || on_clip_boundary(reference, id, screen) ||
           (reference.polygon(id).facing_uncertain && reference.contains(id, screen));
}

}  // namespace

const char* to_string(LayerOpen open) {
    switch (open) {
        case LayerOpen::none: return "none";
        case LayerOpen::edge: return "edge";
        case LayerOpen::depth: return "depth";
        case LayerOpen::order: return "order";
    }
    return "?";
}

bool view_depth_tie(const ReferenceGeometry& reference, uint32_t a, double a_depth, uint32_t b, double b_depth,
                    const glm::dvec2& screen) {
    const double reach = agreement_tolerance(reference, a, screen).view_depth +
                         agreement_tolerance(reference, b, screen).view_depth;
    return !std::isfinite(reach) || std::fabs(a_depth - b_depth) <= reach;
}

LayerVerdicts check_layers(const LayerCheckInputs& in) {
    const SampleBuffer& oracle = *in.oracle;
    const ReferenceGeometry& reference = *in.reference;
    const SampleLayers& layers = *in.layers;
    LayerVerdicts out;
    out.open.assign(oracle.size(), LayerOpen::none);
    out.in_front.assign(layers.hits.size(), 0);
    const PolygonGrid grid(reference, in.transparent, oracle.width, oracle.height);
    parallel_for(static_cast<size_t>(oracle.height), in.threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        std::vector<uint32_t> kept;
        for (int px = 0; px < oracle.width; ++px)
            for (int s = 0; s < oracle.samples; ++s) {
                const size_t at = oracle.index(px, py, s);
                const glm::dvec2 screen = glm::dvec2(px, py) + in.offsets[static_cast<size_t>(s)];
                const uint32_t opaque = oracle.triangle[at];
                const double opaque_depth = oracle.view_depth[at];
                LayerOpen open = LayerOpen::none;
                auto note = [&](LayerOpen why) {
                    if (open == LayerOpen::none) open = why;
                };
                kept.clear();
                const LayerHit* hits = layers.of(at);
                for (size_t h = 0; h < layers.count(at); ++h) {
                    const LayerHit& hit = hits[h];
                    // A hit Embree reports where the exact triangle does not cover the sample (its edge test's
                    // own error): raster need not show it.
                    if (edge_open(reference, hit.triangle, screen) || !reference.contains(hit.triangle, screen))
                        note(LayerOpen::edge);
                    if (opaque != kNoTriangle) {
                        if (view_depth_tie(reference, hit.triangle, hit.view_depth, opaque, opaque_depth, screen)) {
                            note(LayerOpen::depth);
                            continue;
                        }
                        if (hit.view_depth > opaque_depth) continue;  // behind the opaque surface
                    }
                    out.in_front[layers.first[at] + h] = 1;
                    kept.push_back(static_cast<uint32_t>(h));
                }
                // Neighbours in depth order must not tie (the weighted average has no order).
                if (in.scene->settings.transparency.mode == TransparencyMode::sorted)
                    for (size_t k = 1; k < kept.size(); ++k) {
                        const LayerHit &a = hits[kept[k - 1]], &b = hits[kept[k]];
                        if (view_depth_tie(reference, a.triangle, a.view_depth, b.triangle, b.view_depth, screen))
                            note(LayerOpen::order);
                    }
                // A transparent triangle Embree did not hit but whose edge passes within the radius.
                for (uint32_t candidate : grid.near(px, py)) {
                    bool hit_already = false;
                    for (size_t h = 0; h < layers.count(at); ++h) hit_already = hit_already || hits[h].triangle == candidate;
                    // Embree missed it: open where raster may cover it (its clipped polygon's edge band, near and
                    // far edges included), and where the exact triangle covers the sample (Embree's edge test may
                    // miss what it covers). Not on_clip_boundary: away from the triangle its square's range is
                    // unbounded wherever the ray meets the plane behind the eye, which says nothing here.
                    if (hit_already) continue;
                    if (reference.polygon(candidate).culled && !reference.polygon(candidate).facing_uncertain) continue;
                    if (!in_edge_band(reference, candidate, screen) && !reference.contains(candidate, screen)) continue;
                    const ExactHit exact = reference.hit(candidate, screen);
                    if (opaque != kNoTriangle && exact.valid &&
                        !view_depth_tie(reference, candidate, exact.view_depth, opaque, opaque_depth, screen) &&
                        exact.view_depth > opaque_depth)
                        continue;  // behind the opaque surface whether it covers or not
                    note(LayerOpen::edge);
                }
                out.open[at] = open;
            }
    });
    return out;
}

}  // namespace raster::oracle
