// The oracle's shading in interval arithmetic: each step of the documented formula (docs/scene-format.md) over boxes, widened by raster's
// float error for that step (shading_precision.h).
#include "oracle/reference/shader.h"

#include "oracle/reference/precision.h"
#include "oracle/reference/shading_precision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace raster::oracle {
namespace {

Interval3 colour(const glm::vec3& c) { return Interval3(glm::dvec3(c)); }

// raster's float dot product of a and b: gamma_3 of sum_i |a_i| |b_i| (shading_precision.h).
Interval float_dot(const Interval3& a, const Interval3& b) {
    double magnitude = 0.0;
    for (int i = 0; i < 3; ++i) magnitude += a[i].magnitude() * b[i].magnitude();
    return dot(a, b).widened(float_gamma(kDotRoundings) * magnitude);
}

// a * b + c per component, with k roundings relative to |a| |b| + |c|.
Interval3 multiply_add(const Interval3& a, const Interval3& b, const Interval3& c, int k) {
    Interval3 out = a * b + c;
    for (int i = 0; i < 3; ++i)
        out[i] = out[i].widened(float_gamma(k) * (a[i].magnitude() * b[i].magnitude() + c[i].magnitude()));
    return out;
}

// raster's float normalisation of every vector in the box: its roundings per component (shading_precision.h).
Interval3 float_unit(const Interval3& difference) {
    return unit(difference).widened(float_gamma(kDirectionRoundings));
}

// The unit vector towards a light from the points of the box, as raster forms it in float (docs/scene-format.md
// "Lights"): along -direction for a directional light (normalised once), from the point to the light's position
// otherwise; and the squared distance (1 for a directional light, which is never attenuated).
struct TowardsLight {
    Interval3 to_light;
    Interval distance_squared{1.0};
};
TowardsLight towards_light(const Light& light, const Interval3& position) {
    if (light.type == LightType::directional) return {float_unit(Interval3(-glm::dvec3(light.direction))), Interval(1.0)};
    const Interval3 offset = after_roundings(Interval3(glm::dvec3(light.position)) - position, kDifferenceRoundings);
    return {float_unit(offset), float_dot(offset, offset)};
}

// A spot light's fade at the points whose unit vector to the light is in `to_light` (KHR_lights_punctual, as
// docs/scene-format.md "Lights" writes it): its constants in double, each rounded to float once, as the convention
// says; then cd = -dot(unit axis, to_light), f = clamp(cd scale + offset, 0, 1) (2 roundings) and f^2 (1).
Interval spot_fade(const Light& light, const Interval3& to_light) {
    const double inner = std::cos(static_cast<double>(light.inner_cone)), outer = std::cos(static_cast<double>(light.outer_cone));
    const double exact_scale = 1.0 / std::max(0.001, inner - outer);
    const double scale = static_cast<float>(exact_scale), offset = static_cast<float>(-outer * exact_scale);
    const Interval cd = -float_dot(float_unit(Interval3(glm::dvec3(light.direction))), to_light);
    const Interval raw = cd * Interval(scale) + Interval(offset);
    const Interval linear =
        raw.widened(float_gamma(2) * (cd.magnitude() * std::fabs(scale) + std::fabs(offset)));
    const Interval f(std::clamp(linear.lo, 0.0, 1.0), std::clamp(linear.hi, 0.0, 1.0));
    return after_roundings(square(f), 1);
}

// The sum of Ls visibility-scaled terms onto the first: a product and a sum each (flat, Gouraud).
inline constexpr int kCombineShadowRoundings = 2;

}  // namespace

// Per shading call: each light's visibility at the point, asked of the shadow oracle at most once.
class OracleShader::Visibility {
public:
    Visibility(const OracleShader& shader, uint32_t id, const Interval3& bary, ShadowTally* tally)
        : shader_(shader), id_(id), bary_(bary), tally_(tally), known_(shader.scene_.lights.size(), 0),
          value_(shader.scene_.lights.size(), Interval(1.0)) {}

