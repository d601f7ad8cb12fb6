// Fuzz target: a small random scene, in a precision mode the oracle can bound and sometimes with extreme
// coordinates (differential_scene.h), rendered by raster's production path (or by the plugin RASTER_FUZZ_PLUGIN
// names: docs/plugins.md) and by the independent oracle; the comparison must find no genuine disagreement, sample or
// pixel, of the classes the oracle judges in that mode, or the target traps with the comparison and the scene. A
// plugin that fails or breaks the interface's contract traps too; a frame it refuses is skipped.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "backends/plugin/plugin_renderer.h"
#include "fuzz/differential_scene.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "harness/comparison/comparison_output.h"
#include "raster/core/errors.h"

namespace {

// The plugin RASTER_FUZZ_PLUGIN names, loaded once; null (raster itself) when it is unset. A plugin that cannot
// be loaded stops the run before any input, saying why.
const raster::Renderer* plugin_under_test() {
    static const std::unique_ptr<raster::Renderer> plugin = []() -> std::unique_ptr<raster::Renderer> {
        const char* path = std::getenv("RASTER_FUZZ_PLUGIN");
        if (!path || !*path) return nullptr;
        try {
            return std::make_unique<raster::plugin::PluginRenderer>(raster::plugin::PluginLibrary::open(path));
        } catch (const std::exception& error) {
            std::fprintf(stderr, "differential: RASTER_FUZZ_PLUGIN: %s\n", error.what());
            std::exit(2);
        }
    }();
    return plugin.get();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::optional<raster::fuzz::DifferentialCase> input = raster::fuzz::differential_case(data, size);
    if (!input) return 0;
    raster::harness::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    options.renderer = plugin_under_test();
    std::optional<raster::harness::Comparison> compared;
    try {
        compared.emplace(raster::harness::compare_scene(input->scene, options));
    } catch (const raster::InputError&) {
        if (!options.renderer) throw;  // raster refusing a scene the generator made is a bug: let it crash
        return 0;                      // a frame the plugin does not draw
    } catch (const raster::plugin::PluginError& error) {
        FUZZ_CHECK_EQ(std::string(error.what()), std::string("(no plugin failure)"),
                      [&] { return "scene:\n" + raster::fuzz::describe_scene(input->scene); });
    }
    const raster::harness::Comparison& comparison = *compared;
    FUZZ_CHECK_EQ(comparison.genuine_total(), uint64_t{0}, [&] {
        return std::string("modes: ") + input->modes + "\n" + raster::harness::comparison_summary(comparison) + "\n" +
               raster::harness::genuine_details(comparison) +
               "scene:\n" + raster::fuzz::describe_scene(input->scene);
    });
    return 0;
}
