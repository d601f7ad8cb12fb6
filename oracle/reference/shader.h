// The oracle's shading, written from the README's formula, evaluated over boxes of barycentrics in interval
// arithmetic: for a triangle and a box around a sample's exact barycentrics it gives every linear colour a correct
// raster may compute there, its float error included (shading_precision.h). A box of zero width gives the
// README's colour at a point, within float error.
//
//   colour = base * (ambient * ambient_light + sum_lights diffuse * I * max(0, n.l)) + sum_lights specular * I * s
//   I = light colour * intensity (/ r^2 with attenuation); s = max(0, lobe)^exponent (1 when the exponent is 0)
//   lobe = n.h with h = normalize(l + v) (flat, Gouraud, Blinn-Phong), or r.v with r = 2 (n.l) n - l (Phong)
//   a light with n.l <= 0 adds nothing (one-sided); base = face colour, else the interpolated vertex colour, else
//   the material colour. Unlit: base. Flat: lit once at the centroid with the face normal. Gouraud: lit at each
//   vertex, colours interpolated. Phong, Blinn-Phong: lit at the sample, the normal interpolated and renormalised.
//   Lighting is in world space: light positions and the eye are world points, v and l point from the surface.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/reference/interval.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

class OracleShader {
public:
    // Holds references to `scene` and `geometry`, which must outlive it.
    OracleShader(const Scene& scene, const OracleScene& geometry);

    // Linear RGB of triangle `id` for every barycentric triple in `bary`, unclamped.
    Interval3 shade(uint32_t id, const Interval3& bary) const;

private:
    struct LitTerms {
        Interval3 diffuse;   // ambient included
        Interval3 specular;
    };
    LitTerms light(const Interval3& position, const Interval3& normal, const Material& material, bool phong) const;
    Interval3 base_color(uint32_t id, const Interval3& bary) const;
    // A vertex's world position and unit normal as boxes that hold raster's float versions.
    Interval3 position_box(uint32_t vertex) const;
    Interval3 normal_box(uint32_t vertex) const;
    const Material& material_of(uint32_t id) const;

    const Scene& scene_;
    const OracleScene& geometry_;
    std::vector<LitTerms> vertex_terms_;  // Gouraud: per vertex
    std::vector<Interval3> face_color_;   // flat: per triangle
};

}  // namespace raster::oracle
