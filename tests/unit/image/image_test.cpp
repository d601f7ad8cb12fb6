// Image output: PPM bytes as the format defines them, PNG that decodes back to the same pixels, atomic writes.
#include "raster/image/image.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "raster/core/file_io.h"
#include "raster/image/to_byte.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace raster {
namespace {

Image two_by_one() {
    Image image(2, 1, 3);
    const uint8_t bytes[] = {255, 0, 10, 1, 2, 3};
    std::copy(std::begin(bytes), std::end(bytes), image.pixels.begin());
    return image;
}

TEST(Image, toByteRoundsAndClamps) {
    EXPECT_EQ(to_byte(-0.5f), 0);
    EXPECT_EQ(to_byte(0.5f), 128);  // 127.5 rounds half away from zero
    EXPECT_EQ(to_byte(1.0f / 255.0f), 1);
    EXPECT_EQ(to_byte(7.0f), 255);
    EXPECT_EQ(to_byte(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(Image, ppmIsBinaryP6WithHeader) {
    const std::vector<uint8_t> bytes = encode_image(two_by_one(), ImageFormat::ppm);
    const std::string header = "P6\n2 1\n255\n";
    ASSERT_EQ(bytes.size(), header.size() + 6);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + header.size()), header);
    EXPECT_EQ(bytes[header.size()], 255);
    EXPECT_EQ(bytes.back(), 3);
}

TEST(Image, pngDecodesToTheSamePixels) {
    Image image(3, 2, 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<uint8_t>(i * 11);
    const std::vector<uint8_t> bytes = encode_image(image, ImageFormat::png);
    int w = 0, h = 0, channels = 0;
    uint8_t* decoded = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 0);
    ASSERT_NE(decoded, nullptr);
    EXPECT_EQ(w, 3);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(channels, 4);
    EXPECT_TRUE(std::equal(image.pixels.begin(), image.pixels.end(), decoded));
    stbi_image_free(decoded);
}

TEST(Image, formatFollowsTheExtension) {
    EXPECT_EQ(image_format_for("a/b.PPM"), ImageFormat::ppm);
    EXPECT_EQ(image_format_for("out.png"), ImageFormat::png);
    EXPECT_EQ(image_format_for("out"), ImageFormat::png);
}

TEST(FileIo, atomicWriteReplacesWholeAndLeavesNoTemporary) {
    const auto dir = std::filesystem::temp_directory_path() / ("raster_image_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / "out.ppm";
    write_image(path, two_by_one());
    write_image(path, two_by_one());  // replacing an existing file works too
    EXPECT_EQ(std::filesystem::file_size(path), std::string("P6\n2 1\n255\n").size() + 6);
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1);
    // A missing directory fails with an error naming the path, and creates nothing.
    try {
        write_image(dir / "missing" / "out.png", two_by_one());
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("missing"), std::string::npos);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace raster
