// Entry point of the viewer program, raster-view: `raster view` runs it in its own place (cmd_view_forward.cpp), and
// it takes the same command line, with `view` serving pages.
#include <iostream>

#include "apps/cli.h"
#include "apps/command.h"
#include "raster/core/process_heap.h"

int main(int argc, char** argv) {
    raster::prepare_process_heap();  // before any thread: a first frame that starts warm
    std::ios::sync_with_stdio(false);
    return raster::cli::run(std::vector<std::string>(argv, argv + argc), std::cout, std::cerr,
                            {raster::cli::add_view_command});
}
