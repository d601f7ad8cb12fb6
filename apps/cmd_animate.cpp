// `raster animate`: renders an animated scene as a numbered PNG sequence, one image per frame at a frame rate.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/command.h"
#include "apps/progress_bar.h"
#include "apps/settings_flags.h"
#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "raster/core/parallel.h"
#include "raster/frame/render_job.h"
#include "raster/scene/animation.h"
#include "raster/scene/validation.h"
#include "raster/transform/scene_pose.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxFrames = 100000;

struct AnimateFlags {
    std::string scene;
    std::string output;
    double fps = 24.0;
    std::optional<int> frames;
    std::optional<double> duration;
    SettingsFlags settings;
};

void register_animate_flags(CLI::App& app, AnimateFlags& flags) {
    CLI::App* animate = app.add_subcommand("animate", "Render an animated scene as a numbered PNG sequence.");
    animate->footer(
        "Frame i shows the scene at the animation's first key + i / FPS seconds, written to DIR/frame_NNNN.png.\n"
        "Without --frames or --duration the sequence spans the animation's keys. To make a video:\n"
        "  ffmpeg -framerate 24 -i DIR/frame_%04d.png -pix_fmt yuv420p out.mp4   (docs/animation.md)\n"
        "Example: raster animate corpus/scenes/spinning_teapot.yaml --fps 12 -o frames");
    animate->add_option("scene", flags.scene, "Animated scene file (raster YAML with keyframes, or glTF)")->required();
    animate->add_option("-o,--output", flags.output, "Folder for the frames (made when missing)")->required();
    animate->add_option("--fps", flags.fps, "Frames per second (default 24)")->check(CLI::Range(0.001, 1000.0));
    auto* frames = animate->add_option("--frames", flags.frames, "Number of frames (1..100000)")->check(CLI::Range(1, kMaxFrames));
    animate->add_option("--duration", flags.duration, "Seconds to render from the first key (default: to the last key)")
        ->check(CLI::Range(0.0, 1e6))
        ->excludes(frames);
    register_settings_flags(*animate, flags.settings);
}

int run_animate(const AnimateFlags& flags, std::ostream& out, std::ostream& err) {
    if (flags.settings.time) {
        err << "raster animate: error: --time poses one instant; animate renders the frames --fps, --frames and "
               "--duration give\n";
        return kExitBadInput;
    }
    Scene scene;
    int frame_count = 0;
    try {
        start_threads(flags.settings.threads);
        scene = load_scene_file(flags.scene, load_options(flags.settings)).scene;
        if (!scene.animation) throw InputError(scene.path, 0, 0, "the scene has no animation (docs/animation.md)");
        apply_settings_flags(flags.settings, scene);
        const SceneAnimation& animation = *scene.animation;
        const double duration = flags.duration.value_or(static_cast<double>(animation.end) - animation.start);
        // The last key's frame counts though float times put it a hair past the last whole frame.
        const double span = duration * flags.fps;
        const double frames = std::floor(span + 1e-6 * std::max(1.0, span)) + 1.0;
        if (!flags.frames && !(frames <= kMaxFrames))
            throw InputError("", 0, 0, "the animation spans " + std::to_string(duration) + " s: " + std::to_string(frames) +
                                           " frames at " + std::to_string(flags.fps) + " fps; raster animate writes at most " +
                                           std::to_string(kMaxFrames) + " (use --frames or --duration)");
        frame_count = flags.frames.value_or(static_cast<int>(frames));
    } catch (const InputError& error) {
        err << "raster animate: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    std::error_code made;
    fs::create_directories(flags.output, made);
    if (made || !fs::is_directory(flags.output)) {
        err << "raster animate: error: cannot make the folder " << flags.output << (made ? ": " + made.message() : "") << "\n";
        return kExitIoError;
    }
    const float start = scene.animation->start;
    ProgressBar progress(err, static_cast<size_t>(frame_count));
    for (int i = 0; i < frame_count; ++i) {
        const float time = start + static_cast<float>(i / flags.fps);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i);
        pose_scene(scene, time);
        RenderJob job;
        job.options.threads = flags.settings.threads;
        job.options.alpha = flags.settings.alpha;
        job.outputs.push_back({fs::path(flags.output) / name, OutputKind::colour});
        RenderedFrame rendered;
        try {
            validate_scene(scene);
            run_render_job(scene, job, RasterRenderer{}, rendered);
        } catch (const InputError& error) {
            progress.finish();
            err << "raster animate: error: frame " << i << " (t = " << time << " s): " << error.what() << "\n";
            return kExitBadInput;
        } catch (const OutputError& error) {
            progress.finish();
            err << "raster animate: error: " << error.what() << "\n";
            return kExitIoError;
        }
        progress.show(static_cast<size_t>(i + 1), name);
    }
    progress.finish();
    out << "raster animate: " << frame_count << " frames at " << flags.fps << " fps from t = " << start << " s in "
        << flags.output << "\n";
    return kExitOk;
}

}  // namespace

Command add_animate_command(CLI::App& app) {
    return flags_command<AnimateFlags>(app, "animate", register_animate_flags, run_animate);
}

}  // namespace raster::cli
