// One subcommand of `raster`: each registers its flags on the CLI11 app and hands back what to run when chosen.
#pragma once

#include <functional>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>

#include "apps/exit_codes.h"

namespace raster::cli {

// What a subcommand does once its flags are parsed; returns the process exit code (exit_codes.h).
using CommandAction = std::function<int(std::ostream& out, std::ostream& err)>;

struct Command {
    CLI::App* app;  // the subcommand, owned by the parent app
    CommandAction action;
    std::function<void()> reset;  // puts its flags back to their defaults, after each run of a reused app
};

// A subcommand whose flags live in a struct of their own: `add` registers them on `app` (adding the subcommand
// `name`), `run` runs it, and each run's flags go back to the struct's defaults afterwards.
template <typename Flags>
Command flags_command(CLI::App& app, const char* name, void (*add)(CLI::App&, Flags&),
                      int (*run)(const Flags&, std::ostream&, std::ostream&)) {
    auto flags = std::make_shared<Flags>();
    add(app, *flags);
    return {app.get_subcommand(name), [flags, run](std::ostream& out, std::ostream& err) { return run(*flags, out, err); },
            [flags] { *flags = Flags{}; }};
}

// One function per subcommand, each in apps/cmd_<name>.cpp.
Command add_render_command(CLI::App& app);
Command add_animate_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_grade_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_tradeoff_command(CLI::App& app);
Command add_balboa_command(CLI::App& app);
// `raster view`, in its own module raster_viewer (it links cpp-httplib), which only the viewer program, raster-view,
// links and registers (view_main.cpp, through run()'s extra commands).
Command add_view_command(CLI::App& app);
// `raster view` in the `raster` program (main.cpp): the same flags, checked, then the viewer program run in this
// process's place on `arguments`, main's argv (cmd_view_forward.cpp).
Command add_view_forwarding_command(CLI::App& app, std::vector<std::string> arguments);

}  // namespace raster::cli
