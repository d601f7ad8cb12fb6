// Test selection: parameterised names read without their comment, traces attributed to the test whose command started the process, and the rounds the budget makes.
#include "mutants/test_selection.h"

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace raster::mutants {
namespace {

using test_support::TempDir;

struct Fixture {
    TempDir dir;
    Coverage coverage;
    Fixture() {
        dir.write("tests.json", R"({"tests": [
            {"name": "Fast.one", "command": ["/b/unit", "--gtest_filter=Fast.one"]},
            {"name": "Slow.compare", "command": ["/b/raster", "compare", "s.yaml"]},
            {"name": "Mid/Two.case/p  # GetParam() = p", "command": ["/b/unit", "--gtest_filter=Mid/Two.case/p"]},
            {"name": "Never.runs", "command": ["/b/unit", "--gtest_filter=Never.runs"]}]})");
        dir.write("costs.txt", "Fast.one 1 0.1\nSlow.compare 1 3.0\nMid/Two.case/p  # GetParam() = p 1 1.5\nNever.runs 1 0.01\n---\n");
        // A test's own process, a child of a test (the CLI under bash), and a process no test started.
        dir.write("traces/1.trace", "command /b/unit\x1f--gtest_filter=Fast.one\ncommand /usr/bin/ctest\nsite s\n");
        dir.write("traces/2.trace", "command /b/raster\x1f" "render\ncommand /b/raster\x1f" "compare\x1fs.yaml\nsite s\nsite t\n");
        dir.write("traces/3.trace", "command /b/unit\x1f--gtest_filter=Mid/Two.case/p\nsite s\n");
        dir.write("traces/4.trace", "command /usr/bin/stray\nsite s\n");
        coverage = read_coverage(dir / "tests.json", dir / "costs.txt", dir / "traces");
    }
    // Each round's test names, rounds separated by "|".
    std::vector<std::string> names(const std::vector<std::vector<int>>& rounds) const {
        std::vector<std::string> out;
        for (const std::vector<int>& round : rounds) {
            if (!out.empty()) out.push_back("|");
            for (int test : round) out.push_back(coverage.tests[test].name);
        }
        return out;
    }
};

TEST(TestSelection, attributesEachTraceToTheTestThatStartedItsProcess) {
    Fixture f;
    EXPECT_EQ(f.coverage.traces, 4);
    EXPECT_EQ(f.coverage.unattributed, 1);
    EXPECT_EQ(f.coverage.tests_of_site.at("s"), (std::set<int>{0, 1, 2}));
    EXPECT_EQ(f.coverage.tests_of_site.at("t"), (std::set<int>{1}));
    EXPECT_EQ(f.coverage.tests[1].number, 2);
    EXPECT_DOUBLE_EQ(f.coverage.tests[2].seconds, 1.5);
}

TEST(TestSelection, runsTheComparisonFirstThenTheQuickestInRoundsWithinTheBudget) {
    Fixture f;
    // The first round within the budget; the tests it leaves out come in later rounds, so that a bug the first
    // round misses still meets every test that reaches it.
    EXPECT_EQ(f.names(select_test_rounds(f.coverage, "s", "Slow.compare", 3.5)),
              (std::vector<std::string>{"Slow.compare", "Fast.one", "|", "Mid/Two.case/p"}));
    EXPECT_EQ(f.names(select_test_rounds(f.coverage, "s", "Slow.compare", -1)),
              (std::vector<std::string>{"Slow.compare", "Fast.one", "Mid/Two.case/p"}));
    // A comparison that does not reach the site is not run: it cannot fail because of it.
    EXPECT_EQ(f.names(select_test_rounds(f.coverage, "t", "Mid/Two.case/p", 10)),
              (std::vector<std::string>{"Slow.compare"}));
    // At least one test a round whatever the budget, quickest first.
    EXPECT_EQ(f.names(select_test_rounds(f.coverage, "s", "none", 0)),
              (std::vector<std::string>{"Fast.one", "|", "Mid/Two.case/p", "|", "Slow.compare"}));
    EXPECT_TRUE(select_test_rounds(f.coverage, "unreached", "Slow.compare", 10).empty());
}

}  // namespace
}  // namespace raster::mutants
