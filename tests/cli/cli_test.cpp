// CLI tests: run the real `raster` binary and check help, exit codes, output files, --stats and atomic writes.
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

// A fresh directory with in/ (scenes), out/ (outputs, expected empty after a failure) and log/ (captured streams).
class Workspace {
public:
    Workspace() {
        std::string pattern = (fs::temp_directory_path() / "raster_cli_test_XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        root_ = pattern;
        fs::create_directories(in());
        fs::create_directories(out());
        fs::create_directories(root_ / "log");
    }
    ~Workspace() {
        std::error_code ignored;
        fs::remove_all(root_, ignored);
    }
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;

    fs::path in() const { return root_ / "in"; }
    fs::path out() const { return root_ / "out"; }
    fs::path log() const { return root_ / "log"; }

    fs::path write_scene(const std::string& name, const std::string& text) const {
        const fs::path path = in() / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    std::vector<std::string> out_entries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(out())) names.push_back(entry.path().filename().string());
        return names;
    }

private:
    fs::path root_;
};

struct Result {
    int status = -1;
    std::string out;
    std::string err;
};

std::string quote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) {
        if (c == '\'') quoted += "'\\''";
        else quoted += c;
    }
    return quoted + "'";
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs `raster ARGS` (each argument quoted) in `cwd`, capturing stdout and stderr into the workspace's log folder.
Result run_raster(const Workspace& ws, const std::vector<std::string>& args, const fs::path& cwd = {}) {
    std::string command;
    if (!cwd.empty()) {
        command += "cd ";
        command += quote(cwd.string());
        command += " && ";
    }
    command += quote(RASTER_BINARY);
    for (const std::string& arg : args) {
        command += ' ';
        command += quote(arg);
    }
    command += " >";
    command += quote((ws.log() / "stdout").string());
    command += " 2>";
    command += quote((ws.log() / "stderr").string());
    const int raw = std::system(command.c_str());
    Result result;
    result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    result.out = read_bytes(ws.log() / "stdout");
    result.err = read_bytes(ws.log() / "stderr");
    return result;
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

uint32_t big_endian_u32(const std::string& bytes, size_t at) {
    return (uint32_t(uint8_t(bytes.at(at))) << 24) | (uint32_t(uint8_t(bytes.at(at + 1))) << 16) |
           (uint32_t(uint8_t(bytes.at(at + 2))) << 8) | uint32_t(uint8_t(bytes.at(at + 3)));
}

// 40 x 30, one unlit triangle: fast to render.
const char* kScene =
    "image: {width: 40, height: 30, background: [0.1, 0.2, 0.3]}\n"
    "camera: {eye: [0, 0, 3], target: [0, 0, 0], fov: 50}\n"
    "render: {shading: unlit}\n"
    "meshes:\n"
    "  - vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]\n"
    "    faces: [[0, 1, 2]]\n"
    "    vertex_colors: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\n";

// The flags of `raster render` as docs/cli.md lists them.
const std::vector<std::string> kReadmeFlags = {"-o",      "--samples", "--pattern", "--msaa",      "--shading", "--snap-bits",
                                               "--cull",  "--alpha",   "--depth-out", "--threads", "--stats"};

TEST(Cli, helpMentionsEveryReadmeFlag) {
    Workspace ws;
    const Result top = run_raster(ws, {"--help"});
    EXPECT_EQ(top.status, 0) << top.err;
    EXPECT_TRUE(contains(top.out, "render"));
    for (const std::string& flag : kReadmeFlags) EXPECT_TRUE(contains(top.out, flag)) << "raster --help";

    const Result render = run_raster(ws, {"render", "--help"});
    EXPECT_EQ(render.status, 0) << render.err;
    for (const std::string& flag : kReadmeFlags) EXPECT_TRUE(contains(render.out, flag)) << "raster render --help";
    // The choices of the enumerated flags.
    for (const char* choice : {"standard", "grid", "unlit", "flat", "gouraud", "blinn-phong", "none", "back"})
        EXPECT_TRUE(contains(render.out, choice));
}

TEST(Cli, theShadowAndTransparencyFlagsAreListedAndTheABuffersCapIsAClearError) {
    Workspace ws;
    const Result help = run_raster(ws, {"render", "--help"});
    for (const char* flag : {"--shadows", "--shadow-resolution", "--shadow-bias", "--shadow-slope-bias", "--pcf",
                             "--transparency", "--max-fragments", "sorted", "weighted"})
        EXPECT_TRUE(contains(help.out, flag)) << flag;
    // The scene's triangle made a pane of opacity 0.5: 600-odd fragments at 1 sample.
    std::string glass = kScene;
    glass += "    material: {opacity: 0.5}\n";
    const fs::path scene = ws.write_scene("glass.yaml", glass);
    const Result capped = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "capped.png").string(),
                                          "--max-fragments", "10"});
    EXPECT_EQ(capped.status, 2) << capped.err;
    EXPECT_TRUE(contains(capped.err, "more than 10 transparent fragments")) << capped.err;
    EXPECT_FALSE(fs::exists(ws.out() / "capped.png"));
    const Result weighted = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "weighted.png").string(),
                                            "--max-fragments", "10", "--transparency", "weighted", "--stats"});
    EXPECT_EQ(weighted.status, 0) << weighted.err;
    EXPECT_TRUE(contains(weighted.out, "\"transparent_fragments\""));
    const Result bad = run_raster(ws, {"render", scene.string(), "--transparency", "depth-peeling"});
    EXPECT_EQ(bad.status, 2);
}

