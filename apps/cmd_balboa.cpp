// `raster balboa`: seed 001's own command lines (raster/compat/balboa_command.h), rendered and written as
// `raster render` writes a frame.
#include <memory>
#include <string>
#include <vector>

#include "apps/command.h"
#include "raster/compat/balboa_command.h"
#include "raster/core/errors.h"
#include "raster/frame/render_job.h"

namespace raster::cli {
namespace {

int run_balboa(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
    BalboaRun run;
    try {
        run = balboa_run(raw);
    } catch (const InputError& error) {
        err << "raster balboa: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    if (run.help) {
        out << kBalboaUsage;
        return kExitOk;
    }
    RenderJob job;
    job.outputs.push_back({run.output, OutputKind::colour});
    RenderedFrame rendered;
    try {
        run_render_job(run.scene, job, RasterRenderer{}, rendered);
    } catch (const OutputError& error) {
        err << "raster balboa: error: " << error.what() << "\n";
        return kExitIoError;
    }
    return kExitOk;
}

}  // namespace
Command add_balboa_command(CLI::App& app) {
    CLI::App* balboa = app.add_subcommand("balboa", "Run balboa's homework 2 command lines (seed 001): -hw 2_1 ... or "
                                                    "-hw 2_4 SCENE.json; 'raster balboa --help' for its flags.");
    // balboa's flags are single-dash words with several values each (-hw, -p0 X Y Z): CLI11 hands them over raw.
    balboa->prefix_command();
    balboa->allow_extras();
    balboa->set_help_flag();
    // No flags of its own to reset: what it runs is the parse's remaining arguments.
    return {balboa,
            [balboa](std::ostream& out, std::ostream& err) { return run_balboa(balboa->remaining(), out, err); },
            [] {}};
}

}  // namespace raster::cli
