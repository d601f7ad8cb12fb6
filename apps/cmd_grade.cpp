// `raster grade`: judges an image any rasterizer wrote against the oracle, under the precision the rasterizer
// promises (its samples, their pattern, MSAA, sub-pixel bits, colour precision), and says which pixels fail and how.
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/settings_flags.h"
#include "harness/comparison/decoded_image.h"
#include "harness/comparison/scene_comparison.h"
#include "harness/grading/image_grade.h"
#include "oracle/reference/embree_device.h"
#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/compat/scene_loader.h"
#include "raster/image/image.h"

namespace raster::cli {
namespace {

struct GradeFlags {
    std::string scene;
    std::string image;
    SettingsFlags settings;
    int colour_levels = 0;
    uint64_t budget = 0;
    std::string json_out;
    std::string mask_out;
    bool fast_oracle = false;
};

void register_grade_flags(CLI::App& app, GradeFlags& flags) {
    CLI::App* grade = app.add_subcommand(
        "grade", "Judge an image written by any rasterizer (PNG or PPM) against the independent Embree oracle.");
    grade->footer(
        "The settings flags say what the rasterizer promises: --samples and --pattern its sample positions, --msaa\n"
        "its shading rate, --snap-bits its sub-pixel bits (8 by default), --shading and the rest how it shades; the\n"
        "scene file's own settings apply where a flag is left out. The oracle casts a ray at every sample and decides\n"
        "each sample, or leaves it open where a correct rasterizer with those promises may draw another triangle\n"
        "(an edge within its band, a depth tie, a clip plane, an uncertain facing). A pixel whose samples are all\n"
        "decided must lie in the colour interval the oracle derives (widened by --colour-levels); one outside it is\n"
        "missing (the background where the scene is covered), unexpected (drawn where the scene is empty) or a wrong\n"
        "colour. Open pixels are counted, not judged.\n"
        "Exit code 0 when at most --budget pixels fail, 1 when more do, 2 on bad input, 3 when an output cannot be\n"
        "written or Embree fails.\n"
        "Example: raster render corpus/scenes/teapot.yaml -o teapot.png && raster grade corpus/scenes/teapot.yaml "
        "teapot.png --mask errors.png");
    grade->add_option("scene", flags.scene, "Scene file the image is of")->required();
    grade->add_option("image", flags.image, "The image to judge: PNG or PPM, the scene's size")->required();
    register_settings_flags(*grade, flags.settings);
    grade->add_option("--colour-levels", flags.colour_levels,
                      "Levels a channel may be off past the derived interval (the rasterizer's colour precision)")
        ->check(CLI::Range(0, 255));
    grade->add_option("--budget", flags.budget, "Failing pixels tolerated (a weak mode); 0, the default, is strict");
    grade->add_option("--json", flags.json_out, "Write the counts per pixel class and per sample class as JSON here");
    grade->add_option("--mask", flags.mask_out,
                      "Write the error mask: black passes, grey open, blue missing, yellow unexpected, red wrong colour");
    add_fast_oracle_flag(*grade, flags.fast_oracle);
}

int run_grade(const GradeFlags& flags, std::ostream& out, std::ostream& err) {
    SceneFile file;
    Scene& scene = file.scene;
    Image image;
    try {
        file = load_scene_with_flags(flags.scene, flags.settings);
        if (file.request.self_check)
            throw InputError(flags.scene, 0, 0,
                             "this file asks for a check of its own, not an image: there is nothing to grade");
        if (scene.settings.resolution_divisor > 1)
            throw InputError(flags.scene, 0, 0,
                             "--resolution-divisor is how raster renders; an image is graded at its own size, so "
                             "leave it out");
        if (std::string problem = harness::comparison_problem(scene); !problem.empty())
            throw InputError(flags.scene, 0, 0, problem);
        image = harness::read_image_file(flags.image, 3);
        if (image.width != scene.settings.width || image.height != scene.settings.height)
            throw InputError(flags.image, 0, 0, "the image is " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + ", the scene " + flags.scene + " renders " +
                             std::to_string(scene.settings.width) + " x " + std::to_string(scene.settings.height));
    } catch (const InputError& error) {
        err << "raster grade: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    harness::GradeOptions options;
    options.mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.settings.threads;
    options.colour_levels = flags.colour_levels;
    options.budget = flags.budget;
    std::unique_ptr<harness::ImageGrade> grade;
    try {
        grade = std::make_unique<harness::ImageGrade>(harness::grade_image(scene, image, options));
    } catch (const std::exception& error) {  // Embree failing, or memory
        err << "raster grade: error: " << error.what() << "\n";
        return kExitIoError;
    }
    try {
        if (!flags.json_out.empty()) write_file_atomically(flags.json_out, harness::grade_json(*grade).dump(2) + "\n");
        if (!flags.mask_out.empty()) write_image(flags.mask_out, harness::grade_mask(*grade), options.threads);
    } catch (const std::exception& error) {
        err << "raster grade: error: " << error.what() << "\n";
        return kExitIoError;
    }
    using harness::PixelGrade;
    out << (grade->pass() ? "PASS" : "FAIL") << ": " << flags.image << " against " << flags.scene << " ("
        << grade->width << " x " << grade->height << ", " << grade->samples
        << (grade->samples == 1 ? " sample" : " samples") << " per pixel)\n"
        << "  pixels: pass " << grade->count(PixelGrade::pass) << ", open " << grade->count(PixelGrade::open)
        << ", missing " << grade->count(PixelGrade::missing) << ", unexpected " << grade->count(PixelGrade::unexpected)
        << ", wrong colour " << grade->count(PixelGrade::wrong_colour) << " (failing " << grade->failing()
        << ", budget " << grade->budget << ")\n"
        << "  samples: decided " << grade->sample_counts.count(oracle::SampleClass::agree) << ", open "
        << grade->sample_counts.ambiguous_total() << "; widest colour interval " << grade->widest_interval
        << " levels; oracle " << static_cast<int>(grade->oracle_ms) << " ms, grading "
        << static_cast<int>(grade->grade_ms) << " ms\n";
    return grade->pass() ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command add_grade_command(CLI::App& app) {
    return flags_command<GradeFlags>(app, "grade", register_grade_flags, run_grade);
}

}  // namespace raster::cli
