// Transparency: the A-buffer (sorted) and weighted-average passes over the opaque frame, band by band.
#include "raster/resolve/transparency.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>
#include <utility>

#include "raster/core/conventions.h"
#include "raster/core/errors.h"
#include "raster/core/parallel.h"
#include "raster/image/to_byte.h"
#include "raster/geometry/camera_rays.h"
#include "raster/rasterize/per_sample.h"

namespace raster {
namespace {

constexpr int kBandRows = 16;
constexpr uint32_t kEnd = 0xffffffffu;

// An A-buffer entry: one transparent fragment of one sample, in a per-sample list (newest first).
struct Fragment {
    uint32_t triangle;
    float view_depth;
    glm::vec3 bary;
    uint32_t next;
};
static_assert(sizeof(Fragment) == kFragmentBytes);

// What the weighted mode keeps per sample: sum a c, sum a, prod (1 - a).
struct WeightedSum {
    glm::vec3 color{0.0f};
    float alpha = 0.0f;
    float transmittance = 1.0f;
};

// A sample's blend: premultiplied colour and alpha.
struct Blend {
    glm::vec3 color{0.0f};
    float alpha = 0.0f;
};

// A fragment's shaded colour and opacity.
struct ShadedFragment {
    glm::vec3 colour{0.0f};
    float opacity = 1.0f;
};

// MSAA shades each triangle once per pixel, its opacity with it: what has been shaded so far in the pixel.
class PixelShadeCache {
public:
    PixelShadeCache(const Shader& shader, bool msaa) : shader_(shader), msaa_(msaa) {}
    void clear() { entries_.clear(); }
    glm::vec3 shade(uint32_t triangle, const glm::vec3& bary) {
        return msaa_ ? cached(triangle, bary).colour : shader_.shade(triangle, bary);
    }
    ShadedFragment fragment(uint32_t triangle, const glm::vec3& bary) {
        return msaa_ ? cached(triangle, bary) : ShadedFragment{shader_.shade(triangle, bary), shader_.opacity(triangle, bary)};
    }

private:
    const ShadedFragment& cached(uint32_t triangle, const glm::vec3& bary) {
        for (const auto& [id, shaded] : entries_)
            if (id == triangle) return shaded;
        entries_.emplace_back(triangle, ShadedFragment{shader_.shade(triangle, bary), shader_.opacity(triangle, bary)});
        return entries_.back().second;
    }

    const Shader& shader_;
    bool msaa_;
    std::vector<std::pair<uint32_t, ShadedFragment>> entries_;
};

// Calls visit(sample index in the band, hit) for every sample of rows [row_begin, row_end) that `t` covers in
// front of the opaque surface, pixel by pixel, samples in pattern order.
template <typename Visit>
void each_fragment(const TriangleSetup& t, int row_begin, int row_end, const FrameParams& frame,
                   const VisibilityBuffer& opaque, Visit visit) {
    const int samples = opaque.samples;
    const int y0 = std::max(t.min_y, row_begin), y1 = std::min(t.max_y, row_end - 1);
    const size_t band_first = opaque.index(0, row_begin, 0);
    for (int py = y0; py <= y1; ++py)
        for (int px = t.min_x; px <= t.max_x; ++px)
            for (int s = 0; s < samples; ++s) {
                const FixedPosition p = sample_fixed_position(px, py, s, frame.fixed_offsets, frame.fixed_bits);
                if (!covers(t, p.x, p.y)) continue;
                const SampleHit hit = interpolate_hit(t, p.x, p.y);
                const size_t at = opaque.index(px, py, s);
                if (opaque.triangle[at] != kNoTriangle && !(hit.view_depth < opaque.view_depth[at])) continue;
                visit(at - band_first, hit);
            }
}

// The pixel's bytes from its samples' blends over the opaque surface (or the background).
void write_pixel(const Blend* blends, int samples, const ResolveParams& params, uint8_t* out) {
    glm::vec3 sum(0.0f);
    float alpha = 0.0f;
    for (int s = 0; s < samples; ++s) {
        sum += params.alpha ? blends[s].color : blends[s].color + (1.0f - blends[s].alpha) * params.background;
        alpha += blends[s].alpha;
    }
    glm::vec3 colour = sum / static_cast<float>(samples);
    if (params.alpha) colour = alpha > 0.0f ? sum / alpha : params.background;
    for (int c = 0; c < 3; ++c) out[c] = to_byte(colour[c]);
    if (params.alpha) out[3] = to_byte(alpha / static_cast<float>(samples));
}

// The opaque surface's part of a sample's blend, under what the layers let through.
void add_opaque(const VisibilityBuffer& opaque, size_t at, float transmittance, PixelShadeCache& cache, Blend& blend) {
    if (opaque.triangle[at] == kNoTriangle) {
        blend.alpha = 1.0f - transmittance;
        return;
    }
    blend.color += transmittance * cache.shade(opaque.triangle[at], opaque.bary[at]);
    blend.alpha = 1.0f;
}

class BandCompositor {
public:
    BandCompositor(const TransparencyInputs& in, Image& image, std::atomic<int64_t>& kept, std::atomic<bool>& overflow)
        : in_(in), opaque_(*in.opaque), image_(image), kept_(kept), overflow_(overflow) {}

