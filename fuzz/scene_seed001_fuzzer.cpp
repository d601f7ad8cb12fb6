// Fuzz target: the seed 001 course's balboa JSON scenes, through raster::parse_scene as `balboa.json`.
#include "fuzz/scene_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return raster::fuzz::fuzz_scene_text(data, size, "balboa.json");
}
