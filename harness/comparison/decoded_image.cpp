// Reading raster's files back with stb_image; the oracle's image as an Image.
#include "harness/comparison/decoded_image.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_PNM
#include <stb/stb_image.h>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"

namespace raster::harness {
namespace {

// The largest file read back: a 16384 x 16384 RGBA image, uncompressed, with room for the format's overhead.
constexpr uint64_t kMaxDecodedFileBytes = uint64_t{16384} * 16384 * 4 + (uint64_t{1} << 20);

}  // namespace

Image decoded_file(const std::filesystem::path& path) {
    std::vector<uint8_t> bytes;
    try {
        const std::string text = read_file_bytes(path, kMaxDecodedFileBytes);
        bytes.assign(text.begin(), text.end());
    } catch (const std::exception&) {
        return Image{};
    }
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 0);
    if (!pixels) return Image{};
    Image decoded(width, height, channels);
    std::copy(pixels, pixels + decoded.pixels.size(), decoded.pixels.begin());
    stbi_image_free(pixels);
    return decoded;
}

Image read_image_file(const std::filesystem::path& path, int channels) {
    const std::string text = read_file_bytes(path, kMaxDecodedFileBytes);  // throws, naming the file
    int width = 0, height = 0, file_channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(text.data()), static_cast<int>(text.size()),
                                            &width, &height, &file_channels, channels);
    if (!pixels)
        throw InputError(path.string() + ": not a PNG or PPM image stb_image decodes (" + stbi_failure_reason() + ")");
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
