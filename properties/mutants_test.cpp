// The mutants run: every property against every faulty variant of the bug catalogue (and, as a control, against
// the real rasterizer), each implementation in its own child process, two at a time, so that a crash counts as a
// catch instead of ending the run. Prints the bug x check table and fails unless every bug is caught, every
// property catches at least one bug, and the real rasterizer passes every property.
//
// With the oracle built (RASTER_HAVE_ORACLE), every oracle comparison of a corpus scene is a check too.
//
// Knobs (environment): RASTER_MUTANT_CASES, cases per property and implementation (default 40); RASTER_MUTANT_SEED
// (default 1); RASTER_MUTANT_JOBS, child processes at a time (default 2).
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "properties/property_registry.h"
#include "mutants/catalogue.h"
#ifdef RASTER_HAVE_ORACLE
#include "properties/mutants_oracle_checks.h"
#endif

namespace raster::properties {
namespace {

int env_int(const char* name, int fallback) {
    const char* text = std::getenv(name);
    return text && *text ? std::atoi(text) : fallback;
}

// One property against one implementation: up to `cases` cases from a fixed seed, no shrinking (only whether it
// fails matters here; the properties' own runs shrink). Returns "" when it passed, else the first line of why.
std::string run(const Property& property, const Implementation& impl, int cases, uint64_t seed) {
    rc::detail::TestParams params;
    params.seed = seed;
    params.maxSuccess = cases;
    params.maxSize = 100;
    params.disableShrinking = true;
    rc::detail::TestMetadata metadata;
    metadata.id = property.suite + "." + property.name + " / " + impl.name;
    metadata.description = metadata.id;
    const rc::detail::TestResult result =
        rc::detail::checkProperty(rc::detail::toProperty([&] { property.check(impl); }), metadata, params);
    // The description is "file:line:", the macro, then the message (fail_case) or the expansion (RC_ASSERT):
    // keep the first line that is neither.
    auto first_line = [](const std::string& s) {
        std::istringstream lines(s);
        std::string line, fallback;
        while (std::getline(lines, line)) {
            if (line.empty() || line.find("RC_FAIL(") == 0) continue;
            if (line.back() == ':' && line.find(".cpp:") != std::string::npos) continue;
            return line;
        }
        return std::string("failed");
    };
    rc::detail::FailureResult failure;
    if (result.match(failure)) return first_line(failure.description);
    rc::detail::GaveUpResult gave_up;
    if (result.match(gave_up)) return "";  // too many discarded cases is not a catch
    rc::detail::Error error;
    if (result.match(error)) return "";    // nor is an error of the testing process
    return "";
}

// A check of an implementation: a property, or an oracle comparison. Returns "" when it passed, else why not.
struct Check {
    std::string name;
    bool is_property;
    std::function<std::string(const Implementation&)> run;
};

std::vector<Check> all_checks(int cases, uint64_t seed) {
    std::vector<Check> checks;
    for (const Property& p : all_properties())
        checks.push_back({p.suite + "." + p.name, true, [p, cases, seed](const Implementation& impl) { return run(p, impl, cases, seed); }});
#ifdef RASTER_HAVE_ORACLE
    for (const std::string& name : oracle_checks())
        checks.push_back({name, false, [name](const Implementation& impl) { return run_oracle_check(name, impl); }});
#endif
    return checks;
}

// The outcome of one implementation: for each check, whether it failed and how.
struct Outcome {
    std::vector<std::string> caught;  // per check: "" = passed
    bool finished = false;
};

// Runs every check against `impl` in this (child) process, writing "index<TAB>why" lines (why empty when passed)
// to `fd` as it goes, and "index<TAB>>" before starting one, so the parent knows which check was running if the
// child dies.
void run_all(const std::vector<Check>& checks, const Implementation& impl, int fd) {
    for (size_t i = 0; i < checks.size(); ++i) {
        const std::string start = std::to_string(i) + "\t>\n";
        if (write(fd, start.data(), start.size()) < 0) _exit(3);
        std::string why;
        try {
            why = checks[i].run(impl);
        } catch (const std::exception& e) {
            why = std::string("threw: ") + e.what();
        }
        for (char& c : why)
            if (c == '\n' || c == '\t') c = ' ';
        const std::string line = std::to_string(i) + "\t" + why + "\n";
        if (write(fd, line.data(), line.size()) < 0) _exit(3);
    }
}

struct Child {
    size_t implementation;
    pid_t pid;
    int fd;
    std::string buffer;
    int running = -1;  // the property in progress
};

void parse_lines(Child& child, Outcome& outcome) {
    size_t end;
    while ((end = child.buffer.find('\n')) != std::string::npos) {
        const std::string line = child.buffer.substr(0, end);
        child.buffer.erase(0, end + 1);
        const size_t tab = line.find('\t');
        const int index = std::atoi(line.substr(0, tab).c_str());
        const std::string why = line.substr(tab + 1);
        if (why == ">") {
            child.running = index;
        } else {
            outcome.caught[static_cast<size_t>(index)] = why;
            child.running = -1;
        }
    }
}

// Runs every implementation, `jobs` child processes at a time.
std::vector<Outcome> run_everything(const std::vector<Check>& checks, const std::vector<Implementation>& implementations,
                                    int jobs) {
    std::vector<Outcome> outcomes(implementations.size());
    for (Outcome& o : outcomes) o.caught.assign(checks.size(), "");
    std::vector<Child> running;
    size_t next = 0;
    std::cout.flush();
    while (next < implementations.size() || !running.empty()) {
        while (next < implementations.size() && static_cast<int>(running.size()) < jobs) {
            int fds[2];
            if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
            const pid_t pid = fork();
            if (pid == 0) {
                close(fds[0]);
                run_all(checks, implementations[next], fds[1]);
                close(fds[1]);
                _exit(0);
            }
            close(fds[1]);
            running.push_back({next, pid, fds[0], "", -1});
            ++next;
        }
        std::vector<pollfd> polls;
        for (const Child& c : running) polls.push_back({c.fd, POLLIN, 0});
        if (poll(polls.data(), polls.size(), -1) < 0 && errno != EINTR) throw std::runtime_error("poll failed");
        for (size_t k = 0; k < running.size();) {
            Child& child = running[k];
            char data[4096];
            const ssize_t n = (polls[k].revents & (POLLIN | POLLHUP)) ? read(child.fd, data, sizeof data) : -2;
            if (n > 0) {
                child.buffer.append(data, static_cast<size_t>(n));
                parse_lines(child, outcomes[child.implementation]);
                ++k;
                continue;
            }
            if (n == -2 || (n < 0 && errno == EINTR)) {
                ++k;
                continue;
            }
            // End of output: the child has finished or died.
            close(child.fd);
            int status = 0;
            waitpid(child.pid, &status, 0);
            Outcome& outcome = outcomes[child.implementation];
            const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
            if (!clean && child.running >= 0) {
                const std::string how = WIFSIGNALED(status) ? "crashed with signal " + std::to_string(WTERMSIG(status))
                                                            : "exited with status " + std::to_string(WEXITSTATUS(status));
                outcome.caught[static_cast<size_t>(child.running)] = how;
            }
            outcome.finished = clean;
            // Properties after a crash did not run: count them as not catching (the crash already caught it).
            polls.erase(polls.begin() + static_cast<long>(k));
            running.erase(running.begin() + static_cast<long>(k));
        }
    }
    return outcomes;
}

TEST(Mutants, everyBugIsCaughtAndEveryPropertyCatchesABug) {
    const int cases = env_int("RASTER_MUTANT_CASES", 40);
    const uint64_t seed = static_cast<uint64_t>(env_int("RASTER_MUTANT_SEED", 1));
    const int jobs = std::max(1, env_int("RASTER_MUTANT_JOBS", 2));
    const std::vector<mutants::Mutant>& bugs = mutants::catalogue();
    rc::detail::configuration();  // load RapidCheck's configuration once, here, rather than in every child
    const std::vector<Check> checks = all_checks(cases, seed);

    std::vector<Implementation> implementations;
    implementations.push_back(real_implementation());
    for (const mutants::Mutant& m : bugs) implementations.push_back(implementation_of(m));
    const std::vector<Outcome> outcomes = run_everything(checks, implementations, jobs);

    size_t property_count = 0;
    for (const Check& c : checks) property_count += c.is_property;
    std::cout << "\nMutants run: " << bugs.size() << " bugs x " << checks.size() << " checks (" << property_count
              << " properties, up to " << cases << " cases each, seed " << seed << "; " << checks.size() - property_count
              << " oracle comparisons" << (checks.size() == property_count ? ": the oracle is not built" : "") << ")\n\n";
    std::vector<int> catches(checks.size(), 0);
    size_t width = 0;
    for (const mutants::Mutant& m : bugs) width = std::max(width, m.name.size());
    for (size_t b = 0; b < bugs.size(); ++b) {
        const Outcome& outcome = outcomes[b + 1];
        std::vector<std::string> by;
        for (size_t k = 0; k < checks.size(); ++k)
            if (!outcome.caught[k].empty()) {
                by.push_back(checks[k].name);
                ++catches[k];
            }
        std::ostringstream line;
        line << std::left << std::setw(static_cast<int>(width)) << bugs[b].name << "  " << std::setw(22) << bugs[b].stage
             << (by.empty() ? "NOT caught" : "caught    ") << "  ";
        if (!by.empty()) line << by.size() << ": ";
        for (size_t k = 0; k < by.size(); ++k) line << (k ? ", " : "") << by[k];
        std::cout << line.str() << "\n";
        EXPECT_FALSE(by.empty()) << "bug \"" << bugs[b].name << "\" (" << bugs[b].symptom << ") is caught by no check";
    }

    std::cout << "\nBy check (bugs caught; how the first one was caught):\n";
    for (size_t k = 0; k < checks.size(); ++k) {
        std::string example;
        for (size_t b = 0; b < bugs.size() && example.empty(); ++b)
            if (!outcomes[b + 1].caught[k].empty()) example = bugs[b].name + ": " + outcomes[b + 1].caught[k];
        std::cout << "  " << std::setw(2) << catches[k] << "  " << checks[k].name
                  << (catches[k] == 0 ? (checks[k].is_property ? "  CATCHES NOTHING" : "  (catches nothing)") : "") << "\n";
        if (!example.empty()) std::cout << "        e.g. " << example.substr(0, 200) << "\n";
        if (checks[k].is_property) {
            EXPECT_GT(catches[k], 0) << checks[k].name << " catches none of the bugs";
        }
    }

    const Outcome& real = outcomes[0];
    for (size_t k = 0; k < checks.size(); ++k)
        EXPECT_TRUE(real.caught[k].empty()) << "the real rasterizer fails " << checks[k].name << ": " << real.caught[k];
    EXPECT_TRUE(real.finished) << "the control run against the real rasterizer did not finish";
    std::cout << "\nControl: the real rasterizer " << (real.finished ? "passed" : "did not finish") << " every check"
              << (real.finished ? "" : " (see above)") << ".\n";
}

}  // namespace
}  // namespace raster::properties
