// 8-bit images and their files: PNG (stb_image_write) and binary PPM, always written whole (temp + rename).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raster {

// Row-major, top row first, `channels` bytes per pixel (1 grey, 3 RGB, 4 RGBA).
struct Image {
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<uint8_t> pixels;

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c, 0) {}
    uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * channels]; }
    const uint8_t* at(int x, int y) const { return &pixels[(static_cast<size_t>(y) * width + x) * channels]; }
};

enum class ImageFormat { png, ppm };

// The format a file name asks for: ".ppm" gives PPM, anything else PNG.
ImageFormat image_format_for(const std::filesystem::path& path);

// Encodes the image. PPM is binary P6 (RGB; alpha is dropped) or P5 for grey. PNG's deflate runs on up to
// `threads` threads (0 = all cores; zlib_stream.h); the bytes do not depend on the count.
std::vector<uint8_t> encode_image(const Image& image, ImageFormat format, int threads = 0);

// encode_image + write_file_atomically, in the format the extension asks for.
void write_image(const std::filesystem::path& path, const Image& image, int threads = 0);

}  // namespace raster
