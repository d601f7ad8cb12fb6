// Lighting kernels: Blinn-Phong and Phong for a batch of surface points at once, SIMD through Google Highway with
// runtime dispatch. Every target performs the same IEEE operations in the same order, so every target (and the
// scalar fallback) gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"
#include "raster/shading/viewer.h"

namespace raster {

enum class SpecularModel { blinn, phong };

// Points a batch holds. Arrays carry kLanePadding floats more, so a kernel may run its last vector past the end.
inline constexpr size_t kLightingBatch = 64;
inline constexpr size_t kLanePadding = 16;  // the widest vector Highway dispatches to (AVX-512: 16 floats)

// Up to kLightingBatch surface points as structure of arrays, and their lit terms (colour = base * diffuse +
// specular; diffuse includes the ambient term). Rows are x, y, z.
struct LightingBatch {
    static constexpr size_t kRow = kLightingBatch + kLanePadding;
    alignas(64) float position[3][kRow] = {};
    alignas(64) float normal[3][kRow] = {};
    alignas(64) float to_eye[3][kRow] = {};
    alignas(64) float diffuse[3][kRow] = {};
    alignas(64) float specular[3][kRow] = {};
};

// For points [0, count): normal becomes unit length (a zero normal stays zero) and to_eye the unit view vector
// (viewer.h): from position to the eye (zero when they coincide), or the parallel viewer's back direction.
void orient_points(LightingBatch& batch, size_t count, const Viewer& viewer);

// For points [first, first + count), all of one material: ambient plus, per light, one-sided Lambert diffuse and
// the specular lobe (Blinn: n.h, h the normalised l + v; Phong: r.v, r = 2 (n.l) n - l) raised to the material's
// exponent, with optional 1/r^2 attenuation, each light's part times its visibility. `visibility` is null (every
// light fully visible) or holds lights.size() rows of LightingBatch::kRow floats, row k for lights[k], indexed like
// the batch. A light behind the surface (n.l <= 0), on the point, or with visibility 0 adds nothing. Normals and
// to_eye must be unit length.
void light_points(LightingBatch& batch, size_t first, size_t count, const Material& material,
                  const std::vector<Light>& lights, const glm::vec3& ambient_light, SpecularModel model,
                  const float* visibility);

}  // namespace raster