TEST(Cli, repeatRendersTheSameImageAndReportsTheFirstAndMedianFrames) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const Result once = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "once.png").string()});
    ASSERT_EQ(once.status, 0) << once.err;
    const Result repeated = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "repeated.png").string(),
                                            "--repeat", "3", "--stats"});
    ASSERT_EQ(repeated.status, 0) << repeated.err;
    EXPECT_EQ(read_bytes(ws.out() / "repeated.png"), read_bytes(ws.out() / "once.png"));
    EXPECT_TRUE(contains(repeated.out, "\"frames\":3"));
    EXPECT_TRUE(contains(repeated.out, "\"ms_first\""));
    EXPECT_TRUE(contains(repeated.out, "\"ms_median\""));
    EXPECT_EQ(run_raster(ws, {"render", scene.string(), "--repeat", "0"}).status, 2);
}

// Every frame after the first reuses the last one's workspace (setups, bins, transparent setups, threads' scratch):
// on a scene with shadows and transparent layers, where the most is reused, the last of three frames must still be
// the bytes of a single frame.
TEST(Cli, repeatedFramesOfAShadowedTransparentSceneAreASingleFramesBytes) {
    Workspace ws;
    const fs::path scene = fs::path(RASTER_SOURCE_DIR) / "corpus/scenes/shadows_and_glass.yaml";
    const Result once = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "once.png").string()});
    ASSERT_EQ(once.status, 0) << once.err;
    const Result repeated =
        run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "repeated.png").string(), "--repeat", "3"});
    ASSERT_EQ(repeated.status, 0) << repeated.err;
    EXPECT_EQ(read_bytes(ws.out() / "repeated.png"), read_bytes(ws.out() / "once.png"));
}

// The CPU's feature flags as the kernel reports them (/proc/cpuinfo's first "flags" line).
std::string cpu_flags() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("flags", 0) == 0) return line + " ";
    return "";
}

