// A model's warnings: what raster leaves out of a glTF file, each said once on stderr as "file: warning: ...".
#pragma once

#include <set>
#include <string>

namespace raster {

class GltfWarnings {
public:
    explicit GltfWarnings(std::string file) : file_(std::move(file)) {}
    // Prints the warning unless the same text was said before.
    void say(const std::string& message);

private:
    std::string file_;
    std::set<std::string> said_;
};

}  // namespace raster
