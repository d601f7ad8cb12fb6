// Fuzz target: the seed 000 course's YAML `task:` configs, through raster::parse_scene as `config.yaml`.
#include "fuzz/scene_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return raster::fuzz::fuzz_scene_text(data, size, "config.yaml");
}
