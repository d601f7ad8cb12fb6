// Shared by the trade-off tests: the corpus scenes shrunk to a test's size, and reading what the sweep wrote.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace raster::tradeoff_test {

namespace fs = std::filesystem;
using test_support::TempDir;

inline const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

inline std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
}

// A corpus scene at a smaller size, written into `dir` (mesh files still read from the corpus).
inline fs::path small_scene(const TempDir& dir, const std::string& corpus_name, int width, int height) {
    std::string text = read_text(kCorpus + corpus_name);
    const std::string meshes = kCorpus + "../meshes/";
    for (size_t at = text.find("../meshes/"); at != std::string::npos; at = text.find("../meshes/", at + meshes.size()))
        text.replace(at, 10, meshes);
    const size_t image = text.find("image: {width: ");
    const size_t end = text.find(',', text.find("height: ", image));
    EXPECT_NE(image, std::string::npos);
    text.replace(image, end - image, "image: {width: " + std::to_string(width) + ", height: " + std::to_string(height));
    return dir.write(corpus_name, text);
}

inline size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

}  // namespace raster::tradeoff_test
