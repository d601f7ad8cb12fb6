// Mip chains for a whole scene: built once per texture, and only for textures a mip-reading filter samples.
#pragma once

#include "raster/scene/scene.h"

namespace raster {

// Gives every textured material whose filter reads mip levels (trilinear, anisotropic; the settings'
// texture_filter when set) a texture with its full chain; a texture shared by several materials is built once and
// stays shared. Textures only sampled by nearest or bilinear keep level 0 alone. Call after the filters are final
// (the loader does, and so must whoever changes one or the override).
void build_needed_mip_chains(Scene& scene);

}  // namespace raster
