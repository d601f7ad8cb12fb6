// Newell's teapot patch data as read from its text file: 4x4 control point indices per patch, and the points.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/vec3.h"

namespace raster::tools {

struct PatchData {
  std::vector<std::array<std::uint32_t, 16>> patches;
  std::vector<int> patch_lines;  // source line of each patch, for error messages
  std::vector<Vec3> points;
};

// Thrown for bad input; tessellate_teapot turns it into "FILE:LINE: message" and exit code 2.
struct InputError {
  int line;  // 0 when no particular line applies
  std::string message;
};

// A whole decimal integer, nothing else; nullopt otherwise.
std::optional<long long> parse_int(std::string_view tok);

// The patch count, the patches, the control point count and the points, checked; throws InputError.
PatchData parse_data(std::istream& in);

// A note on stderr naming the control points that no patch uses (the Newell data has four).
void note_unused_control_points(const PatchData& data);

}  // namespace raster::tools
