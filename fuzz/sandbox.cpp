// The fuzz targets' private temporary folder, its per-input restore, and the filter that keeps paths inside it.
#include "fuzz/sandbox.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raster::fuzz {
namespace {

[[noreturn]] void setup_failed(const std::string& what) {
    // Setup failing is the environment's fault, not the input's: stop loudly rather than fuzz nothing.
    std::perror(what.c_str());
    std::abort();
}

// Where sandboxes go: /dev/shm when it is a writable folder, else the system temp directory. Commands write their
// outputs atomically with fsync (raster/core/file_io.cpp); on a disk that costs milliseconds per file, in memory
// nothing, and the cli target writes several files for most inputs it runs.
std::filesystem::path sandbox_parent() {
    const std::filesystem::path memory = "/dev/shm";
    std::error_code error;
    if (std::filesystem::is_directory(memory, error) && ::access(memory.c_str(), W_OK | X_OK) == 0) return memory;
    return std::filesystem::temp_directory_path();
}

}  // namespace

Sandbox::Sandbox(const std::string& label, Fixtures fixtures) {
    std::string pattern = (sandbox_parent() / ("raster-fuzz-" + label + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) setup_failed("raster fuzz: mkdtemp " + pattern);
    path_ = pattern;
    for (auto& [name, content] : fixtures) {
        fixtures_.push_back({std::move(name), std::move(content)});
        write_fixture(fixtures_.back());
    }
}

Sandbox::~Sandbox() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

void Sandbox::write_fixture(Written& fixture) {
    const std::filesystem::path file = path_ / fixture.name;
    std::error_code ignored;
    std::filesystem::remove_all(file, ignored);  // it may have been replaced by a folder or another file
    std::ofstream(file, std::ios::binary) << fixture.content;
    struct stat status {};
    if (::stat(file.c_str(), &status) != 0) setup_failed("raster fuzz: writing " + file.string());
    fixture.inode = status.st_ino;
    fixture.modified_ns = static_cast<long long>(status.st_mtim.tv_sec) * 1000000000LL + status.st_mtim.tv_nsec;
}

void Sandbox::restore() {
    std::error_code ignored;
    for (const auto& entry : std::filesystem::directory_iterator(path_, ignored)) {
        const std::string name = entry.path().filename().string();
        const bool fixture = std::any_of(fixtures_.begin(), fixtures_.end(), [&](const Written& f) { return f.name == name; });
        if (!fixture) std::filesystem::remove_all(entry.path(), ignored);
    }
    for (Written& fixture : fixtures_) {
        struct stat status {};
        const bool same = ::stat((path_ / fixture.name).c_str(), &status) == 0 && S_ISREG(status.st_mode) &&
                          status.st_ino == fixture.inode &&
                          static_cast<long long>(status.st_mtim.tv_sec) * 1000000000LL + status.st_mtim.tv_nsec ==
                              fixture.modified_ns &&
                          static_cast<size_t>(status.st_size) == fixture.content.size();
        if (!same) write_fixture(fixture);
    }
}

bool could_spell_a_slash(std::string_view text) {
    if (text.find('/') != std::string_view::npos) return true;
    for (size_t at = text.find('\\'); at != std::string_view::npos; at = text.find('\\', at + 1)) {
        std::string escape(text.substr(at + 1, 9));
        std::transform(escape.begin(), escape.end(), escape.begin(), [](unsigned char c) { return std::tolower(c); });
        if (escape.starts_with("/") || escape.starts_with("x2f") || escape.starts_with("u002f") ||
            escape.starts_with("u0000002f"))
            return true;
    }
    return false;
}

WorkingDirectory::WorkingDirectory(const std::filesystem::path& folder) : previous_(::open(".", O_RDONLY | O_DIRECTORY)) {
    if (previous_ < 0 || ::chdir(folder.c_str()) != 0) setup_failed("raster fuzz: chdir " + folder.string());
}

WorkingDirectory::~WorkingDirectory() {
    if (::fchdir(previous_) != 0) setup_failed("raster fuzz: returning to the previous working directory");
    ::close(previous_);
}

}  // namespace raster::fuzz