TEST(Cli, versionNamesTheReleaseAndTheSimdTargetThisCpuGets) {
    Workspace ws;
    const Result version = run_raster(ws, {"--version"});
    ASSERT_EQ(version.status, 0) << version.err;
    std::istringstream lines(version.out);
    std::string first, second;
    std::getline(lines, first);
    std::getline(lines, second);
    EXPECT_EQ(first, std::string("raster ") + RASTER_PROJECT_VERSION);
    ASSERT_EQ(second.rfind("SIMD target: ", 0), 0u) << second;
    const std::string chosen = second.substr(13, second.find(' ', 13) - 13);
    // The best x86 target the kernel says this CPU has (Highway's AVX3 is AVX-512 F, VL, DQ and BW; its AVX2 also
    // needs FMA, BMI2 and F16C), and the list ends with the portable fallback.
    const std::string flags = cpu_flags();
    auto has = [&](const char* flag) { return flags.find(std::string(" ") + flag + " ") != std::string::npos; };
    if (has("avx512f") && has("avx512vl") && has("avx512dq") && has("avx512bw"))
        EXPECT_EQ(chosen, "AVX3") << second;
    else if (has("avx2") && has("fma") && has("bmi2") && has("f16c"))
        EXPECT_EQ(chosen, "AVX2") << second;
    EXPECT_NE(second.find("SCALAR)"), std::string::npos) << second;
    // It is the program's flag, not a subcommand's: `render --version` is a usage error.
    const Result late = run_raster(ws, {"render", "--version"});
    EXPECT_NE(late.status, 0);
}

TEST(Cli, missingSubcommandIsUsageError) {
    Workspace ws;
    const Result none = run_raster(ws, {});
    EXPECT_EQ(none.status, 2);
    EXPECT_FALSE(none.err.empty());
    const Result unknown = run_raster(ws, {"paint", "scene.yaml"});
    EXPECT_EQ(unknown.status, 2);
    // `render` without a scene.
    EXPECT_EQ(run_raster(ws, {"render"}).status, 2);
}

TEST(Cli, unknownFlagIsUsageError) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const Result result = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "img.png").string(), "--bogus"});
    EXPECT_EQ(result.status, 2);
    EXPECT_TRUE(contains(result.err, "--bogus"));
    EXPECT_TRUE(ws.out_entries().empty());
}

TEST(Cli, rendersPngOfTheScenesSize) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const fs::path image = ws.out() / "img.png";
    const Result result = run_raster(ws, {"render", scene.string(), "-o", image.string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string bytes = read_bytes(image);
    ASSERT_GE(bytes.size(), 33u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");  // the first chunk
    EXPECT_EQ(big_endian_u32(bytes, 16), 40u);
    EXPECT_EQ(big_endian_u32(bytes, 20), 30u);
    EXPECT_EQ(ws.out_entries(), std::vector<std::string>{"img.png"});  // no temporary left beside it
}

TEST(Cli, defaultOutputIsSceneStemPngInCurrentDirectory) {
    Workspace ws;
    const fs::path scene = ws.write_scene("teapotish.yaml", kScene);
    const Result result = run_raster(ws, {"render", scene.string()}, ws.out());
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(ws.out_entries(), std::vector<std::string>{"teapotish.png"});
    EXPECT_EQ(read_bytes(ws.out() / "teapotish.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(Cli, writesBinaryPpmForPpmExtension) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const fs::path image = ws.out() / "img.ppm";
    const Result result = run_raster(ws, {"render", scene.string(), "-o", image.string(), "--samples", "4"});
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string bytes = read_bytes(image);
    std::istringstream header(bytes);
    std::string magic;
    int width = 0, height = 0, maxval = 0;
    header >> magic >> width >> height >> maxval;
    EXPECT_EQ(magic, "P6");
    EXPECT_EQ(width, 40);
    EXPECT_EQ(height, 30);
    EXPECT_EQ(maxval, 255);
    // One whitespace byte after maxval, then exactly width x height RGB triples.
    const size_t body = static_cast<size_t>(header.tellg()) + 1;
    EXPECT_EQ(bytes.size() - body, size_t{40} * 30 * 3);
}

TEST(Cli, statsPrintsOneJsonLine) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const Result result =
        run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "img.png").string(), "--samples", "4", "--stats"});
    ASSERT_EQ(result.status, 0) << result.err;
    ASSERT_FALSE(result.out.empty());
    EXPECT_EQ(result.out.back(), '\n');
    EXPECT_EQ(result.out.find('\n'), result.out.size() - 1) << "more than one line: " << result.out;
    const nlohmann::json stats = nlohmann::json::parse(result.out);
    ASSERT_TRUE(stats.is_object());
    for (const char* key : {"triangles", "clipped", "rasterized", "samples", "covered_samples", "ms_vertex", "ms_setup",
                            "ms_raster", "ms_shade", "ms_total"}) {
        ASSERT_TRUE(stats.contains(key)) << key;
        EXPECT_TRUE(stats[key].is_number()) << key;
        EXPECT_GE(stats[key].get<double>(), 0.0) << key;
    }
    EXPECT_EQ(stats["triangles"].get<int>(), 1);
    EXPECT_EQ(stats["samples"].get<int>(), 40 * 30 * 4);  // width x height x samples per pixel
    EXPECT_GT(stats["covered_samples"].get<int>(), 0);
    EXPECT_LT(stats["covered_samples"].get<int>(), 40 * 30 * 4);
    EXPECT_GE(stats["ms_total"].get<double>(), stats["ms_raster"].get<double>());
    // Without --stats, stdout stays empty.
    EXPECT_TRUE(run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "b.png").string()}).out.empty());
}

