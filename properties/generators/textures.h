// The texture generators for the texture properties: images of any size (powers of two or not, 1-texel rows and
// columns), with random 8-bit texels, and the sampler states that read them.
#pragma once

#include <ostream>
#include <string>

#include <rapidcheck.h>

#include "raster/scene/material.h"
#include "raster/texture/texture.h"

namespace raster::properties {

struct TextureImageCase {
    std::string kind;
    TextureLevel level;  // texels k / 255
};
std::ostream& operator<<(std::ostream& os, const TextureImageCase& c);
rc::Gen<TextureImageCase> texture_images();

rc::Gen<TextureWrap> texture_wraps();
rc::Gen<TextureFilter> texture_filters();

}  // namespace raster::properties
