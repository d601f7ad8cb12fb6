// The `raster` command line: parses flags with CLI11, runs the subcommand, maps failures to exit codes.
#include "apps/cli.h"

#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/command.h"
#include "raster/core/errors.h"
#include "raster/simd/simd_targets.h"

namespace raster::cli {
namespace {

constexpr const char* kDescription =
    "raster: a CPU triangle rasterizer with a verification framework around it.\n"
    "Exit codes: 0 success, 1 a check failed (view: the port could not be bound), 2 bad usage or input (nothing\n"
    "written), 3 an output could not be written.";

// `raster --version`: the version, and the SIMD target the kernels dispatch to on this CPU (the best of those this
// build compiles that the CPU runs; only a test pins another, through force_simd_target).
std::string version_text() {
    const std::vector<int64_t> targets = simd_targets();
    std::string text = std::string("raster ") + RASTER_VERSION + "\nSIMD target: " + simd_target_name(targets.front()) +
                       " (this CPU runs:";
    for (const int64_t target : targets) text += " " + simd_target_name(target);
    return text + ")";
}

}  // namespace

struct CommandLine::Parser {
    CLI::App app{kDescription, "raster"};
    std::vector<Command> commands;

    explicit Parser(const std::vector<CommandRegistrar>& extra_commands) {
        app.require_subcommand(1);
        app.set_version_flag("--version", version_text,
                             "Print raster's version and the SIMD target its kernels run on here, and exit");
        commands = {
            add_render_command(app),
            add_animate_command(app),
            add_compare_command(app),
            add_grade_command(app),
            add_report_command(app),
            add_tradeoff_command(app),
            add_balboa_command(app),
        };
        for (const CommandRegistrar& add_command : extra_commands) commands.push_back(add_command(app));
    }
};

CommandLine::CommandLine(const std::vector<CommandRegistrar>& extra_commands)
    : parser_(std::make_unique<Parser>(extra_commands)) {}
CommandLine::~CommandLine() = default;

int CommandLine::run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    // Each run leaves the parser as it found it, however it ends: CLI11 keeps what a parse saw (clear() frees it)
    // and the bound variables as the parse set them (reset() restores every default). So the next run starts from
    // the defaults, and a run frees what it allocated (a fuzzer counts that: a run that frees its predecessor's
    // memory looks like one that leaks, and is run again under the leak checker).
    struct Restore {
        Parser& parser;
        ~Restore() {
            parser.app.clear();
            for (const Command& command : parser.commands) command.reset();
        }
    } restore{*parser_};
    return run_once(args, out, err);
}

int CommandLine::run_once(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    CLI::App& app = parser_->app;
    const std::vector<Command>& commands = parser_->commands;

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    if (!reversed.empty()) reversed.pop_back();  // program name
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        // `raster render --help` prints the subcommand's help; `raster --help` lists every subcommand's flags too.
        out << app.help("", app.get_subcommands().empty() ? CLI::AppFormatMode::All : CLI::AppFormatMode::Normal);
        return kExitOk;
    } catch (const CLI::CallForVersion& version) {
        out << version.what() << "\n";
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

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        const std::vector<CommandRegistrar>& extra_commands) {
    CommandLine command_line(extra_commands);
    return command_line.run(args, out, err);
}

}  // namespace raster::cli