// Bad input: exit code 2, and nothing in the output folder (neither the image nor a temporary file).
void expect_bad_input(const Workspace& ws, const Result& result, const std::vector<std::string>& mentions) {
    EXPECT_EQ(result.status, 2) << result.err;
    for (const std::string& text : mentions) EXPECT_TRUE(contains(result.err, text));
    EXPECT_TRUE(ws.out_entries().empty()) << ws.out_entries().front();
}

TEST(Cli, missingSceneFileExitsTwo) {
    Workspace ws;
    const fs::path missing = ws.in() / "missing.yaml";
    const Result result = run_raster(ws, {"render", missing.string(), "-o", (ws.out() / "img.png").string()});
    expect_bad_input(ws, result, {missing.string()});
}

TEST(Cli, sceneSyntaxErrorExitsTwoNamingFileAndLine) {
    Workspace ws;
    // Line 3 is indented one space: a YAML syntax error there.
    const fs::path scene = ws.write_scene("broken.yaml", "image:\n  width: 10\n height: 5\nmeshes: []\n");
    const Result result = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "img.png").string()});
    expect_bad_input(ws, result, {scene.string() + ":3:"});
}

TEST(Cli, nearNotPositiveExitsTwoNamingFileLineAndColumn) {
    Workspace ws;
    std::string text = kScene;
    text.replace(text.find("fov: 50}"), 8, "fov: 50,\n         near: -1}");
    // "camera: {eye: ..." is line 2; "         near: -1}" is line 3 and -1 starts at column 16.
    const fs::path scene = ws.write_scene("near.yaml", text);
    const Result result = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "img.png").string()});
    expect_bad_input(ws, result, {scene.string() + ":3:16:", "near"});
}

TEST(Cli, samplesInvalidForPatternExitsTwo) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const std::string image = (ws.out() / "img.png").string();
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--samples", "3"}), {"3"});
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--pattern", "grid", "--samples", "8"}),
                     {"8"});
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--samples", "many"}), {"many"});
}

