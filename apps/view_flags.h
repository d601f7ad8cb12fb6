// `raster view`'s flags and help, shared by the viewer program that serves (cmd_view.cpp) and by `raster`, which
// checks them and then hands the command line to that program (cmd_view_forward.cpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "apps/settings_flags.h"

namespace raster::cli {

struct ViewFlags {
    std::string scene;
    int port = 8080;
    SettingsFlags settings;
};

// Adds the `view` subcommand and its flags to `app`.
void register_view_flags(CLI::App& app, ViewFlags& flags);

// The viewer program's file name, beside `raster` in the build folder (apps/CMakeLists.txt).
inline constexpr const char* kViewerProgram = "raster-view";

}  // namespace raster::cli
