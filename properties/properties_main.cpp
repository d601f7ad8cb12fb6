// The property tests' main: one gtest per registered property, 1000 cases each unless RC_PARAMS says otherwise (the
// soak sets max_success).
#include <cstdlib>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/property_registry.h"

namespace raster::properties {
namespace {

// The gtest of one property: RapidCheck runs its check against implementation_under_test(), the real rasterizer
// or RASTER_PROPERTY_MUTANT's bug, exactly as an RC_GTEST_PROP body would (same ids, same reproduce strings).
class PropertyTest : public ::testing::Test {
public:
    explicit PropertyTest(void (*check)(const Implementation&)) : check_(check) {}

    void TestBody() override {
        ::rc::detail::checkGTest([check = check_] { check(implementation_under_test()); });
    }

private:
    void (*check_)(const Implementation&);
};

void register_property_tests() {
    for (const Property& p : all_properties())
        ::testing::RegisterTest(p.suite.c_str(), p.name.c_str(), nullptr, nullptr, p.file.c_str(), p.line,
                                [check = p.check]() -> ::testing::Test* { return new PropertyTest(check); });
}

}  // namespace
}  // namespace raster::properties

int main(int argc, char** argv) {
    // RapidCheck reads RC_PARAMS when a property first runs; an explicit setting always wins (overwrite = 0).
    setenv("RC_PARAMS", "max_success=1000", 0);
    ::testing::InitGoogleTest(&argc, argv);
    raster::properties::register_property_tests();
    return RUN_ALL_TESTS();
}
