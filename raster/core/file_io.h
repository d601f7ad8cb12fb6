// Whole-file input and output: bounded reads and atomic (temp file + rename) writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raster {

// The file's extension in lower case, with its dot (".obj"); what tells a file's format when its name does.
std::string lowercase_extension(const std::filesystem::path& path);

// Reads a whole file of at most `max_bytes`. Throws InputError naming the file when it cannot.
std::string read_file_bytes(const std::filesystem::path& path, uint64_t max_bytes);

// Writes bytes to `path` whole: into a temporary file beside it, then renamed over it, so a reader never sees a
// half-written file and a failure leaves no file behind. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, const std::vector<uint8_t>& bytes);

// The same for text.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace raster
