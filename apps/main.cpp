// Entry point of the `raster` program: hands argv to the command-line layer.
#include <iostream>

#include "apps/cli.h"

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    return raster::cli::run(std::vector<std::string>(argv, argv + argc), std::cout, std::cerr);
}
