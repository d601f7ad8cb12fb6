// seed 001's own command lines, as balboa (UCSD CSE 167 homework 2) takes them: -hw 2_1 with a triangle's vertices
// and colour, or -hw 2_2|2_3|2_4 with a JSON scene; each flag one dash and its values.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "raster/scene/scene.h"

namespace raster {

// The usage text `raster balboa --help` prints.
extern const char* const kBalboaUsage;

// What one command line asks for: its help, or the scene its part draws and the image to write it to.
struct BalboaRun {
    bool help = false;
    Scene scene;
    std::filesystem::path output;
};

// Parses and checks balboa's arguments (those after `raster balboa`) and builds the scene. Throws InputError naming
// the flag and the problem (or the scene file, line and column).
BalboaRun balboa_run(const std::vector<std::string>& args);

}  // namespace raster
