// The images the harness hands around: raster's as a reader of its files sees it (encoded by raster's own writer,
// image.h, and decoded by stb_image, so that a writer's bugs reach the comparison), and the oracle's as an Image.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/reference/oracle_image.h"
#include "raster/image/image.h"

namespace raster::harness {

// The pixels of `image` after encode_image(image, format) and stb_image's decoder, with as many channels as the
// file holds (PPM drops alpha). Throws std::runtime_error when stb_image cannot read the bytes.
Image encoded_and_decoded(const Image& image, ImageFormat format);

// The oracle's image as an Image, to write or to measure against raster's.
Image image_of(const oracle::OracleImage& oracle);

}  // namespace raster::harness
