// Image encoding (stb_image_write for PNG, by hand for PPM) and the atomic temp-file + rename writer.
#include "raster/image/image.h"

#include "raster/core/file_io.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

std::vector<uint8_t> encode_image(const Image& image, ImageFormat format) {
    std::vector<uint8_t> bytes;
    if (format == ImageFormat::png) {
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

void write_image(const std::filesystem::path& path, const Image& image) {
    write_file_atomically(path, encode_image(image, image_format_for(path)));
}

}  // namespace raster
