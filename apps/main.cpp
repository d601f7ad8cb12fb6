// Entry point of the `raster` program: hands argv to the command-line layer, with `view` (which runs the viewer
// program, raster-view) when it is built.
#include <iostream>

#include "apps/cli.h"
#include "apps/command.h"
#include "raster/core/process_heap.h"

int main(int argc, char** argv) {
    raster::prepare_process_heap();  // before any thread: a first frame that starts warm
    std::ios::sync_with_stdio(false);
    const std::vector<std::string> arguments(argv, argv + argc);
    std::vector<raster::cli::CommandRegistrar> extra_commands;
#ifdef RASTER_WITH_VIEWER
    extra_commands.push_back(
        [&arguments](CLI::App& app) { return raster::cli::add_view_forwarding_command(app, arguments); });
#endif
    return raster::cli::run(arguments, std::cout, std::cerr, extra_commands);
}
