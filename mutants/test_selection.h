// Which ctest tests reach each catalogue site in the correct schemata build, and which of them a planted bug runs.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace raster::mutants {

struct CtestTest {
    int number = 0;            // ctest's test number (-I selects by it)
    std::string name;
    std::string command;       // its arguments joined by the unit separator, as the traces record them
    double seconds = 0.0;      // its average time in the correct run (CTestCostData.txt), 0 when unknown
};

struct Coverage {
    std::vector<CtestTest> tests;                       // in ctest's order
    std::map<std::string, std::set<int>> tests_of_site;  // site name -> indices into tests
    int traces = 0;                                     // trace files read
    int unattributed = 0;                               // traces whose process no test's command started
};

// Reads `ctest --show-only=json-v1`, CTestCostData.txt and the DIR/*.trace files the correct run wrote.
Coverage read_coverage(const std::filesystem::path& ctest_json, const std::filesystem::path& costs,
                       const std::filesystem::path& traces);

// The tests a planted bug runs, in rounds: the entry's own comparison case first when it reaches the site, then
// the other tests that reach it, quickest first, each round closed when its expected time would pass
// `budget_seconds` (one round of every test when the budget is negative). A round holds at least one test, and the
// rounds hold every test that reaches the site: a bug that no round's tests catch was run against all of them.
// Indices into coverage.tests.
std::vector<std::vector<int>> select_test_rounds(const Coverage& coverage, const std::string& site,
                                                 const std::string& first_test, double budget_seconds);

}  // namespace raster::mutants
