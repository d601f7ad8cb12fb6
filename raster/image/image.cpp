// Image encoding (stb_image_write for PNG, with zlib's deflate; by hand for PPM) and the atomic temp-file + rename writer.
#include "raster/image/image.h"

#include "raster/core/file_io.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "raster/image/zlib_stream.h"

namespace {

// The threads the PNG being encoded on this thread may deflate on: stb's compression hook takes no context.
thread_local int png_deflate_threads = 0;

// stb_image_write's own deflate takes ~90 ms for an 800x800 frame, longer than the frame; zlib at level 1 does it
// in ~14 ms on one thread, and its files are no larger than stb's at its default level; chunks on several threads
// (zlib_stream.h) divide that. stb frees the result with free().
unsigned char* zlib_compress(unsigned char* data, int length, int* out_length, int /*stb's quality*/) {
    try {
        const std::vector<uint8_t> stream =
            raster::zlib_compress_chunked(data, static_cast<size_t>(length), 1, png_deflate_threads);
        auto* out = static_cast<unsigned char*>(std::malloc(stream.size()));
        if (!out) return nullptr;
        std::copy(stream.begin(), stream.end(), out);
        *out_length = static_cast<int>(stream.size());
        return out;
    } catch (const std::exception&) {
        return nullptr;  // stb reports the failure; encode_image throws
    }
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace raster {

ImageFormat image_format_for(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".ppm" ? ImageFormat::ppm : ImageFormat::png;
}

namespace {

void append_to_vector(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<uint8_t>*>(context);
    const auto* begin = static_cast<const uint8_t*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

}  // namespace

std::vector<uint8_t> encode_image(const Image& image, ImageFormat format, int threads) {
    std::vector<uint8_t> bytes;
    if (format == ImageFormat::png) {
        // Every row with PNG's Sub filter (each byte minus the one a pixel to its left): stb otherwise tries all
        // five filters on every row, which costs more than the deflate. On the teapot Sub makes the file 21%
        // smaller than no filter (120 KB against 151 KB) at the same deflate time: a flat background becomes
        // zeros. Set once, so that threads encoding at the same time do not race on stb's global.
        static const bool sub_filtered = (stbi_write_force_png_filter = 1, true);
        (void)sub_filtered;
        png_deflate_threads = threads;
        if (!stbi_write_png_to_func(append_to_vector, &bytes, image.width, image.height, image.channels,
                                    image.pixels.data(), image.width * image.channels))
            throw std::runtime_error("PNG encoding failed");
        return bytes;
    }
    const bool grey = image.channels == 1;
    const std::string header = std::string(grey ? "P5\n" : "P6\n") + std::to_string(image.width) + " " +
                               std::to_string(image.height) + "\n255\n";
    bytes.assign(header.begin(), header.end());
    const int out_channels = grey ? 1 : 3;
    bytes.reserve(bytes.size() + static_cast<size_t>(image.width) * image.height * out_channels);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.at(x, y);
            if (grey) bytes.push_back(p[0]);
            else if (image.channels >= 3) bytes.insert(bytes.end(), p, p + 3);
            else bytes.insert(bytes.end(), {p[0], p[0], p[0]});
        }
    return bytes;
}

void write_image(const std::filesystem::path& path, const Image& image, int threads) {
    write_file_atomically(path, encode_image(image, image_format_for(path), threads));
}

}  // namespace raster
