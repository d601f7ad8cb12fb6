// Whole-file input and output: bounded reads and atomic (temp file + rename) writes.
#include "raster/core/file_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include "raster/core/errors.h"

namespace raster {

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension;
}

std::string read_file_bytes(const std::filesystem::path& path, uint64_t max_bytes) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw InputError(path.string(), 0, 0, "is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), 0, 0, "cannot open file");
    std::string bytes;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        bytes.append(buffer, static_cast<size_t>(in.gcount()));
        if (bytes.size() > max_bytes)
            throw InputError(path.string(), 0, 0, "file is larger than " + std::to_string(max_bytes >> 20) + " MiB");
    }
    if (in.bad()) throw InputError(path.string(), 0, 0, "read error");
    return bytes;
}

void write_file_atomically(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    const std::filesystem::path temporary =
        path.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const int saved_errno = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
        std::filesystem::remove(temporary);
        throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(saved_errno));
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary);
        throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
    }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
    write_file_atomically(path, std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace raster
