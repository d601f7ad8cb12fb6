// The oracle's shading, written from the documented formula (docs/scene-format.md), evaluated over boxes of
// barycentrics in interval arithmetic: for a triangle and a box around a sample's exact barycentrics it gives every
// linear colour a correct raster may compute there, its float error included (shading_precision.h). A box of zero
// width gives the documented colour at a point, within float error.
//
//   colour = base * (ambient * ambient_light + sum_lights diffuse * I * max(0, n.l)) + sum_lights specular * I * s
//   I = light colour * intensity (/ r^2 with attenuation); s = max(0, lobe)^exponent (1 when the exponent is 0)
//   lobe = n.h with h = normalize(l + v) (flat, Gouraud, Blinn-Phong), or r.v with r = 2 (n.l) n - l (Phong)
//   a light with n.l <= 0 adds nothing (one-sided); base = face colour, else the interpolated vertex colour, else
//   the material colour. Unlit: base. Flat: lit once at the centroid with the face normal. Gouraud: lit at each
//   vertex, colours interpolated. Phong, Blinn-Phong: lit at the sample, the normal interpolated and renormalised.
//   Lighting is in world space: light positions and the eye are world points, v and l point from the surface.
//   Cel: n.l in the diffuse term replaced by ceil(n.l N) / N, the highlight by the light's full specular where
//   s >= 1/2 and none elsewhere. Gooch: t = (1 + n.l) / 2 to the first light (1/2 without one), colour =
//   base diffuse (alpha + t (beta - alpha)) + t (y, y, 0) + (1 - t) (0, 0, b) + the first light's Blinn highlight.
//   Near a band's edge or the highlight's threshold the interval holds both sides: either is correct there.
//   Textures (docs/textures.md): the texture's value multiplies the base colour, and for Gouraud and flat the lit
//   base * diffuse but not the highlight: colour = T (base * diffuse) + specular.
//   Shadows (docs/shadows.md): each light that casts shadows is scaled by its visibility v at the shaded point:
//   its diffuse and specular terms (Phong, Blinn-Phong; flat and Gouraud per sample, their terms kept per light),
//   cel's banded v n.l and highlight where v s >= 1/2, Gooch's t and highlight. v is what the ShadowOracle says,
//   in one of three ways (ShadowAnswer).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "oracle/reference/interval.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shadow_oracle.h"
#include "oracle/reference/texture_sampling.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// Which visibility a light that casts shadows gets:
enum class ShadowAnswer {
    exact,    // the ray-traced answer (0 or 1): the oracle's own image
    allowed,  // what a correct shadow map may give there: the colour check
    open,     // anything in [0, 1]: to tell a pixel wrong only by its shadows from one wrong otherwise
};

// What the shadow verdicts of one shading call were, for the lights that may reach the point.
struct ShadowTally {
    uint8_t seen = 0;  // bit v: ShadowVerdict v was met
};

class OracleShader {
public:
    // Holds references to `scene`, `geometry` and `shadows` (none when no light casts shadows), which must outlive it.
    OracleShader(const Scene& scene, const OracleScene& geometry, const ShadowOracle* shadows = nullptr,
                 ShadowAnswer answer = ShadowAnswer::allowed);

    // Linear RGB of triangle `id` for every barycentric triple in `bary`, unclamped; `tally` (optional) gets the
    // shadow verdicts met.
    Interval3 shade(uint32_t id, const Interval3& bary, ShadowTally* tally = nullptr) const;
    // Every opacity raster may compute for triangle `id` at barycentrics in `bary` (docs/transparency.md): its
    // material's, times its texture's alpha (and the product's rounding) where the texture reads alpha; a cut-out's
    // 1 where all of those are at least the cut-off, 0 where none is, and [0, 1] where the box straddles it.
    Interval opacity(uint32_t id, const Interval3& bary) const;

private:
    struct LitTerms {
        Interval3 diffuse;   // ambient included
        Interval3 specular;
    };
    // Which lobe and diffuse factor light() evaluates.
    enum class Model { blinn, phong, cel };
    class Visibility;  // per shading call: the lights' visibility at the point, asked for lazily
    // Ambient (when `ambient`) and the lights `lights` (scene indices), each scaled by its visibility.
    LitTerms light(const Interval3& position, const Interval3& normal, const Material& material, Model model,
                   const std::vector<size_t>& lights, bool ambient, const Visibility* visibility) const;
    double cel_band(double n_dot_l) const;  // ceil(n.l N) / N, 0 where n.l <= 0
    LitTerms gooch(const Interval3& position, const Interval3& normal, const Material& material,
                   const Visibility* visibility) const;
    // Flat and Gouraud: `terms_stride_` entries (ambient and the lights without shadows, then each light with
    // shadows alone) for a point, and their sum with each shadowed light scaled by its visibility.
    void lit_terms(const Interval3& position, const Interval3& normal, const Material& material, LitTerms* out) const;
    LitTerms combined(const LitTerms* terms, const Visibility* visibility) const;
    // The texture's value box when the triangle's material has a texture.
    bool texture(uint32_t id, const Interval3& bary, Interval3& value) const;
    const LitTerms* corner_terms(uint32_t id, int corner) const;
    Interval3 base_color(uint32_t id, const Interval3& bary) const;
    // A vertex's world position and unit normal as boxes that hold raster's float versions.
    Interval3 position_box(uint32_t vertex) const;
    Interval3 normal_box(uint32_t vertex) const;
    Interval3 position_at(uint32_t id, const Interval3& bary) const;
    const Material& material_of(uint32_t id) const;

    const Scene& scene_;
    const OracleScene& geometry_;
    const ShadowOracle* shadows_ = nullptr;
    ShadowAnswer answer_ = ShadowAnswer::allowed;
    std::vector<size_t> all_lights_, first_light_, unshadowed_lights_, shadowed_lights_;
    int terms_stride_ = 1;                // flat and Gouraud: 1 + the lights with shadows, when there are any
    bool per_corner_ = false;             // a mesh has several materials: Gouraud terms per triangle corner
    std::vector<LitTerms> vertex_terms_;  // Gouraud: per vertex, or per corner (3 id + k); terms_stride_ each
    std::vector<Interval3> face_color_;   // flat without textures or shadows: per triangle, base * diffuse + specular
    std::vector<LitTerms> face_terms_;    // flat otherwise: per triangle, terms_stride_ of base * diffuse, specular
    std::unique_ptr<OracleTextureSampling> textures_;  // textured scenes only
};

}  // namespace raster::oracle