    Interval at(size_t light) const {
        if (known_[light]) return value_[light];
        known_[light] = 1;
        if (!shader_.shadows_->casts(light)) return value_[light];
        switch (shader_.answer_) {
            case ShadowAnswer::open: value_[light] = Interval(0.0, 1.0); break;
            case ShadowAnswer::exact: {
                const glm::dvec3 centre(0.5 * (bary_.x.lo + bary_.x.hi), 0.5 * (bary_.y.lo + bary_.y.hi),
                                        0.5 * (bary_.z.lo + bary_.z.hi));
                value_[light] = Interval(shader_.shadows_->exact_lit(light, id_, centre) ? 1.0 : 0.0);
                break;
            }
            case ShadowAnswer::allowed: {
                const LightVisibility v = shader_.shadows_->visibility(light, id_, bary_);
                value_[light] = v.allowed;
                if (tally_) tally_->seen |= static_cast<uint8_t>(1u << static_cast<int>(v.verdict));
                break;
            }
        }
        return value_[light];
    }

private:
    const OracleShader& shader_;
    uint32_t id_;
    Interval3 bary_;
    ShadowTally* tally_;
    mutable std::vector<uint8_t> known_;
    mutable std::vector<Interval> value_;
};

OracleShader::OracleShader(const Scene& scene, const OracleScene& geometry, const ShadowOracle* shadows,
                           ShadowAnswer answer)
    : scene_(scene), geometry_(geometry), answer_(answer) {
    const ShadingMode mode = scene.settings.shading;
    for (const SceneMesh& mesh : scene.meshes) per_corner_ = per_corner_ || !mesh.parts.empty();
    if (has_textures(scene)) textures_ = std::make_unique<OracleTextureSampling>(scene, geometry);
    all_lights_.resize(scene.lights.size());
    std::iota(all_lights_.begin(), all_lights_.end(), size_t{0});
    if (!scene.lights.empty()) first_light_ = {0};
    if (shadows && mode != ShadingMode::unlit) {
        shadows_ = shadows;
        for (size_t light = 0; light < scene.lights.size(); ++light)
            (shadows->casts(light) ? shadowed_lights_ : unshadowed_lights_).push_back(light);
        if (!shadowed_lights_.empty() && (mode == ShadingMode::flat || mode == ShadingMode::gouraud))
            terms_stride_ = 1 + static_cast<int>(shadowed_lights_.size());
    }
    const size_t stride = static_cast<size_t>(terms_stride_);
    if (mode == ShadingMode::gouraud) {
        if (per_corner_) {
            vertex_terms_.resize(3 * geometry.triangles.size() * stride);
            for (uint32_t id = 0; id < geometry.triangles.size(); ++id)
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = geometry.triangles[id].vertex[k];
                    lit_terms(position_box(v), normal_box(v), material_of(id), &vertex_terms_[(3 * id + k) * stride]);
                }
        } else {
            vertex_terms_.resize(geometry.world.size() * stride);
            for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
                const uint32_t first = geometry.mesh_first_vertex[m];
                for (uint32_t i = 0; i < scene.meshes[m].data->positions.size(); ++i)
                    lit_terms(position_box(first + i), normal_box(first + i), scene.meshes[m].material,
                              &vertex_terms_[(first + i) * stride]);
            }
        }
    } else if (mode == ShadingMode::flat) {
        const bool per_face_terms = textures_ || terms_stride_ > 1;
        if (per_face_terms) face_terms_.resize(geometry.triangles.size() * stride);
        else face_color_.resize(geometry.triangles.size());
        std::vector<LitTerms> terms(stride);
        const Interval third = Interval(1.0 / 3.0).widened(kFloatUnitRoundoff / 3.0);  // raster's float 1/3
        for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
            const auto& v = geometry.triangles[id].vertex;
            glm::dvec3 world[3], error[3];
            Interval3 corners[3];
            for (int k = 0; k < 3; ++k) {
                world[k] = geometry.world[v[k]];
                error[k] = geometry.world_error[v[k]];
                corners[k] = position_box(v[k]);
            }
            const Interval3 centroid = float_interpolate(Interval3(third, third, third), corners);
            const glm::dvec3 n = glm::cross(world[1] - world[0], world[2] - world[0]);
            const double length = glm::length(n);
            const Interval3 normal = Interval3(length > 0.0 ? n / length : glm::dvec3(0.0))
                                         .widened(raster_face_normal_error(world, error));
            lit_terms(centroid, normal, material_of(id), terms.data());
            const Interval3 base = base_color(id, Interval3(third, third, third));
            if (!per_face_terms) {
                face_color_[id] = multiply_add(base, terms[0].diffuse, terms[0].specular, kCombineRoundings);
                continue;
            }
            for (size_t k = 0; k < stride; ++k)
                face_terms_[id * stride + k] = {after_roundings(base * terms[k].diffuse, 1), terms[k].specular};
        }
    }
}

