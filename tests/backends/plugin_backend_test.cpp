// The plugin backend (backends/plugin): raster's own stages behind the C interface give raster's bytes, so the host
// hands over the frame and takes back the samples faithfully; every breach of the interface's contract is named;
// solved barycentrics project back to the sample; libraries load or are refused by path; and the framework finds
// the example naive plugin's bugs (docs/plugins.md) while passing what it draws right.
#include "backends/plugin/plugin_renderer.h"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "backends/plugin/plugin_samples.h"
#include "harness/comparison/comparison_output.h"
#include "harness/comparison/scene_comparison.h"
#include "properties/raster_stages_plugin.h"
#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "raster/frame/render.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(RASTER_SOURCE_DIR) / "corpus/scenes";

uint32_t current_abi() { return RASTER_PLUGIN_ABI_VERSION; }
const char* test_name() { return "test plugin"; }

std::shared_ptr<const plugin::PluginLibrary> in_process(int (*draw)(const raster_plugin_frame*, raster_plugin_samples*),
                                                       uint32_t (*abi)() = current_abi) {
    return std::make_shared<plugin::PluginLibrary>(plugin::PluginFunctions{abi, test_name, draw}, "in-process");
}

RenderResult render_with(const Renderer& renderer, const Scene& scene) {
    RenderResult result;
    renderer.render_into(scene, RenderOptions{}, result);
    return result;
}

// raster's own stages behind the C interface (properties/raster_stages_plugin.h), on every corpus scene raster
// draws with its default modes (opaque or transparent, lit, shadowed, textured, orthographic, at its own sample
// count), as it is, with back faces culled and, with transparency, its meshes reversed: the same ids, barycentrics
// and image bytes through the plugin interface as from raster itself. The view depths the host derives from the barycentrics agree to float rounding.
TEST(PluginBackend, rastersOwnStagesBehindTheInterfaceGiveRastersBytes) {
    const plugin::PluginRenderer renderer(properties::raster_stages_plugin());
    for (const auto& entry : std::filesystem::directory_iterator(kScenes))
        for (const int variant : {0, 1, 2}) {
        Scene scene = load_scene(entry.path());
        // 1: back faces culled. 2: the meshes in reverse order, so that a transparent mesh comes before opaque
        // ones and the plugin's indices into the opaque triangles are no longer the scene's ids.
        if (variant == 1) scene.settings.cull_backfaces = true;
        if (variant == 2) {
            if (!has_transparency(scene)) continue;
            std::reverse(scene.meshes.begin(), scene.meshes.end());
        }
        const RenderResult direct = render(scene, RenderOptions{});
        const RenderResult through = render_with(renderer, scene);
        const std::string name =
            entry.path().filename().string() + (variant == 1 ? " culled" : variant == 2 ? " reversed" : "");
        ASSERT_EQ(through.visibility.triangle, direct.visibility.triangle) << name;
        EXPECT_TRUE(std::memcmp(through.visibility.bary.data(), direct.visibility.bary.data(),
                                direct.visibility.bary.size() * sizeof(glm::vec3)) == 0)
            << name;
        EXPECT_EQ(through.image.pixels, direct.image.pixels) << name;
        for (size_t i = 0; i < direct.visibility.size(); ++i) {
            if (direct.visibility.triangle[i] == kNoTriangle) continue;
            ASSERT_NEAR(through.visibility.view_depth[i], direct.visibility.view_depth[i],
                        1e-5 * direct.visibility.view_depth[i])
                << name << " sample " << i;
        }
        }
}

// The same plugin answering ids only: the host solves each covered sample's barycentrics from the clip-space
// vertices at the sample's position (pixel, offset, rows from the top). Judged by the oracle, they agree at every
// sample of the corpus scenes below, at 1 and 4 samples (raster's own differ from them on thin triangles, where its
// snapped vertices move the weights by up to 0.1: the precision model allows both).
TEST(PluginBackend, barycentricsSolvedByTheHostAgreeWithTheOracle) {
    const plugin::PluginRenderer renderer(properties::raster_stages_plugin(false));
    harness::ComparisonOptions options;
    options.renderer = &renderer;
    for (const char* name : {"teapot.yaml", "perspective_quad.yaml", "orthographic.yaml", "near_crossing.yaml",
                             "shadows_and_glass.yaml"})
        for (const int samples : {1, 4}) {
            Scene scene = load_scene(kScenes / name);
            scene.settings.samples = samples;
            const harness::Comparison c = harness::compare_scene(scene, options);
            EXPECT_EQ(c.genuine_total(), 0u) << name << " at " << samples << ":\n" << harness::genuine_details(c);
            EXPECT_GT(c.visibility.counts.count(oracle::SampleClass::agree), 0u) << name;
        }
}