    void run(int row_begin, int row_end) {
        row_begin_ = row_begin;
        const size_t band_samples = static_cast<size_t>(row_end - row_begin) * opaque_.width * opaque_.samples;
        reached_.assign(band_samples, 0);
        if (in_.settings.mode == TransparencyMode::sorted) keep_fragments(row_begin, row_end, band_samples);
        else accumulate_fragments(row_begin, row_end, band_samples);
        if (overflow_) return;
        resolve_band(row_end);
    }

private:
    // sorted: every fragment into the band's A-buffer. The frame's count is claimed once per setup and band (not
    // per fragment: one shared counter would bounce between the cores), so the cap may be passed by one setup's
    // share of a band before the pass stops.
    void keep_fragments(int row_begin, int row_end, size_t band_samples) {
        heads_.assign(band_samples, kEnd);
        fragments_.clear();
        for (const TriangleSetup& t : *in_.setups) {
            if (t.max_y < row_begin || t.min_y >= row_end) continue;
            const size_t before = fragments_.size();
            each_fragment(t, row_begin, row_end, *in_.frame, opaque_, [&](size_t at, const SampleHit& hit) {
                fragments_.push_back({t.triangle_id, hit.view_depth, hit.bary, heads_[at]});
                heads_[at] = static_cast<uint32_t>(fragments_.size() - 1);
                reached_[at] = 1;
            });
            const auto added = static_cast<int64_t>(fragments_.size() - before);
            if (added > 0 && kept_.fetch_add(added) + added > in_.settings.max_fragments) overflow_ = true;
            if (overflow_) return;
        }
    }

