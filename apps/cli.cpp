// The `raster` command line: parses flags with CLI11, runs the subcommand, maps failures to exit codes.
#include "apps/cli.h"

#include <vector>

#include <CLI/CLI.hpp>

#include "apps/command.h"
#include "raster/core/errors.h"

namespace raster::cli {
namespace {

constexpr const char* kDescription =
    "raster: a CPU triangle rasterizer with a verification framework around it.\n"
    "Exit codes: 0 success, 1 a check failed, 2 bad usage or input (nothing written), 3 an output could not be written.";

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    CLI::App app(kDescription, "raster");
    app.require_subcommand(1);
    const std::vector<Command> commands = {
        add_render_command(app),
        add_compare_command(app),
        add_report_command(app),
        add_tradeoff_command(app),
        add_balboa_command(app),
    };

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    if (!reversed.empty()) reversed.pop_back();  // program name
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        // `raster render --help` prints the subcommand's help; `raster --help` lists every subcommand's flags too.
        out << app.help("", app.get_subcommands().empty() ? CLI::AppFormatMode::All : CLI::AppFormatMode::Normal);
        return kExitOk;
    } catch (const CLI::CallForAllHelp&) {
        out << app.help("", CLI::AppFormatMode::All);
        return kExitOk;
    } catch (const CLI::ParseError& error) {
        // Subcommand help arrives here as CallForHelp thrown from the subcommand.
        err << "raster: error: " << error.what() << "\nRun 'raster --help' for usage.\n";
        return kExitBadInput;
    }
    try {
        for (const Command& command : commands)
            if (command.app->parsed()) return command.action(out, err);
    } catch (const InputError& error) {
        err << "raster: error: " << error.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& error) {
        err << "raster: internal error: " << error.what() << "\n";
        return kExitIoError;
    }
    return kExitBadInput;
}

}  // namespace raster::cli