// --resolution-divisor: the image keeps its size, the frame's samples are the internal ones; a divisor that is not
// 1, 2 or 4 or does not divide the size, a depth image, alpha and a comparison are clear errors.
TEST(Cli, aReducedResolutionKeepsTheImageSizeAndRefusesWhatItCannotGive) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);  // 40 x 30
    const std::string image = (ws.out() / "img.png").string();
    const Result halved = run_raster(ws, {"render", scene.string(), "-o", image, "--resolution-divisor", "2", "--stats"});
    ASSERT_EQ(halved.status, 0) << halved.err;
    const nlohmann::json stats = nlohmann::json::parse(halved.out);
    EXPECT_EQ(stats["resolution_divisor"], 2);
    EXPECT_EQ(stats["samples"].get<int>(), 20 * 15);
    EXPECT_LE(stats["ms_upscale"].get<double>(), stats["ms_total"].get<double>());  // part of the frame's time
    const std::string png = read_bytes(image);
    EXPECT_EQ(big_endian_u32(png, 16), 40u);  // IHDR width and height
    EXPECT_EQ(big_endian_u32(png, 20), 30u);
    fs::remove(image);
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--resolution-divisor", "3"}), {"3"});
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--resolution-divisor", "4"}),
                     {"resolution divisor 4 must divide the image size 40x30"});
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--depth-out",
                                         (ws.out() / "depth.png").string(), "--resolution-divisor", "2"}),
                     {"no depth image at resolution divisor 2"});
    expect_bad_input(ws, run_raster(ws, {"render", scene.string(), "-o", image, "--alpha", "--resolution-divisor", "2"}),
                     {"no alpha at resolution divisor 2"});
    expect_bad_input(ws, run_raster(ws, {"compare", scene.string(), "--resolution-divisor", "2"}),
                     {"is not compared", "raster tradeoff"});
}

TEST(Cli, invalidShadingExitsTwo) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const Result result =
        run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "img.png").string(), "--shading", "toon"});
    expect_bad_input(ws, result, {"toon"});
}

TEST(Cli, unwritableOutputExitsThreeAndLeavesNothing) {
    Workspace ws;
    const fs::path scene = ws.write_scene("scene.yaml", kScene);
    const fs::path missing_dir = ws.out() / "no_such_dir";
    const Result result = run_raster(ws, {"render", scene.string(), "-o", (missing_dir / "img.png").string()});
    EXPECT_EQ(result.status, 3) << result.err;
    EXPECT_TRUE(contains(result.err, (missing_dir / "img.png").string()));
    EXPECT_FALSE(fs::exists(missing_dir));
    EXPECT_TRUE(ws.out_entries().empty());

    // The target is an existing directory: the temporary file beside it must be cleaned up.
    fs::create_directories(ws.out() / "taken.png");
    const Result over_dir = run_raster(ws, {"render", scene.string(), "-o", (ws.out() / "taken.png").string()});
    EXPECT_EQ(over_dir.status, 3) << over_dir.err;
    EXPECT_EQ(ws.out_entries(), std::vector<std::string>{"taken.png"});
    EXPECT_TRUE(fs::is_directory(ws.out() / "taken.png"));
    EXPECT_TRUE(fs::is_empty(ws.out() / "taken.png"));
}

TEST(Cli, outputIsByteIdenticalForAnyThreadCount) {
    Workspace ws;
    const fs::path teapot = fs::path(RASTER_SOURCE_DIR) / "corpus/meshes/teapot.obj";
    const fs::path scene = ws.write_scene("teapot.yaml",
                                          "image: {width: 120, height: 100, background: 0.1}\n"
                                          "camera: {eye: [0, 3, 8], target: [0, 0.3, 0], fov: 35, near: 1, far: 30}\n"
                                          "render: {samples: 4}\n"
                                          "lights:\n  - {position: [5, 8, 5], intensity: 0.9}\n"
                                          "meshes:\n  - file: " +
                                              teapot.string() +
                                              "\n    material: {color: [0.8, 0.3, 0.25], specular: 0.5, exponent: 40}\n");
    const fs::path one = ws.out() / "one.png", two = ws.out() / "two.png";
    const Result first = run_raster(ws, {"render", scene.string(), "-o", one.string(), "--threads", "1", "--stats"});
    ASSERT_EQ(first.status, 0) << first.err;
    const Result second = run_raster(ws, {"render", scene.string(), "-o", two.string(), "--threads", "2"});
    ASSERT_EQ(second.status, 0) << second.err;
    // The image is not trivially empty: the teapot covers samples.
    EXPECT_GT(nlohmann::json::parse(first.out)["covered_samples"].get<int>(), 1000);
    const std::string a = read_bytes(one), b = read_bytes(two);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "--threads 1 and --threads 2 wrote different files";
}

}  // namespace
