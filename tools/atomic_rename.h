// The last step of the tools' atomic writes: the finished temporary file renamed over its destination.
#pragma once

#include <filesystem>
#include <iostream>
#include <system_error>

namespace raster::tools {

// Renames `temporary` over `path`. On failure it says so on stderr ("PROGRAM: cannot rename TEMPORARY to PATH:
// reason"), removes the temporary and returns false, so a failed write never leaves a half-written file behind.
inline bool rename_over(const std::filesystem::path& temporary, const std::filesystem::path& path,
                        const char* program) {
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::cerr << program << ": cannot rename " << temporary.string() << " to " << path.string() << ": "
                  << error.message() << "\n";
        std::filesystem::remove(temporary, error);
        return false;
    }
    return true;
}

}  // namespace raster::tools
