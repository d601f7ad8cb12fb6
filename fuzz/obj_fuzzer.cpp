// Fuzz target: Wavefront OBJ text through raster::parse_obj (the one-pass reader, triangulation, limits).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        raster::parse_obj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
    } catch (const raster::InputError&) {
        // Rejecting bad input with an InputError is the expected outcome; any other exception is a finding.
    }
    return 0;
}
