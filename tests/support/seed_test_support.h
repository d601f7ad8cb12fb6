// Shared by the seed tests: the corpus folder, a temporary folder, `raster` run in-process, and PPM/PGM reading.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

#include "apps/cli.h"

namespace raster::seed_test {

namespace fs = std::filesystem;

inline fs::path corpus(const std::string& relative) { return fs::path(RASTER_SOURCE_DIR) / "corpus" / relative; }

// A fresh folder that can also take a copy of a corpus folder, so outputs written beside the inputs land in it.
class TempDir : public test_support::TempDir {
public:
    void copy_corpus(const std::string& folder) const { copy_files_of(corpus(folder)); }
};

inline std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct CliResult {
    int status = -1;
    std::string out;
    std::string err;
};

// `raster ARGS...` in this process.
inline CliResult run_raster(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {"raster"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::ostringstream out, err;
    CliResult result;
    result.status = cli::run(argv, out, err);
    result.out = out.str();
    result.err = err.str();
    return result;
}

// A binary PPM (P6) or PGM (P5) with maxval 255, as raster writes them; rows top first.
struct Pixels {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<uint8_t> bytes;
    const uint8_t* at(int x, int y) const { return &bytes[(size_t(y) * width + x) * channels]; }
};

inline Pixels read_pnm(const fs::path& path) {
    std::istringstream in(read_text(path));
    std::string magic;
    int maxval = 0;
    Pixels pixels;
    in >> magic >> pixels.width >> pixels.height >> maxval;
    in.get();  // the single whitespace byte before the raster
    if ((magic != "P6" && magic != "P5") || maxval != 255 || pixels.width <= 0 || pixels.height <= 0)
        throw std::runtime_error("not a binary PPM/PGM with maxval 255: " + path.string());
    pixels.channels = magic == "P6" ? 3 : 1;
    pixels.bytes.resize(size_t(pixels.width) * pixels.height * pixels.channels);
    in.read(reinterpret_cast<char*>(pixels.bytes.data()), std::streamsize(pixels.bytes.size()));
    if (in.gcount() != std::streamsize(pixels.bytes.size())) throw std::runtime_error("truncated image: " + path.string());
    return pixels;
}

inline testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

}  // namespace raster::seed_test
