// The registry holds every property the sources write, each once, in suites that stay together, and each runs as
// a gtest of the same name (a drawing one once per backend), so that ctest and the mutants run check the same
// properties; and exactly the properties registered as drawing ones rasterize.
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "properties/property_registry.h"
#include "properties/stage_driver.h"

namespace raster::properties {
namespace {

// RASTER_PROPERTIES_WRITTEN is the number of lines starting with RASTER_PROPERTY( or RASTER_DRAWING_PROPERTY( in the
// property sources, counted by properties/CMakeLists.txt at configure time: a property the linker dropped is missing
// here but not there.
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
    for (const Property& p : all_properties()) {
        if (!p.draws) {
            EXPECT_EQ(registered.count(p.suite + "." + p.name), 1u) << p.suite << "." << p.name << " has no gtest";
            continue;
        }
        for (const Backend& backend : drawing_backends())
            EXPECT_EQ(registered.count(p.suite + "." + p.name + "/" + backend.name), 1u)
                << p.suite << "." << p.name << " has no gtest on backend " << backend.name;
    }
}

// A drawing property registered as a plain one would never run on the production renderer; a plain one registered
// as drawing would run several times for nothing. Twenty cases of each, counting the rasterizations it asks for.
TEST(PropertyRegistry, exactlyTheDrawingPropertiesRasterize) {
    rc::detail::TestParams params;
    params.seed = 1;
    params.maxSuccess = 20;
    params.disableShrinking = true;
    for (const Property& p : all_properties()) {
        const size_t before = rasterizer_runs();
        rc::detail::TestMetadata metadata;
        metadata.id = p.suite + "." + p.name;
        const Implementation impl = on_backend(real_implementation(), reference_backend());
        rc::detail::checkProperty(rc::detail::toProperty([&] { p.check(impl); }), metadata, params);
        const bool drew = rasterizer_runs() > before;
        EXPECT_EQ(drew, p.draws) << p.suite << "." << p.name << (p.draws ? " is registered as drawing but never rasterized"
                                                                          : " rasterizes but is not registered as drawing");
    }
}

}  // namespace
}  // namespace raster::properties
