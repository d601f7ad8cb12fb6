// The ctest comparison case that judges an entry's scene and flags: a corpus case, or a line of tests/compare/cases.txt.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raster::mutants {

struct ComparisonCase {
    std::string scene;  // relative to the project root
    std::string flags;  // render's settings flags, split at spaces (may be empty)
};

// The ctest name of the case: the in-process corpus comparison at 1 sample for a corpus scene (or seed 003's
// textured and shadowed scenes) without flags, else the `raster compare` case tests/compare/CMakeLists.txt adds:
// "Compare/" + the scene under corpus/ + ("/" + the flags with blanks as _).
std::string comparison_test_name(const ComparisonCase& c);

// True when the corpus comparison (tests/harness/compare_corpus_test.cpp) already runs it.
bool is_corpus_case(const ComparisonCase& c);

// tests/compare/cases.txt: "scene | flags" lines, # comments.
std::vector<ComparisonCase> read_comparison_cases(const std::filesystem::path& path);

}  // namespace raster::mutants
