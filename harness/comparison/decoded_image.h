// raster's image as a reader of its files sees it: encoded by raster's own writer (image.h) and decoded by
// stb_image, so that a writer's bugs (rows in the wrong order, wrong channels) reach the comparison.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image/image.h"

namespace raster::harness {

// The pixels of `image` after encode_image(image, format) and stb_image's decoder, with as many channels as the
// file holds (PPM drops alpha). Throws std::runtime_error when stb_image cannot read the bytes.
Image encoded_and_decoded(const Image& image, ImageFormat format);

}  // namespace raster::harness
