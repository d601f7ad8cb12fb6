// Fuzz target: the `raster` command line (raster::cli::CommandLine, built once, each run as a fresh `raster`) with
// fuzzed arguments, run inside a sandbox folder.
//
// The input is the argument list, separated by NUL bytes. Arguments containing '/' are refused, so every file the
// command reads or writes is a bare name in the sandbox (and so are newlines, so that no argument echoed in a
// message can fake the start of a line). The sandbox holds tiny scenes (8 x 8 pixels at most, one per format),
// and argument lists with a "2_1" are skipped: `raster balboa -hw 2_1` always renders 640 x 480 x 16 samples,
// seconds under the sanitizers. So no input makes the command render a large image. A `report` or `tradeoff` that
// would take more than one scene (a folder counts as all the scenes in it) is skipped too, and so is a `tradeoff`
// with --runs or --reference-grid: each scene of a report is a whole comparison and a page of images, and reports
// of the whole sandbox, 20 ms or more each, took most of the target's time (under 600 inputs a second); a tradeoff
// renders every mode --runs times, 2 s at --runs 100 for one tiny scene, past the 1 s hang limit. Their one-scene,
// default forms keep every path of both commands. The sandbox is restored after every input, so outputs of one
// input never change what the next one sees.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "apps/cli.h"
#include "fuzz/sandbox.h"

namespace {

constexpr size_t kMaxArguments = 32;
// The sandbox's scenes, each of which `report` and `tradeoff` take when named.
constexpr std::string_view kSceneFixtures[] = {"s.yaml", "s.json", "b.json", "c.yaml"};

raster::fuzz::Sandbox& cli_sandbox() {
    static raster::fuzz::Sandbox sandbox("cli", {
        {"s.yaml",
         "image: {width: 8, height: 8}\nrender: {samples: 4, shading: phong}\nlights: [{position: [1, 1, 4]}]\n"
         "meshes:\n  - vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n"
         "  - file: q.ply\n    transform: [{translate: [0, 0, -1]}]\n"},
        {"s.json",
         "{\"eye\": [0, 0, 3], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"fov_angle\": 45, \"width\": 8, "
         "\"height\": 6, \"near\": -0.1, \"far\": -100, \"lights\": [{\"position\": [1, 1, 3], \"color\": [1, 1, 1]}], "
         "\"meshes\": [{\"obj\": \"t.obj\", \"ambient\": [0.1, 0.1, 0.1], \"diffuse\": [0.5, 0.5, 0.5], "
         "\"specular\": [0.2, 0.2, 0.2], \"phong_exponent\": 16}]}\n"},
        {"b.json",
         "{\"camera\": {\"resolution\": [8, 6], \"s\": 1, \"z_near\": 1e-6}, \"background\": [0.5, 0.5, 0.5], "
         "\"objects\": [{\"vertices\": [-1, -1, -3, 1, -1, -3, 0, 1, -3], \"faces\": [0, 1, 2], "
         "\"vertex_colors\": [1, 0, 0, 0, 1, 0, 0, 0, 1]}, {\"filename\": \"q.ply\", "
         "\"transform\": [{\"translate\": [0, 0, -4]}]}]}\n"},
        {"c.yaml",
         "task: shading\nantialias: SSAA\nsamples: 4\nresolution: {width: 8, height: 8}\nobj: t\noutput: o\n"
         "camera: {pos: [0, 0, 3], lookAt: [0, 0, 0], up: [0, 1, 0], width: 0.2, height: 0.2, nearClip: 0.1, "
         "farClip: 100}\ntransforms: [{rotation: [1, 0, 0, 0], translation: [0, 0, 0], scale: [1, 1, 1]}]\n"
         "exponent: 4\nambient: [10, 10, 10]\nlights: [{pos: [0, 1, 2], intensity: 2, color: [255, 255, 255]}]\n"},
        {"t.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n"},
        {"q.ply",
         "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n"},
    });
    return sandbox;
}

// Splits the input at NUL bytes into arguments after the program name; false when it should not be run.
bool arguments_from(std::string_view input, std::vector<std::string>& args) {
    args = {"raster"};
    size_t start = 0;
    while (start <= input.size()) {
        size_t end = input.find('\0', start);
        if (end == std::string_view::npos) end = input.size();
        const std::string_view argument = input.substr(start, end - start);
        if (argument.find_first_of("/\n") != std::string_view::npos || argument == "2_1" || args.size() > kMaxArguments)
            return false;
        args.emplace_back(argument);
        start = end + 1;
    }
    return true;
}

// At most how many scenes a `report` or `tradeoff` with these arguments could take: each fixture scene named, and
// every scene of a folder named ("." is the sandbox, ".." its parent, whose scenes are unknown: counted as two).
size_t scenes_named(const std::vector<std::string>& args) {
    size_t scenes = 0;
    for (const std::string& argument : args) {
        if (argument == ".") scenes += std::size(kSceneFixtures);
        if (argument == "..") scenes += 2;
        for (std::string_view fixture : kSceneFixtures) scenes += argument == fixture;
    }
    return scenes;
}

// The argument lists skipped for their work (see the top of the file).
bool is_heavy(const std::vector<std::string>& args) {
    const auto has = [&](const char* word) { return std::find(args.begin(), args.end(), word) != args.end(); };
    const bool tradeoff = has("tradeoff");
    if ((tradeoff || has("report")) && scenes_named(args) > 1) return true;
    return tradeoff && std::any_of(args.begin(), args.end(), [](const std::string& argument) {
               return argument.starts_with("--runs") || argument.starts_with("--reference-grid");
           });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    raster::fuzz::Sandbox& sandbox = cli_sandbox();
    std::vector<std::string> args;
    if (!arguments_from(std::string_view(reinterpret_cast<const char*>(data), size), args) || is_heavy(args))
        return 0;
    // Registering every subcommand's flags costs more than most runs; the command line resets them for each run.
    static raster::cli::CommandLine command_line;
    std::ostringstream out, err;
    int code;
    {
        const raster::fuzz::WorkingDirectory inside(sandbox.path());
        code = command_line.run(args, out, err);
    }
    sandbox.restore();
    // run() turns exceptions other than input errors into "internal error": for these inputs that is a bug.
    const std::string errors = err.str();
    const bool internal_error = errors.starts_with("raster: internal error: ") ||
                                errors.find("\nraster: internal error: ") != std::string::npos;
    if (internal_error || code < 0 || code > 3) {
        std::fprintf(stderr, "raster cli fuzz: exit code %d, stderr:\n%s\n", code, errors.c_str());
        __builtin_trap();
    }
    return 0;
}
