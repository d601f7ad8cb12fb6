// Fuzz target: a small random scene, in a precision mode the oracle can bound and sometimes with extreme
// coordinates (differential_scene.h), rendered by raster's production path and by the independent oracle; the
// comparison must find no genuine disagreement, sample or pixel, of the classes the oracle judges in that mode, or
// the target traps with the comparison and the scene.
//
// In raster's place: the plugin RASTER_FUZZ_PLUGIN names (docs/plugins.md), judged under the exact modes, trapping
// too when it fails or breaks the interface's contract; or, in a build with the GL backend, OpenGL when
// RASTER_FUZZ_BACKEND=gl (docs/gl.md), on the nearest scene it draws. A frame either refuses is skipped, and every
// power of two of refusals is counted on stderr, so that a run that drew nothing says so.
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
#ifdef RASTER_WITH_GL
#include "backends/gl/gl_renderer.h"
#include "backends/gl/gl_scene.h"
#endif

namespace {

enum class UnderTest { raster, plugin, gl };

struct RendererUnderTest {
    UnderTest kind = UnderTest::raster;
    std::unique_ptr<raster::Renderer> renderer;  // null for raster itself
};

[[noreturn]] void stop(const std::string& message) {
    std::fprintf(stderr, "differential: %s\n", message.c_str());
    std::exit(2);
}

// Made once, from the environment; one that cannot be made stops the run before any input, saying why.
const RendererUnderTest& under_test() {
    static const RendererUnderTest chosen = [] {
        RendererUnderTest made;
        const char* backend = std::getenv("RASTER_FUZZ_BACKEND");
        const char* path = std::getenv("RASTER_FUZZ_PLUGIN");
        const bool has_backend = backend && *backend, has_plugin = path && *path;
        if (has_backend && has_plugin) stop("set RASTER_FUZZ_BACKEND or RASTER_FUZZ_PLUGIN, not both");
        if (has_backend) {
#ifdef RASTER_WITH_GL
            if (std::string(backend) == "gl") {
                made.kind = UnderTest::gl;
                made.renderer = std::make_unique<raster::gl::GlRenderer>();
                return made;
            }
#endif
            stop(std::string("RASTER_FUZZ_BACKEND=") + backend +
                 ": this build has no such backend (gl needs -DRASTER_BUILD_GL=ON)");
        }
        if (has_plugin) {
            try {
                made.renderer =
                    std::make_unique<raster::plugin::PluginRenderer>(raster::plugin::PluginLibrary::open(path));
            } catch (const std::exception& error) {
                stop(std::string("RASTER_FUZZ_PLUGIN: ") + error.what());
            }
            made.kind = UnderTest::plugin;
        }
        return made;
    }();
    return chosen;
}

void count_refusal(const char* why) {
    static uint64_t refused = 0;
    ++refused;
    if ((refused & (refused - 1)) == 0)
        std::fprintf(stderr, "differential: %llu inputs refused so far, the last: %s\n",
                     static_cast<unsigned long long>(refused), why);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::optional<raster::fuzz::DifferentialCase> input = raster::fuzz::differential_case(data, size);
    if (!input) return 0;
    const RendererUnderTest& tested = under_test();
    // What is judged: every genuine class, but for OpenGL at more than one sample, where llvmpipe's per-sample 1/w
    // (docs/gl.md, finding 2) puts colours off wherever the perspective varies across a pixel: there the samples.
    bool samples_only = false;
    if (tested.kind == UnderTest::plugin) {  // a plugin is told no precision mode: it is judged under the exact ones
        input->scene.settings.modes = raster::PrecisionModes{};
        input->modes = "default (a plugin runs under the exact modes)";
    }
#ifdef RASTER_WITH_GL
    if (tested.kind == UnderTest::gl) {  // otherwise OpenGL would refuse almost every input
        input->scene = raster::gl::gl_drawable(std::move(input->scene));
        input->modes = "default (restricted to what the GL backend draws)";
        samples_only = input->scene.settings.samples > 1;
    }
#endif
    raster::harness::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    options.renderer = tested.renderer.get();
    std::optional<raster::harness::Comparison> compared;
    try {
        compared.emplace(raster::harness::compare_scene(input->scene, options));
    } catch (const raster::plugin::PluginRefusal& refusal) {
        count_refusal(refusal.what());
        return 0;
    } catch (const raster::plugin::PluginError& error) {
        raster::fuzz::check_failed(__FILE__, __LINE__, "the plugin's failure", "==", "none", std::string(error.what()),
                                   std::string("none"),
                                   [&] { return "scene:\n" + raster::fuzz::describe_scene(input->scene); });
    } catch (const raster::InputError& error) {
        if (tested.kind != UnderTest::gl) throw;  // raster refusing a scene the generator made is a bug: crash
        count_refusal(error.what());              // what the GL backend does not draw even so (finding 3)
        return 0;
    }
    const raster::harness::Comparison& comparison = *compared;
    const uint64_t genuine =
        samples_only ? comparison.visibility.counts.genuine_total() : comparison.genuine_total();
    FUZZ_CHECK_EQ(genuine, uint64_t{0}, [&] {
        return std::string("modes: ") + input->modes + "\n" + raster::harness::comparison_summary(comparison) + "\n" +
               raster::harness::genuine_details(comparison) +
               "scene:\n" + raster::fuzz::describe_scene(input->scene);
    });
    return 0;
}
