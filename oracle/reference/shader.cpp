// The oracle's shading in interval arithmetic: each step of the README's formula over boxes, widened by raster's
// float error for that step (shading_precision.h).
#include "oracle/reference/shader.h"

#include "oracle/reference/precision.h"
#include "oracle/reference/shading_precision.h"

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

// sum_i b_i v_i with its rounding, gamma_3 of sum_i |b_i| |v_i| per component.
Interval3 interpolate(const Interval3& bary, const Interval3 values[3]) {
    Interval3 out = bary.x * values[0] + bary.y * values[1] + bary.z * values[2];
    for (int c = 0; c < 3; ++c) {
        double magnitude = 0.0;
        for (int i = 0; i < 3; ++i) magnitude += bary[i].magnitude() * values[i][c].magnitude();
        out[c] = out[c].widened(float_gamma(kInterpolationRoundings) * magnitude);
    }
    return out;
}

}  // namespace

OracleShader::OracleShader(const Scene& scene, const OracleScene& geometry) : scene_(scene), geometry_(geometry) {
    const ShadingMode mode = scene.settings.shading;
    for (const SceneMesh& mesh : scene.meshes) per_corner_ = per_corner_ || !mesh.parts.empty();
    if (has_textures(scene)) textures_ = std::make_unique<OracleTextureSampling>(scene, geometry);
    if (mode == ShadingMode::gouraud) {
        const size_t lights = scene.lights.size();
        if (per_corner_) {
            vertex_terms_.resize(3 * geometry.triangles.size());
            for (uint32_t id = 0; id < geometry.triangles.size(); ++id)
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = geometry.triangles[id].vertex[k];
                    vertex_terms_[3 * id + k] = light(position_box(v), normal_box(v), material_of(id), Model::blinn, lights);
                }
        } else {
            vertex_terms_.resize(geometry.world.size());
            for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
                const uint32_t first = geometry.mesh_first_vertex[m];
                for (uint32_t i = 0; i < scene.meshes[m].data.positions.size(); ++i)
                    vertex_terms_[first + i] = light(position_box(first + i), normal_box(first + i),
                                                     scene.meshes[m].material, Model::blinn, lights);
            }
        }
    } else if (mode == ShadingMode::flat) {
        face_color_.resize(geometry.triangles.size());
        if (textures_) face_terms_.resize(geometry.triangles.size());
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
            const Interval3 centroid = interpolate(Interval3(third, third, third), corners);
            const glm::dvec3 n = glm::cross(world[1] - world[0], world[2] - world[0]);
            const double length = glm::length(n);
            const Interval3 normal = Interval3(length > 0.0 ? n / length : glm::dvec3(0.0))
                                         .widened(raster_face_normal_error(world, error));
            const LitTerms terms = light(centroid, normal, material_of(id), Model::blinn, scene.lights.size());
            const Interval3 base = base_color(id, Interval3(third, third, third));
            face_color_[id] = multiply_add(base, terms.diffuse, terms.specular, kCombineRoundings);
            if (textures_) face_terms_[id] = {after_roundings(base * terms.diffuse, 1), terms.specular};
        }
    }
}

const Material& OracleShader::material_of(uint32_t id) const {
    return triangle_material(scene_, geometry_.triangles[id]);
}

const OracleShader::LitTerms& OracleShader::corner_terms(uint32_t id, int corner) const {
    return per_corner_ ? vertex_terms_[3 * id + corner] : vertex_terms_[geometry_.triangles[id].vertex[corner]];
}