void OracleShader::lit_terms(const Interval3& position, const Interval3& normal, const Material& material,
                             LitTerms* out) const {
    if (terms_stride_ == 1) {
        out[0] = light(position, normal, material, Model::blinn, all_lights_, true, nullptr);
        return;
    }
    out[0] = light(position, normal, material, Model::blinn, unshadowed_lights_, true, nullptr);
    for (size_t k = 0; k < shadowed_lights_.size(); ++k)
        out[1 + k] = light(position, normal, material, Model::blinn, {shadowed_lights_[k]}, false, nullptr);
}

OracleShader::LitTerms OracleShader::combined(const LitTerms* terms, const Visibility* visibility) const {
    LitTerms out = terms[0];
    if (terms_stride_ == 1) return out;
    glm::dvec3 diffuse_magnitude(0.0), specular_magnitude(0.0);
    for (int c = 0; c < 3; ++c) {
        diffuse_magnitude[c] = out.diffuse[c].magnitude();
        specular_magnitude[c] = out.specular[c].magnitude();
    }
    for (size_t k = 0; k < shadowed_lights_.size(); ++k) {
        const LitTerms& own = terms[1 + k];
        bool reaches = false;  // a light that adds nothing here needs no visibility
        for (int c = 0; c < 3; ++c)
            reaches = reaches || own.diffuse[c].lo != 0.0 || own.diffuse[c].hi != 0.0 || own.specular[c].lo != 0.0 ||
                      own.specular[c].hi != 0.0;
        if (!reaches) continue;
        const Interval v = visibility->at(shadowed_lights_[k]);
        out.diffuse = out.diffuse + v * own.diffuse;
        out.specular = out.specular + v * own.specular;
        for (int c = 0; c < 3; ++c) {
            diffuse_magnitude[c] += own.diffuse[c].magnitude();
            specular_magnitude[c] += own.specular[c].magnitude();
        }
    }
    const double rounding = float_gamma(kCombineShadowRoundings * static_cast<int>(shadowed_lights_.size()));
    for (int c = 0; c < 3; ++c) {
        out.diffuse[c] = out.diffuse[c].widened(rounding * diffuse_magnitude[c]);
        out.specular[c] = out.specular[c].widened(rounding * specular_magnitude[c]);
    }
    return out;
}

const Material& OracleShader::material_of(uint32_t id) const {
    return triangle_material(scene_, geometry_.triangles[id]);
}

const OracleShader::LitTerms* OracleShader::corner_terms(uint32_t id, int corner) const {
    const size_t stride = static_cast<size_t>(terms_stride_);
    return per_corner_ ? &vertex_terms_[(3 * id + corner) * stride]
                       : &vertex_terms_[geometry_.triangles[id].vertex[corner] * stride];
}

bool OracleShader::texture(uint32_t id, const Interval3& bary, Interval3& value) const {
    if (!textures_) return false;
    const Material& material = material_of(id);
    if (!material.texture) return false;
    value = textures_->at(id, material, bary);
    return true;
}

