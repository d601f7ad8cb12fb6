// The chunked zlib stream: zlib's own inflate (which checks the Adler-32) gives back the input, at every size
// around the chunk boundaries and for incompressible and repetitive data, and the bytes are the same on 1 and 2
// threads.
#include <random>

#include <gtest/gtest.h>
#include <zlib.h>

#include "raster/image/zlib_stream.h"

namespace raster {
namespace {

std::vector<uint8_t> inflate_all(const std::vector<uint8_t>& stream, size_t expected_size) {
    std::vector<uint8_t> out(expected_size + 1);  // one spare byte: a stream longer than expected fails the size check
    uLongf length = static_cast<uLongf>(out.size());
    const int status = uncompress(out.data(), &length, stream.data(), static_cast<uLong>(stream.size()));
    EXPECT_EQ(status, Z_OK) << "zlib's inflate refused the stream (" << stream.size() << " bytes)";
    out.resize(status == Z_OK ? length : 0);
    return out;
}

std::vector<uint8_t> sample_data(size_t size, bool repetitive) {
    std::mt19937 random(static_cast<uint32_t>(size));
    std::vector<uint8_t> data(size);
    for (size_t i = 0; i < size; ++i)
        data[i] = repetitive ? static_cast<uint8_t>((i / 97) % 7) : static_cast<uint8_t>(random());
    return data;
}

TEST(ZlibStream, zlibsInflateGivesBackEveryInputAroundTheChunkBoundaries) {
    const size_t chunk = kZlibChunkBytes;
    for (size_t size : {size_t{0}, size_t{1}, chunk - 1, chunk, chunk + 1, 2 * chunk, 3 * chunk + 7})
        for (bool repetitive : {false, true}) {
            const std::vector<uint8_t> data = sample_data(size, repetitive);
            const std::vector<uint8_t> stream = zlib_compress_chunked(data.data(), data.size(), 1, 2);
            EXPECT_EQ(inflate_all(stream, size), data) << size << " bytes, repetitive " << repetitive;
        }
}

TEST(ZlibStream, theBytesAreTheSameOnOneAndTwoThreads) {
    const std::vector<uint8_t> data = sample_data(3 * kZlibChunkBytes + 123, true);
    EXPECT_EQ(zlib_compress_chunked(data.data(), data.size(), 1, 1), zlib_compress_chunked(data.data(), data.size(), 1, 2));
}

TEST(ZlibStream, repetitiveDataStillCompresses) {
    const std::vector<uint8_t> data = sample_data(4 * kZlibChunkBytes, true);
    EXPECT_LT(zlib_compress_chunked(data.data(), data.size(), 1, 2).size(), data.size() / 20);
}

}  // namespace
}  // namespace raster
