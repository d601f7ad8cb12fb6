// Runs the raster command line in-process for the CLI tests: its exit code and what it printed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "apps/cli.h"

namespace raster::test_support {

struct CliRun {
    int code;
    std::string out, err;
};

// `args` without the program name.
inline CliRun run_raster(std::vector<std::string> args) {
    args.insert(args.begin(), "raster");
    std::ostringstream out, err;
    const int code = cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

}  // namespace raster::test_support
