// Chunked parallel deflate: each chunk a raw deflate stream with its own window, joined under one zlib header.
#include "raster/image/zlib_stream.h"

#include <algorithm>
#include <stdexcept>

#include <zlib.h>

#include "raster/core/parallel.h"

namespace raster {
namespace {

// One chunk as raw deflate (no header or checksum): a sync flush leaves a non-final block ending on a byte
// boundary, so the next chunk's blocks can follow it; the last chunk ends with the final block.
std::vector<uint8_t> deflate_chunk(const uint8_t* data, size_t size, int level, bool last) {
    z_stream stream{};
    if (deflateInit2(&stream, level, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("zlib: deflateInit2 failed");
    struct End {
        z_stream& stream;
        ~End() { deflateEnd(&stream); }  // however this chunk ends
    } end{stream};
    // deflateBound covers the final block; a sync flush's empty stored block adds 5 bytes more at most, and each
    // call may add a few bytes of block overhead.
    std::vector<uint8_t> out(deflateBound(&stream, static_cast<uLong>(size)) + 16);
    stream.next_in = const_cast<Bytef*>(data);
    stream.avail_in = static_cast<uInt>(size);
    stream.next_out = out.data();
    stream.avail_out = static_cast<uInt>(out.size());
    const int flush = last ? Z_FINISH : Z_SYNC_FLUSH;
    const int status = deflate(&stream, flush);
    // A sync flush that filled the buffer may not have written its marker: only room left proves it complete.
    const bool done = last ? status == Z_STREAM_END : (status == Z_OK && stream.avail_in == 0 && stream.avail_out > 0);
    if (!done) throw std::runtime_error("zlib: deflate did not finish a chunk");
    out.resize(out.size() - stream.avail_out);
    return out;
}

}  // namespace

std::vector<uint8_t> zlib_compress_chunked(const uint8_t* data, size_t size, int level, int threads) {
    const size_t chunks = std::max<size_t>(1, (size + kZlibChunkBytes - 1) / kZlibChunkBytes);
    std::vector<std::vector<uint8_t>> deflated(chunks);
    std::vector<uLong> checksum(chunks);
    auto length_of = [&](size_t k) { return std::min(size - std::min(size, k * kZlibChunkBytes), kZlibChunkBytes); };
    parallel_for(chunks, chunks > 1 ? threads : 1, [&](size_t k) {
        const uint8_t* begin = data + k * kZlibChunkBytes;
        deflated[k] = deflate_chunk(begin, length_of(k), level, k + 1 == chunks);
        checksum[k] = adler32(adler32(0L, Z_NULL, 0), begin, static_cast<uInt>(length_of(k)));
    });
    size_t total = 2 + 4;  // header and checksum
    for (const std::vector<uint8_t>& chunk : deflated) total += chunk.size();
    std::vector<uint8_t> out;
    out.reserve(total);
    // Header: deflate with a 32 KiB window (CMF 0x78), FLEVEL 0 (the level is only a hint), FCHECK making
    // CMF * 256 + FLG a multiple of 31.
    out.push_back(0x78);
    out.push_back(0x01);
    uLong adler = adler32(0L, Z_NULL, 0);
    for (size_t k = 0; k < chunks; ++k) {
        out.insert(out.end(), deflated[k].begin(), deflated[k].end());
        adler = adler32_combine(adler, checksum[k], static_cast<z_off_t>(length_of(k)));
    }
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(adler >> shift));
    return out;
}

}  // namespace raster
