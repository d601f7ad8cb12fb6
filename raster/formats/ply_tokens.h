// Internal to raster_formats (the PLY reader): white space and numbers of PLY text, shared by the header and the
// ascii body, and file text made safe to quote in a message.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace raster::ply {

// Line and column numbers are counted in 64 bits and clamped when handed to InputError (int).
inline int clamp_int(int64_t v) { return static_cast<int>(std::min<int64_t>(v, std::numeric_limits<int>::max())); }

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Makes file text safe for an error message: printable ASCII kept, everything else escaped, long text cut.
std::string printable(std::string_view s);

// printable(s) in single quotes.
std::string quote(std::string_view s);

// Strips one leading '+' (from_chars does not accept it) unless a sign follows it.
std::string_view strip_plus(std::string_view s);

enum class NumberError { None, NotANumber, OutOfRange };

// The whole token as an integer, or why it is not one.
NumberError parse_int64(std::string_view token, int64_t& out);

// The whole token as a floating-point number, or why it is not one; an underflow reads as (signed) zero.
NumberError parse_double(std::string_view token, double& out);

}  // namespace raster::ply