// A frame of one triangle covering the middle of a 4 x 4 image at one sample per pixel.
plugin::ClipSpaceFrame one_triangle_frame() {
    plugin::ClipSpaceFrame frame;
    frame.width = frame.height = 4;
    frame.sample_offsets = {glm::vec2(0.5f)};
    frame.triangles.push_back({glm::vec4(-1, -1, 0.5f, 1), glm::vec4(1, -1, 0.5f, 1), glm::vec4(0, 1, 0.5f, 1)});
    return frame;
}

std::string message_of_draw(const std::shared_ptr<const plugin::PluginLibrary>& library) {
    VisibilityBuffer out;
    try {
        library->draw(one_triangle_frame(), out);
    } catch (const std::exception& error) {
        return error.what();
    }
    return "(drew)";
}

TEST(PluginBackend, everyBreachOfTheContractIsNamedWithTheSample) {
    // A triangle the frame does not have.
    const auto past_the_end = [](const raster_plugin_frame*, raster_plugin_samples* out) {
        out->triangle[6] = 7;
        return RASTER_PLUGIN_DRAWN;
    };
    EXPECT_THROW(in_process(past_the_end)->draw(one_triangle_frame(), *std::make_unique<VisibilityBuffer>()),
                 plugin::PluginError);
    EXPECT_EQ(message_of_draw(in_process(past_the_end)),
              "plugin test plugin wrote triangle 7 at sample 0 of pixel (2, 1), but the frame has 1 triangles");
    // Barycentrics claimed but left unwritten at a covered sample.
    const auto claimed = [](const raster_plugin_frame*, raster_plugin_samples* out) {
        out->triangle[5] = 0;
        out->barycentrics_written = 1;
        return RASTER_PLUGIN_DRAWN;
    };
    EXPECT_NE(message_of_draw(in_process(claimed)).find("at sample 0 of pixel (1, 1): they must be finite"),
              std::string::npos)
        << message_of_draw(in_process(claimed));
    // A refusal is the plugin's limit (PluginRefusal, an InputError: exit 2); a failure is a finding (PluginError).
    const auto refusing = [](const raster_plugin_frame*, raster_plugin_samples* out) {
        std::strcpy(out->message, "only 1 sample per pixel");
        return RASTER_PLUGIN_REFUSED;
    };
    VisibilityBuffer out;
    EXPECT_THROW(in_process(refusing)->draw(one_triangle_frame(), out), plugin::PluginRefusal);
    EXPECT_EQ(message_of_draw(in_process(refusing)), "plugin test plugin does not draw this frame: only 1 sample per pixel");
    const auto failing = [](const raster_plugin_frame*, raster_plugin_samples* out) {
        std::memset(out->message, 'x', RASTER_PLUGIN_MESSAGE_SIZE);  // unterminated: raster ends it in the buffer
        return 42;
    };
    EXPECT_THROW(in_process(failing)->draw(one_triangle_frame(), out), plugin::PluginError);
    EXPECT_EQ(message_of_draw(in_process(failing)),
              "plugin test plugin failed (raster_plugin_draw returned 42): " +
                  std::string(RASTER_PLUGIN_MESSAGE_SIZE - 1, 'x'));
    // Another version of the interface is refused before any frame.
    const auto other_abi = []() -> uint32_t { return RASTER_PLUGIN_ABI_VERSION + 1; };
    try {
        in_process(past_the_end, other_abi);
        ADD_FAILURE() << "a plugin of another interface version was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("built against version 2 of raster_plugin.h"), std::string::npos)
            << error.what();
    }
}

// Ids only: the host solves each covered sample's barycentrics from the clip-space vertices, and they project back
// to the sample: for random triangles with random w and random weights, the point sum l_i v_i projects to a
// screen position whose solve gives l back.
TEST(PluginBackend, solvedBarycentricsProjectBackToTheSample) {
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0), w(0.01, 50.0), weight(0.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        std::array<glm::vec4, 3> triangle;
        for (glm::vec4& v : triangle) {
            const double vw = w(random);
            v = glm::vec4(coordinate(random) * vw, coordinate(random) * vw, 0.5 * vw, vw);
        }
        glm::dvec3 l(weight(random), weight(random), weight(random));
        l /= l.x + l.y + l.z;
        glm::dvec4 p(0.0);
        for (int k = 0; k < 3; ++k) p += l[k] * glm::dvec4(triangle[static_cast<size_t>(k)]);
        const int width = 640, height = 480;
        const glm::dvec2 screen((p.x / p.w + 1.0) * 0.5 * width, (1.0 - p.y / p.w) * 0.5 * height);
        const glm::dvec3 solved = plugin::solve_barycentrics(triangle, screen, width, height);
        const double area = std::abs(glm::determinant(glm::dmat3(glm::dvec3(triangle[0].x, triangle[0].y, triangle[0].w),
                                                                 glm::dvec3(triangle[1].x, triangle[1].y, triangle[1].w),
                                                                 glm::dvec3(triangle[2].x, triangle[2].y, triangle[2].w))));
        if (area < 1e-3) continue;  // nearly edge-on: the weights are ill-conditioned
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(solved[k], l[k], 1e-6) << "case " << i;
    }
}

