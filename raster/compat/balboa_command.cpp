// balboa's command line (seed 001): its single-dash flags parsed and checked, and the scene each part draws.
#include "raster/compat/balboa_command.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "raster/compat/scene_format_seed001.h"
#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"

namespace raster {

const char* const kBalboaUsage =
    "Usage:\n"
    "  raster balboa -hw 2_1 -p0 X Y Z -p1 X Y Z -p2 X Y Z -color R G B [-s S] [-znear Z] [-o OUT.png]\n"
    "  raster balboa -hw 2_2|2_3|2_4 SCENE.json [-s S] [-znear Z] [-o OUT.png]\n"
    "\n"
    "balboa's command line for seed 001 (UCSD CSE 167 homework 2). Each flag is one dash and its values.\n"
    "  -hw PART            2_1: one triangle in camera space. 2_2, 2_3, 2_4: a JSON scene (section 4's format).\n"
    "                      raster has none of balboa's built-in scenes, so 2_2 and 2_3 take a scene file instead\n"
    "                      of -scene_id; face_colors give constant-colour triangles (2.2), vertex_colors are\n"
    "                      interpolated with perspective correction (2.3).\n"
    "  -p0, -p1, -p2 X Y Z the triangle's vertices in camera space (2_1, required)\n"
    "  -color R G B        the triangle's colour, 0..1 (2_1, required)\n"
    "  -s S                half the image plane's height at z = -1 (default 1; overrides a scene's s)\n"
    "  -znear Z            near clipping distance (default 1e-6; overrides a scene's z_near); triangles that\n"
    "                      cross it are clipped, not rejected\n"
    "  -o FILE             output image, .png or .ppm (default hw_2_1.png, or hw_PART_SCENENAME.png)\n"
    "  -h, --help          this text\n"
    "Images: 640 x 480 for 2_1 (balboa's starter code), the scene's resolution otherwise; 4x4 supersampling;\n"
    "background grey 0.5 (byte 128).\n";

namespace {

struct BalboaArgs {
    bool help = false;
    std::string part;  // 2_1, 2_2, 2_3 or 2_4
    std::optional<float> s, z_near;
    std::optional<glm::vec3> vertex[3], color;
    std::string scene;
    std::string output;
};

[[noreturn]] void usage_error(const std::string& message) {
    throw InputError("", 0, 0, message + " (see 'raster balboa --help')");
}

float parse_number(const std::string& flag, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) usage_error(flag + ": '" + text + "' is not a number");
    if (!std::isfinite(value) || std::fabs(value) > 3.0e38) usage_error(flag + ": " + text + " is not a finite float");
    return static_cast<float>(value);
}

// The `count` values after args[at], which is the flag.
std::vector<float> flag_values(const std::vector<std::string>& args, size_t at, size_t count, const char* names) {
    const std::string& flag = args[at];
    std::vector<float> values;
    for (size_t i = 1; i <= count; ++i) {
        // A value cannot be a flag: "-p0 1 2 -o x" is missing a number; "-1" and "-.5" are numbers.
        const bool next_is_flag = at + i < args.size() && args[at + i].size() > 1 && args[at + i][0] == '-' &&
                                  std::isalpha(static_cast<unsigned char>(args[at + i][1]));
        if (at + i >= args.size() || next_is_flag)
            usage_error(flag + " needs " + std::to_string(count) + " number" + (count > 1 ? "s " : " ") + names +
                        ", got " + std::to_string(values.size()));
        values.push_back(parse_number(flag, args[at + i]));
    }
    return values;
}

template <typename T>
void set_once(std::optional<T>& slot, const std::string& flag, const T& value) {
    if (slot) usage_error(flag + " is given twice");
    slot = value;
}

BalboaArgs parse_balboa_args(const std::vector<std::string>& args) {
    BalboaArgs parsed;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-h" || arg == "--help") {
            parsed.help = true;
        } else if (arg == "-hw") {
            if (i + 1 >= args.size()) usage_error("-hw needs a part: 2_1, 2_2, 2_3 or 2_4");
            if (!parsed.part.empty()) usage_error("-hw is given twice");
            parsed.part = args[++i];
            if (parsed.part != "2_1" && parsed.part != "2_2" && parsed.part != "2_3" && parsed.part != "2_4")
                usage_error("-hw " + parsed.part + ": raster runs homework 2's parts 2_1, 2_2, 2_3 and 2_4");
        } else if (arg == "-s" || arg == "-znear") {
            const float value = flag_values(args, i, 1, "")[0];
            set_once(arg == "-s" ? parsed.s : parsed.z_near, arg, value);
            i += 1;
        } else if (arg == "-p0" || arg == "-p1" || arg == "-p2" || arg == "-color") {
            const std::vector<float> v = flag_values(args, i, 3, arg == "-color" ? "(R G B)" : "(X Y Z)");
            set_once(arg == "-color" ? parsed.color : parsed.vertex[arg[2] - '0'], arg, glm::vec3(v[0], v[1], v[2]));
            i += 3;
        } else if (arg == "-o") {
            if (i + 1 >= args.size()) usage_error("-o needs a file name");
            if (!parsed.output.empty()) usage_error("-o is given twice");
            parsed.output = args[++i];
        } else if (arg == "-scene_id") {
            usage_error("-scene_id picks a scene built into balboa's starter code, which raster does not have; "
                        "write the scene as JSON and pass the file: raster balboa -hw 2_2 SCENE.json");
        } else if (!arg.empty() && arg[0] == '-') {
            usage_error("unknown flag '" + arg + "'");
        } else {
            if (!parsed.scene.empty()) usage_error("unexpected argument '" + arg + "' (the scene is '" + parsed.scene + "')");
            parsed.scene = arg;
        }
    }
    if (parsed.help) return parsed;
    if (parsed.part.empty()) usage_error("missing -hw PART (2_1, 2_2, 2_3 or 2_4)");
    if (parsed.part == "2_1") {
        if (!parsed.scene.empty()) usage_error("-hw 2_1 takes no scene file, got '" + parsed.scene + "'");
        const char* names[] = {"-p0", "-p1", "-p2"};
        for (int k = 0; k < 3; ++k)
            if (!parsed.vertex[k]) usage_error(std::string("-hw 2_1 needs ") + names[k] + " X Y Z");
        if (!parsed.color) usage_error("-hw 2_1 needs -color R G B");
    } else {
        if (parsed.scene.empty()) usage_error("-hw " + parsed.part + " needs a scene file (JSON)");
        if (parsed.vertex[0] || parsed.vertex[1] || parsed.vertex[2] || parsed.color)
            usage_error("-p0, -p1, -p2 and -color are for -hw 2_1 only");
    }
    const std::string problem = seed001_camera_problem(parsed.s.value_or(kSeed001DefaultS),
                                                      parsed.z_near.value_or(kSeed001DefaultZNear));
    if (!problem.empty()) usage_error(problem);
    return parsed;
}

