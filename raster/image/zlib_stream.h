// A zlib stream (RFC 1950) deflated in independent fixed-size chunks on several threads, as PNG's IDAT holds it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raster {

// The input is cut into chunks of kZlibChunkBytes, each deflated on its own (no shared window), ending byte-aligned
// with a sync flush, the last with the final block; the chunks follow one zlib header and the Adler-32 of the
// whole input. The chunking depends only on the input's size, so the bytes are the same for any thread count.
inline constexpr size_t kZlibChunkBytes = size_t{256} << 10;

// Deflates `size` bytes at `level` (zlib's 0..9) on up to `threads` threads (0 = all cores). Throws
// std::runtime_error when zlib fails.
std::vector<uint8_t> zlib_compress_chunked(const uint8_t* data, size_t size, int level, int threads);

}  // namespace raster
