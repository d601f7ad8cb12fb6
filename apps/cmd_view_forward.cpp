// `raster view` in the `raster` program: checks the flags, then runs the viewer program (raster-view, beside it) on
// the same command line in this process's place. The server's libraries (cpp-httplib, with OpenSSL and Brotli)
// are linked only into that program: loaded by `raster` they cost every other subcommand ~5 ms at start-up.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "apps/command.h"
#include "apps/view_flags.h"

namespace raster::cli {
namespace {

// Runs the viewer program on `arguments` (exactly what `raster` was given, so that it parses the same line).
int run_viewer_program(std::vector<std::string> arguments, std::ostream& out, std::ostream& err) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::filesystem::path viewer = self.parent_path() / kViewerProgram;
    out.flush();
    err.flush();
    if (!error && !arguments.empty()) {
        std::vector<char*> argv;
        for (std::string& argument : arguments) argv.push_back(argument.data());
        argv.push_back(nullptr);
        execv(viewer.c_str(), argv.data());  // returns only on failure
    }
    const std::string why = error                ? "cannot find this program's folder: " + error.message()
                            : arguments.empty() ? std::string("no program name to run it under")
                                                : std::string(std::strerror(errno));
    err << "raster view: error: cannot run the viewer program " << viewer.string() << ": " << why
        << " (it is built beside raster unless RASTER_BUILD_VIEWER is OFF)\n";
    return kExitBadInput;
}

}  // namespace

Command add_view_forwarding_command(CLI::App& app, std::vector<std::string> arguments) {
    auto flags = std::make_shared<ViewFlags>();
    register_view_flags(app, *flags);
    return {app.get_subcommand("view"),
            [arguments = std::move(arguments)](std::ostream& out, std::ostream& err) {
                return run_viewer_program(arguments, out, err);
            },
            [flags] { *flags = ViewFlags{}; }};
}

}  // namespace raster::cli