    // weighted: each fragment shaded and added to its sample's sums. A clipped triangle's setups are consecutive
    // and share its id: they are taken together, so that MSAA shades the triangle once per pixel, at the first
    // sample (pattern order) any of them keeps.
    void accumulate_fragments(int row_begin, int row_end, size_t band_samples) {
        sums_.assign(band_samples, WeightedSum{});
        const std::vector<TriangleSetup>& setups = *in_.setups;
        const size_t samples = static_cast<size_t>(opaque_.samples);
        int64_t added = 0;
        for (size_t first = 0, last = 0; first < setups.size(); first = last) {
            const uint32_t triangle = setups[first].triangle_id;
            for (last = first; last < setups.size() && setups[last].triangle_id == triangle;) ++last;
            group_.clear();
            for (size_t k = first; k < last; ++k) {
                const TriangleSetup& t = setups[k];
                if (t.max_y < row_begin || t.min_y >= row_end) continue;
                each_fragment(t, row_begin, row_end, *in_.frame, opaque_,
                              [&](size_t at, const SampleHit& hit) { group_.push_back({at, hit.bary}); });
            }
            if (last - first > 1)  // pieces: their samples in pixel and pattern order
                std::sort(group_.begin(), group_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            size_t shaded_pixel = SIZE_MAX;
            glm::vec3 colour(0.0f);
            float a = 0.0f;
            for (const auto& [at, bary] : group_) {
                if (!in_.resolve.msaa || at / samples != shaded_pixel) {
                    colour = in_.shader->shade(triangle, bary);
                    a = in_.shader->opacity(triangle, bary);
                }
                shaded_pixel = at / samples;
                WeightedSum& sum = sums_[at];
                sum.color += a * colour;
                sum.alpha += a;
                sum.transmittance *= 1.0f - a;
                reached_[at] = 1;
            }
            added += static_cast<int64_t>(group_.size());
        }
        kept_.fetch_add(added);
    }

    // The sample's layers, sorted front to back (ties in draw order), blended.
    void blend_sorted(size_t band_at, size_t at, PixelShadeCache& cache, Blend& blend) {
        layers_.clear();
        for (uint32_t f = heads_[band_at]; f != kEnd; f = fragments_[f].next) layers_.push_back(&fragments_[f]);
        std::reverse(layers_.begin(), layers_.end());  // draw order
        std::stable_sort(layers_.begin(), layers_.end(),
                         [](const Fragment* a, const Fragment* b) { return a->view_depth < b->view_depth; });
        float transmittance = 1.0f;
        for (const Fragment* f : layers_) {
            const ShadedFragment shaded = cache.fragment(f->triangle, f->bary);
            blend.color += (transmittance * shaded.opacity) * shaded.colour;
            transmittance *= 1.0f - shaded.opacity;
        }
        add_opaque(opaque_, at, transmittance, cache, blend);
    }

    void blend_weighted(size_t band_at, size_t at, PixelShadeCache& cache, Blend& blend) {
        const WeightedSum& sum = sums_[band_at];
        if (sum.alpha > 0.0f) blend.color = (sum.color / sum.alpha) * (1.0f - sum.transmittance);
        add_opaque(opaque_, at, sum.transmittance, cache, blend);
    }

    void resolve_band(int row_end) {
        const int samples = opaque_.samples;
        PixelShadeCache cache(*in_.shader, in_.resolve.msaa);
        std::vector<Blend> blends(static_cast<size_t>(samples));
        size_t band_at = 0;
        for (int py = row_begin_; py < row_end; ++py)
            for (int px = 0; px < opaque_.width; ++px, band_at += static_cast<size_t>(samples)) {
                if (std::none_of(&reached_[band_at], &reached_[band_at] + samples, [](uint8_t r) { return r != 0; }))
                    continue;
                cache.clear();
                for (int s = 0; s < samples; ++s) {
                    blends[static_cast<size_t>(s)] = Blend{};
                    const size_t at = opaque_.index(px, py, s);
                    if (in_.settings.mode == TransparencyMode::sorted)
                        blend_sorted(band_at + static_cast<size_t>(s), at, cache, blends[static_cast<size_t>(s)]);
                    else
                        blend_weighted(band_at + static_cast<size_t>(s), at, cache, blends[static_cast<size_t>(s)]);
                }
                write_pixel(blends.data(), samples, in_.resolve, image_.at(px, py));
            }
    }

    const TransparencyInputs& in_;
    const VisibilityBuffer& opaque_;
    Image& image_;
    std::atomic<int64_t>& kept_;
    std::atomic<bool>& overflow_;
    int row_begin_ = 0;
    std::vector<uint8_t> reached_;      // per band sample: some fragment kept
    std::vector<uint32_t> heads_;       // sorted: per band sample, its newest fragment
    std::vector<Fragment> fragments_;   // sorted: the band's A-buffer
    std::vector<const Fragment*> layers_;
    std::vector<WeightedSum> sums_;     // weighted: per band sample
    std::vector<std::pair<size_t, glm::vec3>> group_;  // weighted: one triangle's fragments in the band
};

}  // namespace

size_t composite_transparency(const TransparencyInputs& in, Image& image) {
    if (in.setups->empty()) return 0;
    const int height = in.opaque->height;
    const size_t bands = static_cast<size_t>((height + kBandRows - 1) / kBandRows);
    std::atomic<int64_t> kept{0};
    std::atomic<bool> overflow{false};
    parallel_for(bands, in.frame->threads, [&](size_t band) {
        BandCompositor compositor(in, image, kept, overflow);
        const int row_begin = static_cast<int>(band) * kBandRows;
        compositor.run(row_begin, std::min(height, row_begin + kBandRows));
    });
    if (overflow)
        throw InputError("sorted transparency keeps more than " + std::to_string(in.settings.max_fragments) +
                         " transparent fragments in this frame (render.transparency.max_fragments, " +
                         std::to_string(kFragmentBytes) + " bytes each); raise it, lower the samples, or use "
                         "--transparency weighted, which keeps none");
    return static_cast<size_t>(kept.load());
}

}  // namespace raster
