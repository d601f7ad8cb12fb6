// Known divergences between raster and the oracle: a checked-in file, one entry per line with its reason
// (like llvmpipe's ci/*-fails.txt), that the corpus comparison test reads instead of ever skipping a scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raster::oracle {

// One line `SCENE SAMPLES MAX_GENUINE  # reason`: scene SCENE (the file's stem) compared at SAMPLES samples per
// pixel may have up to MAX_GENUINE genuine disagreements, for the stated reason.
struct KnownDivergence {
    std::string scene;
    int samples = 0;
    uint64_t max_genuine = 0;
    std::string reason;
    int line = 0;
};

// Parses the file's text. Blank lines and lines starting with '#' are comments. Throws InputError naming the file
// and line for a malformed entry, an entry without a `# reason`, or a repeated (scene, samples).
std::vector<KnownDivergence> parse_expectations(const std::string& text, const std::string& file_name);

// Reads and parses a file (InputError when it cannot be read).
std::vector<KnownDivergence> load_expectations(const std::filesystem::path& path);

// The entry for (scene, samples), or nullptr.
const KnownDivergence* find_expectation(const std::vector<KnownDivergence>& list, const std::string& scene, int samples);

}  // namespace raster::oracle
