// The registry holds every property the sources write, each once, in suites that stay together, and each runs as
// a gtest of the same name, so that ctest and the mutants run check the same properties.
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "properties/property_registry.h"

namespace raster::properties {
namespace {

// RASTER_PROPERTIES_WRITTEN is the number of lines starting with RASTER_PROPERTY( in the property sources, counted
// by properties/CMakeLists.txt at configure time: a property the linker dropped is missing here but not there.
TEST(PropertyRegistry, holdsEveryPropertyTheSourcesWrite) {
    EXPECT_EQ(all_properties().size(), static_cast<size_t>(RASTER_PROPERTIES_WRITTEN));
}

TEST(PropertyRegistry, namesEachPropertyOnceWithItsSuiteInOneRun) {
    std::set<std::string> names;
    std::vector<std::string> runs;  // the suites in order, one entry per run of properties of the same suite
    for (const Property& p : all_properties()) {
        EXPECT_TRUE(names.insert(p.suite + "." + p.name).second) << p.suite << "." << p.name << " is registered twice";
        if (runs.empty() || runs.back() != p.suite) runs.push_back(p.suite);
    }
    EXPECT_EQ(std::set<std::string>(runs.begin(), runs.end()).size(), runs.size()) << "a suite is split by another";
}

TEST(PropertyRegistry, everyPropertyRunsAsTheGtestOfItsName) {
    std::set<std::string> registered;
    const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
    for (int i = 0; i < unit.total_test_suite_count(); ++i) {
        const ::testing::TestSuite& suite = *unit.GetTestSuite(i);
        for (int j = 0; j < suite.total_test_count(); ++j)
            registered.insert(std::string(suite.name()) + "." + suite.GetTestInfo(j)->name());
    }
    for (const Property& p : all_properties())
        EXPECT_EQ(registered.count(p.suite + "." + p.name), 1u) << p.suite << "." << p.name << " has no gtest";
}

}  // namespace
}  // namespace raster::properties
