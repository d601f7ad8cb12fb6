// The `raster` command line: subcommands, flags, messages and exit codes (testable without a process).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace raster::cli {

// Exit codes scripts can rely on.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;  // a comparison or check ran and failed
inline constexpr int kExitBadInput = 2;     // bad usage, unreadable or invalid input; nothing was written
inline constexpr int kExitIoError = 3;      // the input was fine but an output could not be written

// Runs `raster` with argv-style arguments (args[0] is the program name), writing to out and err.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace raster::cli