TEST(PluginBackend, librariesLoadOrAreRefusedByPath) {
    const auto naive = plugin::PluginLibrary::open(RASTER_NAIVE_PLUGIN);
    EXPECT_EQ(naive->name(), "naive rasterizer (float edges, no fill rule)");
    const auto refused = [](const std::string& path) {
        try {
            plugin::PluginLibrary::open(path);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("(loaded)");
    };
    EXPECT_NE(refused("/no/such/plugin.so").find("no plugin library at this path"), std::string::npos);
    test_support::TempDir dir;
    std::ofstream(dir / "text.so") << "not a library\n";
    EXPECT_NE(refused((dir / "text.so").string()).find("cannot load this plugin"), std::string::npos);
    // A real shared library without the interface's functions: the C library's mathematics.
    Dl_info math{};
    ASSERT_NE(dladdr(reinterpret_cast<void*>(static_cast<double (*)(double)>(&::cos)), &math), 0);
    EXPECT_NE(refused(math.dli_fname).find("has no function raster_plugin_abi_version"), std::string::npos)
        << refused(math.dli_fname);
}

// What the framework finds in the example naive rasterizer (docs/plugins.md): its affine barycentrics are genuine
// barycentric disagreements on every perspective scene, its dropped near-plane triangles genuine visibility ones;
// a screen-parallel triangle, where neither bug shows, agrees everywhere.
TEST(PluginBackend, theOracleFindsTheNaivePluginsBugsAndPassesWhatItDrawsRight) {
    const plugin::PluginRenderer renderer(plugin::PluginLibrary::open(RASTER_NAIVE_PLUGIN));
    harness::ComparisonOptions options;
    options.renderer = &renderer;
    const auto compare = [&](const char* name) {
        return harness::compare_scene(load_scene(kScenes / name), options);
    };
    const harness::Comparison teapot = compare("teapot.yaml");
    EXPECT_GT(teapot.visibility.counts.count(oracle::SampleClass::barycentrics), 10000u);
    EXPECT_EQ(teapot.visibility.counts.count(oracle::SampleClass::visibility), 0u)
        << harness::genuine_details(teapot);
    const harness::Comparison near = compare("near_crossing.yaml");
    EXPECT_GT(near.visibility.counts.count(oracle::SampleClass::visibility), 10000u);
    const harness::Comparison flat = compare("single_triangle.yaml");
    EXPECT_EQ(flat.genuine_total(), 0u) << harness::genuine_details(flat);
    EXPECT_GT(flat.visibility.counts.count(oracle::SampleClass::agree), 0u);
}

// The command line: render draws with the plugin (exit 0); compare finds its bugs (exit 1) and names it; report
// writes its own row and page beside raster's and fails; a library that cannot be loaded, or a backend that is no
// backend, exits 2 naming it.
TEST(PluginBackend, theCommandLineRunsItByName) {
    const std::string plugin = std::string("plugin:") + RASTER_NAIVE_PLUGIN;
    const std::string teapot = (kScenes / "teapot.yaml").string();
    const test_support::TempDir dir;
    const test_support::CliRun rendered =
        test_support::run_raster({"render", teapot, "--backend", plugin, "-o", (dir / "naive.png").string()});
    EXPECT_EQ(rendered.code, 0) << rendered.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "naive.png"));
    const test_support::CliRun compared = test_support::run_raster({"compare", teapot, "--backend", plugin});
    EXPECT_EQ(compared.code, 1) << compared.out << compared.err;
    EXPECT_NE(compared.out.find("(plugin naive rasterizer (float edges, no fill rule))"), std::string::npos)
        << compared.out;
    const test_support::CliRun reported = test_support::run_raster(
        {"report", teapot, "--backend", "raster," + plugin, "-o", (dir / "report").string()});
    EXPECT_EQ(reported.code, 1) << reported.out << reported.err;
    EXPECT_NE(reported.out.find("teapot (plugin-naive_rasterizer): genuine 104464"), std::string::npos) << reported.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "report" / "teapot-plugin-naive_rasterizer.html"));
    EXPECT_TRUE(std::filesystem::exists(dir / "report" / "teapot.html"));
    const test_support::CliRun missing =
        test_support::run_raster({"compare", teapot, "--backend", "plugin:/no/such/plugin.so"});
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("/no/such/plugin.so: no plugin library at this path"), std::string::npos) << missing.err;
    const test_support::CliRun unknown = test_support::run_raster({"render", teapot, "--backend", "plugin:"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_NE(unknown.err.find("'plugin:' is not a backend: raster, gl or plugin:PATH"), std::string::npos)
        << unknown.err;
}

}  // namespace
}  // namespace raster
