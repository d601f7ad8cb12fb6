// Fuzz target: Stanford PLY bytes (ascii and binary little-endian) through raster::parse_ply.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "raster/core/errors.h"
#include "raster/formats/mesh_ply.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        raster::parse_ply(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ply");
    } catch (const raster::InputError&) {
        // Rejecting bad input with an InputError is the expected outcome; any other exception is a finding.
    }
    return 0;
}
