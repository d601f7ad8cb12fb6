// Encoding with raster's writer and decoding with stb_image; the oracle's image as an Image.
#include "harness/comparison/decoded_image.h"

#include <algorithm>
#include <stdexcept>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_PNM
#include <stb/stb_image.h>

namespace raster::harness {

Image encoded_and_decoded(const Image& image, ImageFormat format) {
    const std::vector<uint8_t> bytes = encode_image(image, format);
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 0);
    if (!pixels) throw std::runtime_error(std::string("stb_image cannot decode raster's image: ") + stbi_failure_reason());
    Image decoded(width, height, channels);
    std::copy(pixels, pixels + decoded.pixels.size(), decoded.pixels.begin());
    stbi_image_free(pixels);
    return decoded;
}

Image image_of(const oracle::OracleImage& oracle) {
    Image image;
    image.width = oracle.width;
    image.height = oracle.height;
    image.channels = oracle.channels;
    image.pixels = oracle.pixels;
    return image;
}

}  // namespace raster::harness
