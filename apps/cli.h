// The `raster` command line: subcommands, flags, messages and exit codes (testable without a process).
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "apps/exit_codes.h"

namespace CLI {
class App;
}

namespace raster::cli {

struct Command;

// Registers one subcommand beyond raster_cli's own (apps/command.h): the `raster` program adds `view`, which lives
// in its own module so that nothing else linking raster_cli (the cli fuzz target, in-process tests) links a server.
using CommandRegistrar = std::function<Command(CLI::App&)>;

// Runs `raster` with argv-style arguments (args[0] is the program name), writing to out and err.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        const std::vector<CommandRegistrar>& extra_commands = {});

// The same command line built once and run many times (the cli fuzz target runs thousands of argument lists a
// second, and registering every subcommand's flags costs more than most runs): each run starts from every flag's
// default, so it behaves exactly as run() on the same arguments.
class CommandLine {
public:
    explicit CommandLine(const std::vector<CommandRegistrar>& extra_commands = {});
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

private:
    struct Parser;
    int run_once(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

    std::unique_ptr<Parser> parser_;
};

}  // namespace raster::cli