Interval OracleShader::opacity(uint32_t id, const Interval3& bary) const {
    const Material& material = material_of(id);
    if (!material.texture || !material.texture->reads_alpha || !textures_) return Interval(material.opacity);
    Interval alpha = Interval(material.opacity) * textures_->alpha_at(id, material, bary);
    // The product's rounding: relative, or a float subnormal's absolute step where it underflows.
    alpha = alpha.widened(float_gamma(1) * alpha.magnitude() + std::numeric_limits<float>::denorm_min());
    if (!material.alpha_cutoff) return alpha;
    const double cutoff = *material.alpha_cutoff;
    if (alpha.lo >= cutoff) return Interval(1.0);
    if (alpha.hi < cutoff) return Interval(0.0);
    return Interval(0.0, 1.0);
}

Interval3 OracleShader::position_box(uint32_t vertex) const {
    const glm::dvec3& p = geometry_.world[vertex];
    const glm::dvec3& e = geometry_.world_error[vertex];
    return {Interval(p.x).widened(e.x), Interval(p.y).widened(e.y), Interval(p.z).widened(e.z)};
}

Interval3 OracleShader::normal_box(uint32_t vertex) const {
    // A 2-norm bound bounds every component.
    return Interval3(geometry_.normal[vertex]).widened(geometry_.normal_error[vertex]);
}

Interval3 OracleShader::position_at(uint32_t id, const Interval3& bary) const {
    Interval3 positions[3];
    for (int k = 0; k < 3; ++k) positions[k] = position_box(geometry_.triangles[id].vertex[k]);
    return float_interpolate(bary, positions);
}

Interval3 OracleShader::base_color(uint32_t id, const Interval3& bary) const {
    const OracleTriangle& t = geometry_.triangles[id];
    const MeshData& mesh = *scene_.meshes[t.mesh].data;
    if (!mesh.face_colors.empty()) return colour(mesh.face_colors[t.local]);
    if (!mesh.colors.empty()) {
        const auto& v = mesh.triangles[t.local].v;
        const Interval3 corners[3] = {colour(mesh.colors[v[0]]), colour(mesh.colors[v[1]]), colour(mesh.colors[v[2]])};
        return float_interpolate(bary, corners);
    }
    return colour(material_of(id).color);
}

