// The oracle's texture filters over boxes: every value a correct raster may read from a texture when its texture
// coordinates and derivatives lie anywhere in the given boxes, its float roundings included (texture_precision.h).
#pragma once

#include "oracle/reference/interval.h"
#include "oracle/reference/oracle_texture.h"
#include "raster/scene/material.h"

namespace raster::oracle {

// Texture coordinates (u right, v up) and their per-pixel derivatives, each a box.
struct UvBox {
    Interval u, v;
};
struct TextureFootprintBox {
    UvBox uv;
    UvBox d_dx, d_dy;  // d(u, v) / dx and / dy, per pixel
};

// The oracle's wrap of texel index i on an n-texel axis (docs/textures.md).
long long oracle_wrap(long long i, int n, TextureWrap wrap);

// The filters of docs/textures.md over the boxes.
Interval3 nearest_over(const OracleTextureLevel& level, int level_index, const UvBox& uv, TextureWrap wrap);
Interval3 bilinear_over(const OracleTextureLevel& level, int level_index, const UvBox& uv, TextureWrap wrap);
Interval3 trilinear_over(const OracleTexture& texture, const UvBox& uv, Interval lod, TextureWrap wrap);
Interval3 filtered_over(const OracleTexture& texture, const SamplerState& sampler, const TextureFootprintBox& box);

}  // namespace raster::oracle
