// Test selection from coverage: every check is seeded, so a test that never runs a site cannot fail because of it.
#include "mutants/test_selection.h"

#include <algorithm>
#include <fstream>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "mutants/catalogue.h"

namespace raster::mutants {

namespace fs = std::filesystem;

Coverage read_coverage(const fs::path& ctest_json, const fs::path& costs, const fs::path& traces) {
    Coverage coverage;
    std::ifstream json_in(ctest_json);
    if (!json_in) throw CatalogueError(ctest_json.string() + ": cannot read ctest's test list");
    const nlohmann::json list = nlohmann::json::parse(json_in, nullptr, false);
    if (list.is_discarded() || !list.contains("tests"))
        throw CatalogueError(ctest_json.string() + ": not the output of ctest --show-only=json-v1");
    std::map<std::string, int> by_command, by_name;
    for (const auto& test : list["tests"]) {
        CtestTest entry;
        entry.number = static_cast<int>(coverage.tests.size()) + 1;
        // A parameterised GoogleTest case is listed as "Suite/Test.name/param  # GetParam() = ...": the name is
        // the part before the comment.
        entry.name = test.value("name", "");
        entry.name = entry.name.substr(0, entry.name.find("  # "));
        if (test.contains("command"))
            for (const auto& argument : test["command"]) {
                if (!entry.command.empty()) entry.command += '\x1f';
                entry.command += argument.get<std::string>();
            }
        by_command.emplace(entry.command, static_cast<int>(coverage.tests.size()));
        by_name.emplace(entry.name, static_cast<int>(coverage.tests.size()));
        coverage.tests.push_back(entry);
    }
    // CTestCostData.txt: "name runs average-seconds" per test, then "---" and the failed tests.
    std::ifstream costs_in(costs);
    for (std::string line; std::getline(costs_in, line) && line != "---";) {
        // The name may hold blanks (a parameterised case's comment): the last two fields are the numbers.
        const size_t cost_at = line.rfind(' ');
        const size_t runs_at = cost_at == std::string::npos ? std::string::npos : line.rfind(' ', cost_at - 1);
        if (runs_at == std::string::npos) continue;
        std::string name = line.substr(0, runs_at);
        name = name.substr(0, name.find("  # "));
        if (auto found = by_name.find(name); found != by_name.end())
            coverage.tests[found->second].seconds = std::strtod(line.c_str() + cost_at + 1, nullptr);
    }
    if (!fs::is_directory(traces)) throw CatalogueError(traces.string() + ": no trace folder");
    for (const auto& file : fs::directory_iterator(traces)) {
        if (file.path().extension() != ".trace") continue;
        ++coverage.traces;
        std::ifstream in(file.path());
        int test = -1;
        std::vector<std::string> sites;
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("command ", 0) == 0 && test < 0) {
                if (auto found = by_command.find(line.substr(8)); found != by_command.end()) test = found->second;
            } else if (line.rfind("site ", 0) == 0) {
                sites.push_back(line.substr(5));
            }
        }
        if (test < 0) {
            ++coverage.unattributed;
            continue;
        }
        for (const std::string& site : sites) coverage.tests_of_site[site].insert(test);
    }
    return coverage;
}

std::vector<std::vector<int>> select_test_rounds(const Coverage& coverage, const std::string& site,
                                                 const std::string& first_test, double budget_seconds) {
    std::vector<int> reaching;
    if (auto found = coverage.tests_of_site.find(site); found != coverage.tests_of_site.end())
        reaching.assign(found->second.begin(), found->second.end());
    std::stable_sort(reaching.begin(), reaching.end(),
                     [&](int a, int b) { return coverage.tests[a].seconds < coverage.tests[b].seconds; });
    const auto first = std::find_if(reaching.begin(), reaching.end(),
                                    [&](int test) { return coverage.tests[test].name == first_test; });
    if (first != reaching.end()) std::rotate(reaching.begin(), first, first + 1);
    std::vector<std::vector<int>> rounds;
    double spent = 0.0;
    for (int test : reaching) {
        if (rounds.empty() || (budget_seconds >= 0 && spent + coverage.tests[test].seconds > budget_seconds)) {
            rounds.emplace_back();
            spent = 0.0;
        }
        rounds.back().push_back(test);
        spent += coverage.tests[test].seconds;
    }
    return rounds;
}

}  // namespace raster::mutants