// The scene parts' file, with -s and -znear overriding the scene's own values.
Scene seed001_file_scene(const BalboaArgs& args) {
    SceneFormat format = SceneFormat::raster;
    Scene scene = load_scene(args.scene, &format);
    if (format != SceneFormat::seed001)
        throw InputError(args.scene, 0, 0, "not a balboa scene (expected top-level 'camera' and 'objects')");
    if (args.s || args.z_near) {
        const float scene_s = float(std::tan(double(scene.camera.fov_y_degrees) * (M_PI / 360.0)));
        set_seed001_camera(args.s.value_or(scene_s), args.z_near.value_or(scene.camera.near), scene);
    }
    return scene;
}

std::filesystem::path default_output(const BalboaArgs& args) {
    if (args.scene.empty()) return "hw_" + args.part + ".png";
    return "hw_" + args.part + "_" + std::filesystem::path(args.scene).stem().string() + ".png";
}

}  // namespace

BalboaRun balboa_run(const std::vector<std::string>& raw) {
    BalboaRun run;
    const BalboaArgs args = parse_balboa_args(raw);
    if (args.help) {
        run.help = true;
        return run;
    }
    if (args.part == "2_1") {
        Seed001Triangle triangle;
        for (int k = 0; k < 3; ++k) triangle.vertices[k] = *args.vertex[k];
        triangle.color = *args.color;
        triangle.s = args.s.value_or(kSeed001DefaultS);
        triangle.z_near = args.z_near.value_or(kSeed001DefaultZNear);
        run.scene = seed001_triangle_scene(triangle);
    } else {
        run.scene = seed001_file_scene(args);
    }
    run.output = args.output.empty() ? default_output(args) : std::filesystem::path(args.output);
    return run;
}

}  // namespace raster
