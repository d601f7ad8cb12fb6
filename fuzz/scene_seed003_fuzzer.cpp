// Fuzz target: the seed 003 course's JSON scene format, through raster::parse_scene as `scene.json`.
#include "fuzz/scene_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return raster::fuzz::fuzz_scene_text(data, size, "scene.json");
}
