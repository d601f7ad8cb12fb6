// Internal to raster_formats (the OBJ reader): how an OBJ file's numbers and indices are read, by the rules of
// tinyobjloader, the library raster read OBJ files with before, so that every file loads as it did.
#pragma once

#include <optional>
#include <string_view>

namespace raster::obj {

// An ASCII decimal digit, '0' to '9' (std::isdigit without its locale and its int argument).
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The value of the longest prefix of `word` that is a number, computed digit by digit as tinyobjloader computed it:
// [sign] (digits [. digits] | . digits) [(e | E) [sign] digits]. nullopt when no prefix is a number (and for an
// exponent of more than nine digits). This is not strtod: for long numbers with an exponent the two can differ in
// the last bit of a float, and a hex or "inf" word reads as 0 or nothing here.
std::optional<double> number_value(std::string_view word);

// atoi(text) as the C library computes it, (int) strtol(text, 10): leading white space, a sign and digits, the long
// range saturated and then cut to int. Every index tinyobjloader read, it read so, and refused one that reads as 0.
int atoi_value(std::string_view text);

// Whether tinyobjloader read the face corner (v, v/vt, v//vn or v/vt/vn) that starts at `at` in `text` without an
// index that reads as 0; `at` moves past what it read (not past a '/' that would start a fourth part).
bool reads_corner(std::string_view text, size_t& at);

// Whether tinyobjloader read the corners of an `l` or `p` statement (drawn by no stage) without refusing it; `rest` is
// the text after the keyword and its blank, and `has_corner` tells whether it holds at least one corner.
bool reads_corner_list(std::string_view rest, bool& has_corner);

// Whether tinyobjloader read a `vw` statement (skin weights, used by no stage) without refusing it, which it did for
// a joint id that is negative or not a number; `rest` is the text after the keyword and its blank.
bool reads_skin_weights(std::string_view rest);

}  // namespace raster::obj
