// Helpers shared by the fuzz targets that touch files: a private temporary folder with fixture files, and the
// input filter that keeps every path a target can reach inside it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raster::fuzz {

// A fresh folder in memory (/dev/shm, else the system temp directory) holding `fixtures` (name, content), removed at
// exit. Targets make one in a function-local static, so the setup runs once per process.
class Sandbox {
public:
    using Fixtures = std::vector<std::pair<std::string, std::string>>;

    Sandbox(const std::string& label, Fixtures fixtures);
    ~Sandbox();
    Sandbox(const Sandbox&) = delete;
    Sandbox& operator=(const Sandbox&) = delete;

    const std::filesystem::path& path() const { return path_; }

    // Puts the folder back as it was made: removes every other entry and rewrites any fixture that was replaced
    // or changed. Cheap when nothing changed (one directory listing and one stat per fixture).
    void restore();

private:
    struct Written {
        std::string name, content;
        unsigned long long inode = 0;
        long long modified_ns = 0;
    };
    void write_fixture(Written& fixture);

    std::filesystem::path path_;
    std::vector<Written> fixtures_;
};

// True when `text` contains a '/' or an escape sequence a YAML or JSON string could turn into one ("\/", "\x2f",
// "\u002f", "\U0000002f"). Scene targets skip such inputs, so every mesh path a scene names is a bare file name
// resolved inside the sandbox: no absolute path, no "..", nothing outside.
bool could_spell_a_slash(std::string_view text);

// Calls chdir(folder) now and chdir back to the previous working directory when destroyed.
class WorkingDirectory {
public:
    explicit WorkingDirectory(const std::filesystem::path& folder);
    ~WorkingDirectory();
    WorkingDirectory(const WorkingDirectory&) = delete;
    WorkingDirectory& operator=(const WorkingDirectory&) = delete;

private:
    int previous_;  // an open descriptor of the previous directory, for fchdir
};

}  // namespace raster::fuzz
