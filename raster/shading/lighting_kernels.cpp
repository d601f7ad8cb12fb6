// Lighting kernels over Highway: compiled once per SIMD target (foreach_target), dispatched at run time. Only
// IEEE-exact operations (add, subtract, multiply, divide, square root; no fused multiply-add, the file is built
// with -ffp-contract=off), in the order the formulas are written, so every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shading/lighting_kernels.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target

#include <hwy/highway.h>

#include <cmath>

#include "raster/shading/lighting_kernels.h"
#include "raster/core/unit_vector.h"
#include "raster/shading/light_direction.h"

HWY_BEFORE_NAMESPACE();
namespace raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;

struct Vec3 {
    V x, y, z;
};

inline V dot(const Vec3& a, const Vec3& b) {
    return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

inline Vec3 load3(const float (&rows)[3][LightingBatch::kRow], size_t i) {
    const D d;
    return {hn::LoadU(d, rows[0] + i), hn::LoadU(d, rows[1] + i), hn::LoadU(d, rows[2] + i)};
}

inline void store3(const Vec3& v, float (&rows)[3][LightingBatch::kRow], size_t i) {
    const D d;
    hn::StoreU(v.x, d, rows[0] + i);
    hn::StoreU(v.y, d, rows[1] + i);
    hn::StoreU(v.z, d, rows[2] + i);
}

// v / |v|, or zero where |v| is 0.
inline Vec3 unit_or_zero(const Vec3& v) {
    const D d;
    const V length = hn::Sqrt(dot(v, v));
    const auto positive = hn::Gt(length, hn::Zero(d));
    return {hn::IfThenElseZero(positive, hn::Div(v.x, length)), hn::IfThenElseZero(positive, hn::Div(v.y, length)),
            hn::IfThenElseZero(positive, hn::Div(v.z, length))};
}

void OrientPoints(LightingBatch& batch, size_t count, const Viewer& viewer) {
    const D d;
    const glm::vec3& eye = viewer.eye;
    const V eye_x = hn::Set(d, eye.x), eye_y = hn::Set(d, eye.y), eye_z = hn::Set(d, eye.z);
    for (size_t i = 0; i < count; i += hn::Lanes(d)) {
        store3(unit_or_zero(load3(batch.normal, i)), batch.normal, i);
        if (viewer.parallel) {
            store3(Vec3{hn::Set(d, viewer.back.x), hn::Set(d, viewer.back.y), hn::Set(d, viewer.back.z)}, batch.to_eye, i);
            continue;
        }
        const Vec3 position = load3(batch.position, i);
        const Vec3 to_eye{hn::Sub(eye_x, position.x), hn::Sub(eye_y, position.y), hn::Sub(eye_z, position.z)};
        store3(unit_or_zero(to_eye), batch.to_eye, i);
    }
}

// base^exponent for the highlight: repeated squaring for an integer exponent in [0, 256] (the same multiplications
// in every lane), std::pow lane by lane otherwise.
inline V specular_power(V base, float exponent) {
    const D d;
    if (exponent >= 0.0f && exponent <= 256.0f && exponent == std::floor(exponent)) {
        unsigned n = static_cast<unsigned>(exponent);
        V result = hn::Set(d, 1.0f), square = base;
        while (n) {
            if (n & 1u) result = hn::Mul(result, square);
            n >>= 1;
            if (n) square = hn::Mul(square, square);
        }
        return result;
    }
    HWY_ALIGN float lanes[kLanePadding];
    hn::Store(base, d, lanes);
    for (size_t k = 0; k < hn::Lanes(d); ++k) lanes[k] = std::pow(lanes[k], exponent);
    return hn::Load(d, lanes);
}

void LightPoints(LightingBatch& batch, size_t first, size_t count, const Material& material,
                 const std::vector<Light>& lights, const glm::vec3& ambient_light, SpecularModel model,
                 const float* visibility) {
    const D d;
    const V zero = hn::Zero(d);
    const V highlight_at_or_below_zero = hn::Set(d, material.exponent == 0.0f ? 1.0f : 0.0f);  // 0^0 = 1
    for (size_t i = first; i < first + count; i += hn::Lanes(d)) {
        const Vec3 normal = load3(batch.normal, i), to_eye = load3(batch.to_eye, i);
        const Vec3 position = load3(batch.position, i);
        V diffuse[3], specular[3];
        for (int c = 0; c < 3; ++c) {
            diffuse[c] = hn::Set(d, material.ambient[c] * ambient_light[c]);
            specular[c] = zero;
        }
        for (size_t index = 0; index < lights.size(); ++index) {
            const Light& light = lights[index];
            const V visible = visibility ? hn::LoadU(d, visibility + index * LightingBatch::kRow + i) : hn::Set(d, 1.0f);
            const bool directional = light.type == LightType::directional;
            Vec3 to_light;
            V distance_squared = hn::Set(d, 1.0f);  // a directional light is never attenuated and never on the point
            if (directional) {
                const glm::vec3 unit = directional_to_light(light);
                to_light = {hn::Set(d, unit.x), hn::Set(d, unit.y), hn::Set(d, unit.z)};
            } else {
                to_light = {hn::Sub(hn::Set(d, light.position.x), position.x),
                            hn::Sub(hn::Set(d, light.position.y), position.y),
                            hn::Sub(hn::Set(d, light.position.z), position.z)};
                distance_squared = dot(to_light, to_light);
                const V distance = hn::Sqrt(distance_squared);
                to_light = {hn::Div(to_light.x, distance), hn::Div(to_light.y, distance), hn::Div(to_light.z, distance)};
            }
            const V n_dot_l = dot(normal, to_light);
            V fade = hn::Set(d, 1.0f);
            if (light.type == LightType::spot) {  // light_direction.h spot_factor, lane by lane
                const SpotFade cone = spot_fade(light);
                const glm::vec3 axis = raster::unit_or_zero(light.direction);
                const V cd = hn::Neg(dot(Vec3{hn::Set(d, axis.x), hn::Set(d, axis.y), hn::Set(d, axis.z)}, to_light));
                const V f = hn::Min(hn::Max(hn::Add(hn::Mul(cd, hn::Set(d, cone.scale)), hn::Set(d, cone.offset)), zero),
                                    hn::Set(d, 1.0f));
                fade = hn::Mul(f, f);
            }
            // The light adds nothing where it sits on the point, lies behind the surface, or is in shadow.
            const auto arrives = hn::And(hn::And(hn::Gt(distance_squared, zero), hn::Gt(n_dot_l, zero)),
                                         hn::Not(hn::Eq(visible, zero)));  // Eq: NaN-safe on every target
            V lobe;
            if (model == SpecularModel::blinn) {
                const Vec3 half{hn::Add(to_light.x, to_eye.x), hn::Add(to_light.y, to_eye.y),
                                hn::Add(to_light.z, to_eye.z)};
                const V half_length_squared = dot(half, half);
                lobe = hn::IfThenElseZero(hn::Gt(half_length_squared, zero),
                                          hn::Div(dot(normal, half), hn::Sqrt(half_length_squared)));
            } else {
                const V twice_n_dot_l = hn::Mul(hn::Set(d, 2.0f), n_dot_l);
                const Vec3 reflected{hn::Sub(hn::Mul(twice_n_dot_l, normal.x), to_light.x),
                                     hn::Sub(hn::Mul(twice_n_dot_l, normal.y), to_light.y),
                                     hn::Sub(hn::Mul(twice_n_dot_l, normal.z), to_light.z)};
                lobe = dot(reflected, to_eye);
            }
            const V highlight = hn::IfThenElse(hn::Gt(lobe, zero), specular_power(lobe, material.exponent),
                                               highlight_at_or_below_zero);
            for (int c = 0; c < 3; ++c) {
                const float radiance_c = light.color[c] * light.intensity;
                V radiance = hn::Set(d, radiance_c);
                if (light.type == LightType::spot) radiance = hn::Mul(radiance, fade);
                if (light.attenuate && !directional) radiance = hn::Div(radiance, distance_squared);
                V lit = hn::Mul(hn::Mul(radiance, hn::Set(d, material.diffuse[c])), n_dot_l);
                V shine = hn::Mul(hn::Mul(radiance, hn::Set(d, material.specular[c])), highlight);
                if (visibility) {
                    lit = hn::Mul(lit, visible);
                    shine = hn::Mul(shine, visible);
                }
                diffuse[c] = hn::Add(diffuse[c], hn::IfThenElseZero(arrives, lit));
                specular[c] = hn::Add(specular[c], hn::IfThenElseZero(arrives, shine));
            }
        }
        for (int c = 0; c < 3; ++c) {
            hn::StoreU(diffuse[c], d, batch.diffuse[c] + i);
            hn::StoreU(specular[c], d, batch.specular[c] + i);
        }
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace raster {

HWY_EXPORT(OrientPoints);
HWY_EXPORT(LightPoints);

void orient_points(LightingBatch& batch, size_t count, const Viewer& viewer) {
    HWY_DYNAMIC_DISPATCH(OrientPoints)(batch, count, viewer);
}

void light_points(LightingBatch& batch, size_t first, size_t count, const Material& material,
                  const std::vector<Light>& lights, const glm::vec3& ambient_light, SpecularModel model,
                  const float* visibility) {
    HWY_DYNAMIC_DISPATCH(LightPoints)(batch, first, count, material, lights, ambient_light, model, visibility);
}

}  // namespace raster
#endif  // HWY_ONCE
