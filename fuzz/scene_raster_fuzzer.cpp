// Fuzz target: the project's own YAML scene format, through raster::parse_scene as `scene.yaml`.
#include "fuzz/scene_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return raster::fuzz::fuzz_scene_text(data, size, "scene.yaml");
}
