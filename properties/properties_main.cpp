// The property tests' main: one gtest per registered property, per drawing backend for a drawing property and per
// plugin backend for a renderer property (RASTER_PROPERTIES_PLUGIN=PATH adds a plugin of yours as "plugin"); 1000
// cases each from a fixed seed, printed, unless RC_PARAMS says otherwise (the soak sets max_success and no seed, so
// it draws a fresh one each run).
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/property_registry.h"

namespace raster::properties {
namespace {

// The gtest of one property: RapidCheck runs its check against the real rasterizer on one backend, exactly as an RC_GTEST_PROP body would (same ids, same
// reproduce strings).
class PropertyTest : public ::testing::Test {
public:
    PropertyTest(void (*check)(const Implementation&), Backend backend) : check_(check), backend_(std::move(backend)) {}

    void TestBody() override {
        const Implementation impl = on_backend(real_implementation(), backend_);
        ::rc::detail::checkGTest([check = check_, &impl] { check(impl); });
    }

private:
    void (*check_)(const Implementation&);
    Backend backend_;
};

void register_property_tests(const std::vector<Backend>& plugins) {
    for (const Property& p : all_properties()) {
        auto add = [&](const std::string& name, const Backend& backend) {
            ::testing::RegisterTest(p.suite.c_str(), name.c_str(), nullptr, nullptr, p.file.c_str(), p.line,
                                    [check = p.check, backend]() -> ::testing::Test* {
                                        return new PropertyTest(check, backend);
                                    });
        };
        if (!p.draws) {
            add(p.name, production_backend());
            continue;
        }
        for (const Backend& backend : drawing_backends()) add(p.name + "/" + backend.name, backend);
        if (p.any_renderer)
            for (const Backend& backend : plugins) add(p.name + "/" + backend.name, backend);
    }
}

// The seed ctest's runs use, so that every run gives the same verdicts; a failure's reproduce string still
// names the exact case.
constexpr const char* kDefaultSeed = "2026";

}  // namespace
}  // namespace raster::properties

int main(int argc, char** argv) {
    // RapidCheck reads RC_PARAMS when a property first runs; an explicit setting always wins (overwrite = 0).
    const std::string defaults = std::string("max_success=1000 seed=") + raster::properties::kDefaultSeed;
    setenv("RC_PARAMS", defaults.c_str(), 0);
    bool listing = false;
    for (int i = 1; i < argc; ++i) listing = listing || std::strcmp(argv[i], "--gtest_list_tests") == 0;
    if (!listing) std::cout << "properties: RC_PARAMS=\"" << std::getenv("RC_PARAMS") << "\"\n";
    ::testing::InitGoogleTest(&argc, argv);
    std::vector<raster::properties::Backend> plugins;
    try {
        plugins = raster::properties::plugin_backends();
    } catch (const std::exception& error) {  // RASTER_PROPERTIES_PLUGIN names no loadable plugin
        std::cerr << "properties: RASTER_PROPERTIES_PLUGIN: " << error.what() << "\n";
        return 2;
    }
    raster::properties::register_property_tests(plugins);
    return RUN_ALL_TESTS();
}