OracleShader::LitTerms OracleShader::light(const Interval3& position, const Interval3& normal, const Material& material,
                                           Model model, const std::vector<size_t>& lights, bool ambient,
                                           const Visibility* visibility) const {
    const bool phong = model == Model::phong, cel = model == Model::cel;
    const Interval3 zero(glm::dvec3(0.0));
    LitTerms terms;
    terms.diffuse = ambient ? multiply_add(colour(material.ambient), colour(scene_.settings.ambient_light), zero, 1) : zero;
    terms.specular = zero;
    // The sums' magnitudes, for the rounding of the L + 1 term sums.
    Interval3 diffuse_magnitude = terms.diffuse, specular_magnitude = zero;
    // The view vector (docs/conventions.md "Lighting"): towards the eye; orthographic, the back direction
    // normalize(eye - target) at every point.
    const Camera& camera = scene_.camera;
    const Interval3 to_eye = float_unit(after_roundings(
        Interval3(glm::dvec3(camera.eye)) -
            (camera.projection == Projection::orthographic ? Interval3(glm::dvec3(camera.target)) : position),
        kDifferenceRoundings));
    for (size_t index : lights) {
        const Light& light = scene_.lights[index];
        const auto [to_light, distance_squared] = towards_light(light, position);
        if (!(distance_squared.hi > 0.0)) continue;  // a light at the point: skipped, as raster skips it
        const Interval n_dot_l = float_dot(normal, to_light);
        if (!(n_dot_l.hi > 0.0)) continue;  // one-sided: behind the surface everywhere in the box
        // Only a light that may reach the point asks for its visibility; raster skips a light in full shadow.
        const Interval visible = visibility ? visibility->at(index) : Interval(1.0);
        if (visible.hi == 0.0) continue;
        const int shadow_rounding = visible.lo == 1.0 ? 0 : 1;  // raster multiplies by a visibility below 1
        // Where n.l (or r^2) may be on either side of 0, the light may or may not count.
        const Interval counts = n_dot_l.lo > 0.0 && distance_squared.lo > 0.0 ? Interval(1.0) : Interval(0.0, 1.0);
        Interval3 radiance = after_roundings(Interval(light.intensity) * colour(light.color), kRadianceRoundings);
        if (light.type == LightType::spot) radiance = after_roundings(spot_fade(light, to_light) * radiance, 1);
        if (light.attenuate && light.type != LightType::directional)
            radiance = after_roundings((Interval(1.0) / distance_squared) * radiance, 1);
        Interval lobe;
        if (phong) {
            const Interval3 scaled = after_roundings(Interval(2.0) * n_dot_l * normal, 1);
            const Interval3 reflected = after_roundings(scaled - to_light, 1);
            lobe = float_dot(reflected, to_eye);
        } else {
            const Interval3 half = after_roundings(to_light + to_eye, 1);
            const Interval half_length = after_roundings(sqrt(float_dot(half, half)), 1);
            lobe = half_length.lo > 0.0 ? after_roundings(float_dot(normal, half) / half_length, 1) : Interval(-1.0, 1.0);
        }
        Interval highlight =
            material.exponent == 0.0f ? Interval(1.0) : after_roundings(power(lobe, material.exponent), kPowerRoundings);
        Interval factor = positive_part(n_dot_l);
        Interval scale = visible;  // what multiplies both terms
        if (cel) {
            // Both sides of a band edge or of the highlight's threshold are possible inside their float error.
            // raster's product (v) n.l N rounds once or twice before its ceiling, and v s once before its threshold.
            const Interval shaded = after_roundings(factor * visible, shadow_rounding);
            const Interval scaled = shaded.widened(float_gamma(1) * shaded.magnitude());
            factor = Interval(cel_band(scaled.lo), cel_band(scaled.hi));
            const Interval dimmed = after_roundings(highlight * visible, shadow_rounding);
            const bool surely = lobe.lo > 0.0 && dimmed.lo >= 0.5, never = !(lobe.hi > 0.0) || dimmed.hi < 0.5;
            highlight = surely ? Interval(1.0) : never ? Interval(0.0) : Interval(0.0, 1.0);
            scale = Interval(1.0);
        }
        const int roundings = kTermRoundings + (cel ? 0 : shadow_rounding);
        const Interval3 diffuse = after_roundings(scale * factor * (colour(material.diffuse) * radiance), roundings);
        const Interval3 specular =
            after_roundings(scale * (counts * highlight) * (colour(material.specular) * radiance), roundings);
        terms.diffuse = terms.diffuse + diffuse;
        terms.specular = terms.specular + specular;
        for (int c = 0; c < 3; ++c) {
            diffuse_magnitude[c] = diffuse_magnitude[c] + Interval(diffuse[c].magnitude());
            specular_magnitude[c] = specular_magnitude[c] + Interval(specular[c].magnitude());
        }
    }
    const double sum_rounding = float_gamma(static_cast<int>(scene_.lights.size()) + 1);
    for (int c = 0; c < 3; ++c) {
        terms.diffuse[c] = terms.diffuse[c].widened(sum_rounding * diffuse_magnitude[c].magnitude());
        terms.specular[c] = terms.specular[c].widened(sum_rounding * specular_magnitude[c].magnitude());
    }
    return terms;
}

double OracleShader::cel_band(double n_dot_l) const {
    if (!(n_dot_l > 0.0)) return 0.0;
    const double bands = scene_.settings.cel_bands;
    return std::min(std::ceil(n_dot_l * bands), bands) / bands;
}

