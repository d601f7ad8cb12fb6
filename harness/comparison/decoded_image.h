// The images the harness hands around: a file raster wrote, as a reader sees it (decoded by stb_image, so that a
// writer's bugs reach the comparison), and the oracle's image as an Image.
#pragma once

#include <filesystem>

#include "oracle/reference/oracle_image.h"
#include "raster/image/image.h"

namespace raster::harness {

// The pixels of the PNG or PPM file at `path`, with as many channels as the file holds (PPM drops alpha). An empty
// image (0 x 0) when the file cannot be read or decoded: a comparison then finds every pixel wrong.
Image decoded_file(const std::filesystem::path& path);

// The PNG or PPM file at `path` decoded to `channels` channels (1 to 4: stb_image converts grey, grey-alpha, RGB and
// RGBA into each other). Throws InputError naming the file and what is wrong with it.
Image read_image_file(const std::filesystem::path& path, int channels);

// The oracle's image as an Image, to write or to measure against raster's.
Image image_of(const oracle::OracleImage& oracle);

}  // namespace raster::harness
