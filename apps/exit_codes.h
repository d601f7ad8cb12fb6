// The exit codes of every `raster` subcommand, which scripts can rely on.
#pragma once

namespace raster::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;  // a comparison or check ran and failed
inline constexpr int kExitCannotServe = 1;  // `raster view`: the port could not be bound
inline constexpr int kExitBadInput = 2;     // bad usage, unreadable or invalid input; nothing was written
inline constexpr int kExitIoError = 3;      // the input was fine but an output could not be written

}  // namespace raster::cli
