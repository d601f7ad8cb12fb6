// `raster view` in the `raster` program: checks the flags, then runs the viewer program (raster-view, beside it) on
// the same command line in this process's place. The server's libraries (cpp-httplib, with OpenSSL and Brotli)
// are linked only into that program: loaded by `raster` they cost every other subcommand ~5 ms at start-up.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "apps/command.h"
#include "apps/view_flags.h"

namespace raster::cli {
namespace {

// This process's own arguments, as the kernel keeps them (NUL-separated), so that the viewer program parses
// exactly what `raster` was given.
std::vector<std::string> own_arguments() {
    std::ifstream file("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::vector<std::string> arguments;
    for (size_t start = 0; start < all.size();) {
        const size_t end = all.find('\0', start);
        arguments.push_back(all.substr(start, end == std::string::npos ? std::string::npos : end - start));
        start = end == std::string::npos ? all.size() : end + 1;
    }
    return arguments;
}

int run_viewer_program(std::ostream& out, std::ostream& err) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::filesystem::path viewer = self.parent_path() / kViewerProgram;
    std::vector<std::string> arguments = own_arguments();
    out.flush();
    err.flush();
    if (!error && !arguments.empty()) {
        std::vector<char*> argv;
        for (std::string& argument : arguments) argv.push_back(argument.data());
        argv.push_back(nullptr);
        execv(viewer.c_str(), argv.data());  // returns only on failure
    }
    const std::string why = error                ? "cannot find this program's folder: " + error.message()
                            : arguments.empty() ? std::string("cannot read /proc/self/cmdline")
                                                : std::string(std::strerror(errno));
    err << "raster view: error: cannot run the viewer program " << viewer.string() << ": " << why
        << " (it is built beside raster unless RASTER_BUILD_VIEWER is OFF)\n";
    return kExitBadInput;
}

}  // namespace

Command add_view_forwarding_command(CLI::App& app) {
    auto flags = std::make_shared<ViewFlags>();
    register_view_flags(app, *flags);
    return {app.get_subcommand("view"), [](std::ostream& out, std::ostream& err) { return run_viewer_program(out, err); },
            [flags] { *flags = ViewFlags{}; }};
}

}  // namespace raster::cli
