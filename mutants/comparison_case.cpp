// Names the ctest comparison cases the catalogue's entries are judged by.
#include "mutants/comparison_case.h"

#include <fstream>
#include <regex>

#include "mutants/catalogue.h"

namespace raster::mutants {

bool is_corpus_case(const ComparisonCase& c) {
    static const std::regex corpus(R"(^corpus/scenes/[^/]+\.yaml$|^corpus/seeds/003/(textured|shadows)\.json$)");
    return c.flags.empty() && std::regex_match(c.scene, corpus);
}

std::string comparison_test_name(const ComparisonCase& c) {
    const std::string stem = std::filesystem::path(c.scene).stem().string();
    if (is_corpus_case(c)) return "Corpus/CorpusAgainstOracle.hasNoGenuineDisagreement/" + stem + "_1spp";
    std::string name = "Compare/";
    name.append(c.scene, c.scene.rfind("corpus/", 0) == 0 ? 7 : 0);
    if (!c.flags.empty()) {
        name += '/';
        name += std::regex_replace(c.flags, std::regex(" +"), "_");
    }
    return name;
}

std::vector<ComparisonCase> read_comparison_cases(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw CatalogueError(path.string() + ": cannot read the comparison cases");
    std::vector<ComparisonCase> cases;
    const std::regex line_form(R"(^\s*([^|#\s]+)\s*(?:\|\s*(.*?))?\s*$)");
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        std::smatch match;
        if (!std::regex_match(line, match, line_form))
            throw CatalogueError(path.string() + ":" + std::to_string(number) + ": expected 'scene | flags'");
        cases.push_back({match[1], match[2]});
    }
    return cases;
}

}  // namespace raster::mutants