OracleShader::LitTerms OracleShader::gooch(const Interval3& position, const Interval3& normal, const Material& material,
                                           const Visibility* visibility) const {
    const GoochTones& tones = scene_.settings.gooch;
    Interval t(0.5);
    LitTerms terms;
    terms.specular = Interval3(glm::dvec3(0.0));
    if (!scene_.lights.empty()) {
        const auto [to_light, distance_squared] = towards_light(scene_.lights[0], position);
        const Interval visible = visibility ? visibility->at(0) : Interval(1.0);
        const Interval tilt = after_roundings(Interval(0.5) * (Interval(1.0) + float_dot(normal, to_light)) * visible,
                                              kGoochTiltRoundings + (visible.lo == 1.0 ? 0 : 1));
        // A light at the point leaves t at 1/2.
        t = distance_squared.lo > 0.0 ? tilt : hull(tilt, Interval(0.5));
        terms.specular = light(position, normal, material, Model::blinn, first_light_, false, visibility).specular;
    }
    const Interval blend = after_roundings(Interval(tones.alpha) + t * Interval(double(tones.beta) - tones.alpha),
                                           kGoochBlendRoundings);
    terms.diffuse = after_roundings(blend * colour(material.diffuse), 1);
    const Interval3 warm(Interval(tones.yellow), Interval(tones.yellow), Interval(0.0));
    const Interval3 cool(Interval(0.0), Interval(0.0), Interval(tones.blue));
    terms.specular = after_roundings(terms.specular + t * warm + (Interval(1.0) - t) * cool, kGoochToneRoundings);
    return terms;
}

Interval3 OracleShader::shade(uint32_t id, const Interval3& bary, ShadowTally* tally) const {
    Interval3 texel;
    const bool textured = texture(id, bary, texel);
    auto textured_base = [&](const Interval3& base) { return textured ? after_roundings(base * texel, 1) : base; };
    const OracleTriangle& t = geometry_.triangles[id];
    const ShadingMode mode = scene_.settings.shading;
    if (mode == ShadingMode::unlit) return textured_base(base_color(id, bary));
    std::unique_ptr<Visibility> visibility;
    if (shadows_ && !shadowed_lights_.empty()) visibility = std::make_unique<Visibility>(*this, id, bary, tally);
    switch (mode) {
        case ShadingMode::unlit: break;
        case ShadingMode::flat: {
            if (face_terms_.empty()) return face_color_[id];
            const LitTerms terms = combined(&face_terms_[id * static_cast<size_t>(terms_stride_)], visibility.get());
            if (textured) return multiply_add(texel, terms.diffuse, terms.specular, kCombineRoundings);
            return after_roundings(terms.diffuse + terms.specular, 1);
        }
        case ShadingMode::gouraud: {
            Interval3 corners[3], lit[3], highlight[3];
            for (int k = 0; k < 3; ++k) {
                Interval3 corner_bary(Interval(0.0), Interval(0.0), Interval(0.0));
                corner_bary[k] = Interval(1.0);
                const LitTerms terms = combined(corner_terms(id, k), visibility.get());
                const Interval3 base = base_color(id, corner_bary);
                if (textured) {
                    lit[k] = after_roundings(base * terms.diffuse, 1);
                    highlight[k] = terms.specular;
                } else {
                    corners[k] = multiply_add(base, terms.diffuse, terms.specular, kCombineRoundings);
                }
            }
            if (textured)
                return multiply_add(texel, float_interpolate(bary, lit), float_interpolate(bary, highlight), kCombineRoundings);
            return float_interpolate(bary, corners);
        }
        case ShadingMode::phong:
        case ShadingMode::blinn_phong:
        case ShadingMode::cel:
        case ShadingMode::gooch: {
            Interval3 normals[3];
            for (int k = 0; k < 3; ++k) normals[k] = normal_box(t.vertex[k]);
            const Interval3 position = position_at(id, bary);
            const Interval3 normal = float_unit(float_interpolate(bary, normals));
            const LitTerms terms =
                mode == ShadingMode::gooch ? gooch(position, normal, material_of(id), visibility.get())
                                           : light(position, normal, material_of(id),
                                                   mode == ShadingMode::phong ? Model::phong
                                                   : mode == ShadingMode::cel ? Model::cel
                                                                              : Model::blinn,
                                                   all_lights_, true, visibility.get());
            return multiply_add(textured_base(base_color(id, bary)), terms.diffuse, terms.specular, kCombineRoundings);
        }
    }
    return Interval3(glm::dvec3(0.0));
}

}  // namespace raster::oracle