bool OracleShader::texture(uint32_t id, const Interval3& bary, Interval3& value) const {
    if (!textures_) return false;
    const Material& material = material_of(id);
    if (!material.texture) return false;
    value = textures_->at(id, material, bary);
    return true;
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

Interval3 OracleShader::base_color(uint32_t id, const Interval3& bary) const {
    const OracleTriangle& t = geometry_.triangles[id];
    const MeshData& mesh = scene_.meshes[t.mesh].data;
    if (!mesh.face_colors.empty()) return colour(mesh.face_colors[t.local]);
    if (!mesh.colors.empty()) {
        const auto& v = mesh.triangles[t.local].v;
        const Interval3 corners[3] = {colour(mesh.colors[v[0]]), colour(mesh.colors[v[1]]), colour(mesh.colors[v[2]])};
        return interpolate(bary, corners);
    }
    return colour(material_of(id).color);
}

OracleShader::LitTerms OracleShader::light(const Interval3& position, const Interval3& normal, const Material& material,
                                           Model model, size_t light_count) const {
    const bool phong = model == Model::phong, cel = model == Model::cel;
    const Interval3 zero(glm::dvec3(0.0));
    LitTerms terms;
    terms.diffuse = multiply_add(colour(material.ambient), colour(scene_.settings.ambient_light), zero, 1);
    terms.specular = zero;
    // The sums' magnitudes, for the rounding of the L + 1 term sums.
    Interval3 diffuse_magnitude = terms.diffuse, specular_magnitude = zero;
    const Interval3 to_eye =
        float_unit(after_roundings(Interval3(glm::dvec3(scene_.camera.eye)) - position, kDifferenceRoundings));
    for (size_t index = 0; index < light_count; ++index) {
        const Light& light = scene_.lights[index];
        const Interval3 offset = after_roundings(Interval3(glm::dvec3(light.position)) - position, kDifferenceRoundings);
        const Interval distance_squared = float_dot(offset, offset);
        if (!(distance_squared.hi > 0.0)) continue;  // a light at the point: skipped, as raster skips it
        const Interval3 to_light = float_unit(offset);
        const Interval n_dot_l = float_dot(normal, to_light);
        if (!(n_dot_l.hi > 0.0)) continue;  // one-sided: behind the surface everywhere in the box
        // Where n.l (or r^2) may be on either side of 0, the light may or may not count.
        const Interval counts = n_dot_l.lo > 0.0 && distance_squared.lo > 0.0 ? Interval(1.0) : Interval(0.0, 1.0);
        Interval3 radiance = after_roundings(Interval(light.intensity) * colour(light.color), kRadianceRoundings);
        if (light.attenuate) radiance = after_roundings((Interval(1.0) / distance_squared) * radiance, 1);
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
        if (cel) {
            // Both sides of a band edge or of the highlight's threshold are possible inside their float error.
            // raster's product n.l N rounds once before its ceiling.
            const Interval scaled = factor.widened(float_gamma(1) * factor.magnitude());
            factor = Interval(cel_band(scaled.lo), cel_band(scaled.hi));
            const bool surely = lobe.lo > 0.0 && highlight.lo >= 0.5, never = !(lobe.hi > 0.0) || highlight.hi < 0.5;
            highlight = surely ? Interval(1.0) : never ? Interval(0.0) : Interval(0.0, 1.0);
        }
        const Interval3 diffuse = after_roundings(factor * (colour(material.diffuse) * radiance), kTermRoundings);
        const Interval3 specular = after_roundings((counts * highlight) * (colour(material.specular) * radiance),
                                                   kTermRoundings);
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

OracleShader::LitTerms OracleShader::gooch(const Interval3& position, const Interval3& normal,
                                           const Material& material) const {
    const GoochTones& tones = scene_.settings.gooch;
    Interval t(0.5);
    LitTerms terms;
    terms.specular = Interval3(glm::dvec3(0.0));
    if (!scene_.lights.empty()) {
        const Interval3 offset =
            after_roundings(Interval3(glm::dvec3(scene_.lights[0].position)) - position, kDifferenceRoundings);
        const Interval tilt = after_roundings(Interval(0.5) * (Interval(1.0) + float_dot(normal, float_unit(offset))),
                                              kGoochTiltRoundings);
        // A light at the point leaves t at 1/2.
        t = float_dot(offset, offset).lo > 0.0 ? tilt : hull(tilt, Interval(0.5));
        terms.specular = light(position, normal, material, Model::blinn, 1).specular;
    }
    const Interval blend = after_roundings(Interval(tones.alpha) + t * Interval(double(tones.beta) - tones.alpha),
                                           kGoochBlendRoundings);
    terms.diffuse = after_roundings(blend * colour(material.diffuse), 1);
    const Interval3 warm(Interval(tones.yellow), Interval(tones.yellow), Interval(0.0));
    const Interval3 cool(Interval(0.0), Interval(0.0), Interval(tones.blue));
    terms.specular = after_roundings(terms.specular + t * warm + (Interval(1.0) - t) * cool, kGoochToneRoundings);
    return terms;
}

Interval3 OracleShader::shade(uint32_t id, const Interval3& bary) const {
    Interval3 texel;
    const bool textured = texture(id, bary, texel);
    auto textured_base = [&](const Interval3& base) { return textured ? after_roundings(base * texel, 1) : base; };
    const OracleTriangle& t = geometry_.triangles[id];
    switch (scene_.settings.shading) {
        case ShadingMode::unlit: return textured_base(base_color(id, bary));
        case ShadingMode::flat:
            if (textured) return multiply_add(texel, face_terms_[id].diffuse, face_terms_[id].specular, kCombineRoundings);
            return face_color_[id];
        case ShadingMode::gouraud: {
            Interval3 corners[3], lit[3], highlight[3];
            for (int k = 0; k < 3; ++k) {
                Interval3 corner_bary(Interval(0.0), Interval(0.0), Interval(0.0));
                corner_bary[k] = Interval(1.0);
                const LitTerms& terms = corner_terms(id, k);
                const Interval3 base = base_color(id, corner_bary);
                if (textured) {
                    lit[k] = after_roundings(base * terms.diffuse, 1);
                    highlight[k] = terms.specular;
                } else {
                    corners[k] = multiply_add(base, terms.diffuse, terms.specular, kCombineRoundings);
                }
            }
            if (textured)
                return multiply_add(texel, interpolate(bary, lit), interpolate(bary, highlight), kCombineRoundings);
            return interpolate(bary, corners);
        }
        case ShadingMode::phong:
        case ShadingMode::blinn_phong:
        case ShadingMode::cel:
        case ShadingMode::gooch: {
            Interval3 positions[3], normals[3];
            for (int k = 0; k < 3; ++k) {
                positions[k] = position_box(t.vertex[k]);
                normals[k] = normal_box(t.vertex[k]);
            }
            const Interval3 position = interpolate(bary, positions);
            const Interval3 normal = float_unit(interpolate(bary, normals));
            const ShadingMode mode = scene_.settings.shading;
            const LitTerms terms =
                mode == ShadingMode::gooch ? gooch(position, normal, material_of(id))
                                           : light(position, normal, material_of(id),
                                                   mode == ShadingMode::phong ? Model::phong
                                                   : mode == ShadingMode::cel ? Model::cel
                                                                              : Model::blinn,
                                                   scene_.lights.size());
            return multiply_add(textured_base(base_color(id, bary)), terms.diffuse, terms.specular, kCombineRoundings);
        }
    }
    return Interval3(glm::dvec3(0.0));
}

}  // namespace raster::oracle
