// The property list and the RC_GTEST_PROPs name the same properties, so the mutants run checks exactly what ctest runs.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "properties/property_list.h"

namespace raster::properties {
namespace {

TEST(PropertyList, namesExactlyTheRegisteredPropertyTests) {
    std::set<std::string> listed, suites;
    for (const Property& p : all_properties()) {
        EXPECT_TRUE(listed.insert(p.suite + "." + p.name).second) << p.suite << "." << p.name << " is listed twice";
        suites.insert(p.suite);
    }
    std::set<std::string> registered;
    const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
    for (int i = 0; i < unit.total_test_suite_count(); ++i) {
        const ::testing::TestSuite& suite = *unit.GetTestSuite(i);
        if (!suites.count(suite.name())) continue;
        for (int j = 0; j < suite.total_test_count(); ++j)
            registered.insert(std::string(suite.name()) + "." + suite.GetTestInfo(j)->name());
    }
    EXPECT_EQ(listed, registered);
    EXPECT_GE(listed.size(), 25u);
}

}  // namespace
}  // namespace raster::properties
