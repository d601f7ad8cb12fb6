// Texture lookups: wrap modes, nearest and bilinear texels, the level of detail from the screen-space derivatives
// of the texture coordinates, and the trilinear and anisotropic filters built on them.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/scene/material.h"
#include "raster/texture/texture.h"

namespace raster {

// Texel index `i` of a `size`-texel axis after wrapping: repeat takes i mod size; clamp the nearest of 0 and
// size - 1; mirror repeats with period 2 size, the odd copies reversed (i = -1 reads 0, i = size reads size - 1).
int wrap_texel(long long i, int size, TextureWrap wrap);

// Texture coordinates (u right, v up, as OBJ has them; the image's row 0 is v = 1) to the level's texel space:
// x = u width, y = (1 - v) height, so texel (i, j) spans [i, i + 1) x [j, j + 1) and has its centre at + 0.5.
glm::dvec2 texel_space(const TextureLevel& level, glm::vec2 uv);

// The texel the point falls in.
glm::vec3 sample_nearest(const TextureLevel& level, glm::vec2 uv, TextureWrap wrap);
// The four texels whose centres surround the point, weighted by the point's distance to them.
glm::vec3 sample_bilinear(const TextureLevel& level, glm::vec2 uv, TextureWrap wrap);

// How a footprint maps onto level 0: the derivatives scaled to texels, their lengths rho_x, rho_y
// (Vulkan's scale factors), and what the filter makes of them.
struct Footprint {
    float lod = 0.0f;          // log2 of the footprint's size in level-0 texels (trilinear: max(rho); anisotropic:
                               // max(rho) / taps); -inf..inf, clamped to the chain where used
    int taps = 1;              // anisotropic: min(ceil(max / min), max_anisotropy); 1 otherwise
    glm::vec2 major_axis{0.0f};  // anisotropic: the derivative (in uv) along the longer side
};

// The footprint of a pixel whose texture coordinates change by `duv_dx` per pixel step right and `duv_dy` per step
// down. A footprint that is not finite (an edge-on triangle) takes the coarsest level.
Footprint texture_footprint(const TextureLevel& level0, const SamplerState& sampler, glm::vec2 duv_dx,
                            glm::vec2 duv_dy);

// Trilinear at level of detail `lod`: clamped to [0, last level]; bilinear in levels floor(lod) and the next,
// blended by the fraction; at or below 0 (magnified), bilinear in level 0.
glm::vec3 sample_trilinear(const Texture& texture, glm::vec2 uv, float lod, TextureWrap wrap);

// The texture's value at `uv` through the sampler's filter, for a pixel with the given derivatives (per pixel,
// whatever the sample count). The texture must have its mip chain when the filter uses one.
glm::vec3 sample_texture(const Texture& texture, const SamplerState& sampler, glm::vec2 uv, glm::vec2 duv_dx,
                         glm::vec2 duv_dy);

}  // namespace raster
