// raster_mutants: the bug catalogue's tool: lists and checks mutants/bugs.txt, writes the schemata build's sources,
// and plans which ctest tests each planted bug runs (tools/plant_bugs.sh drives it).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

#include "mutants/catalogue.h"
#include "mutants/comparison_case.h"
#include "mutants/schema.h"
#include "mutants/test_selection.h"

namespace fs = std::filesystem;
using namespace raster::mutants;

namespace {

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw CatalogueError(path.string() + ": cannot read");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Writes only when the bytes change, so an unchanged file keeps its time and rebuilds nothing.
void write_if_changed(const fs::path& path, const std::string& text) {
    if (fs::exists(path) && read_file(path) == text) return;
    fs::create_directories(path.parent_path());
    const fs::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out) throw CatalogueError(temporary.string() + ": cannot write");
    }
    fs::rename(temporary, path);
}

// Each source file with its sites, in catalogue order (a site's number is its entry's index).
std::map<std::string, std::vector<Site>> sites_by_file(const Catalogue& catalogue) {
    std::map<std::string, std::vector<Site>> files;
    for (size_t i = 0; i < catalogue.entries.size(); ++i)
        files[catalogue.entries[i].file].push_back({&catalogue.entries[i], static_cast<int>(i)});
    return files;
}

// The schemata sources, path relative to the root -> text.
std::map<std::string, std::string> schemata_sources(const Catalogue& catalogue, const fs::path& root) {
    std::map<std::string, std::string> out;
    std::string problems;  // every file's first problem, so that one run names them all
    for (const auto& [file, sites] : sites_by_file(catalogue)) {
        const fs::path path = root / file;
        try {
            if (!fs::is_regular_file(path))
                throw CatalogueError(where(catalogue, *sites.front().entry) + " is stale: " + file + " does not exist");
            // The switch by its absolute path: the copies need no include directory of their own, so every
            // other file of the schemata build compiles with the production build's command line.
            const fs::path switch_header = fs::absolute(root) / "mutants/switch/raster_mutant_switch.h";
            out[file] = schemata_source(catalogue, read_file(path), sites, switch_header.lexically_normal().string());
        } catch (const CatalogueError& error) {
            problems += std::string(problems.empty() ? "" : "\nraster_mutants: ") + error.what();
        }
    }
    if (!problems.empty()) throw CatalogueError(problems);
    return out;
}

std::string sites_header(const Catalogue& catalogue) {
    std::string text =
        "// The catalogue's sites, generated from mutants/bugs.txt by raster_mutants generate.\n#pragma once\n\n"
        "namespace raster_mutant {\n\ninline constexpr int kSiteCount = " +
        std::to_string(catalogue.entries.size()) + ";\ninline constexpr const char* kSiteNames[] = {\n";
    for (const Entry& entry : catalogue.entries) text += "    \"" + entry.name + "\",\n";
    return text + "};\n\n}  // namespace raster_mutant\n";
}

ComparisonCase case_of(const Entry& entry) { return {entry.scene, entry.flags}; }

int check(const Catalogue& catalogue, const fs::path& root) {
    schemata_sources(catalogue, root);  // every entry fresh and every switch derivable
    const std::vector<ComparisonCase> cases = read_comparison_cases(root / "tests/compare/cases.txt");
    for (const Entry& entry : catalogue.entries) {
        if (!fs::is_regular_file(root / entry.scene))
            throw CatalogueError(where(catalogue, entry) + ": no scene " + entry.scene);
        const ComparisonCase wanted = case_of(entry);
        const bool listed = std::any_of(cases.begin(), cases.end(), [&](const ComparisonCase& c) {
            return c.scene == wanted.scene && c.flags == wanted.flags;
        });
        if (!is_corpus_case(wanted) && !listed)
            throw CatalogueError(where(catalogue, entry) + ": '" + entry.scene + (entry.flags.empty() ? "" : " | ") +
                                 entry.flags + "' is no ctest comparison case: add it to tests/compare/cases.txt");
    }
    std::cout << "raster_mutants: " << catalogue.entries.size()
              << " entries well formed, fresh, switchable and judged by a ctest comparison case\n";
    return 0;
}

int plan(const Catalogue& catalogue, const fs::path& ctest_json, const fs::path& costs, const fs::path& traces,
         double budget) {
    const Coverage coverage = read_coverage(ctest_json, costs, traces);
    std::cerr << "raster_mutants: " << coverage.traces << " traces, " << coverage.unattributed
              << " from processes no test started directly or through its children\n";
    // One line per entry: name, comparison test, tests reaching its site, the rounds of tests to run (each a "-I"
    // list, rounds separated by ';'), and whether the comparison case reaches the site.
    for (const Entry& entry : catalogue.entries) {
        const std::string first = comparison_test_name(case_of(entry));
        const std::vector<std::vector<int>> rounds = select_test_rounds(coverage, entry.name, first, budget);
        const auto reaching = coverage.tests_of_site.find(entry.name);
        const size_t reached = reaching == coverage.tests_of_site.end() ? 0 : reaching->second.size();
        std::string numbers;
        bool first_reaches = false;
        for (const std::vector<int>& round : rounds) {
            if (!numbers.empty()) numbers += ';';
            for (size_t i = 0; i < round.size(); ++i) {
                if (i) numbers += ',';
                numbers += std::to_string(coverage.tests[round[i]].number);
                first_reaches = first_reaches || coverage.tests[round[i]].name == first;
            }
        }
        std::cout << entry.name << '\t' << first << '\t' << reached << '\t' << (numbers.empty() ? "-" : numbers) << '\t'
                  << (first_reaches ? "reaches" : "does-not-reach") << '\n';
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"raster_mutants: the bug catalogue's tool (tools/plant_bugs.sh runs it; docs/catalogue.md)"};
    app.require_subcommand(1);
    fs::path root = ".", catalogue_path;
    app.add_option("--root", root, "the project root (default: the current folder)");
    app.add_option("--catalogue", catalogue_path, "the catalogue (default ROOT/mutants/bugs.txt)");
    CLI::App* list = app.add_subcommand("list", "print each entry as 'name: bug'");
    CLI::App* entries = app.add_subcommand("entries", "print each entry as name, family, file, scene, flags and its "
                                                      "ctest comparison case, separated by |");
    CLI::App* check_command = app.add_subcommand("check", "check that every entry is well formed, fresh, switchable "
                                                          "and judged by a ctest comparison case");
    CLI::App* generate = app.add_subcommand("generate", "write the schemata build's sources into a folder");
    fs::path out;
    generate->add_option("--out", out, "the folder")->required();
    CLI::App* plan_command = app.add_subcommand("plan", "from the correct run's traces, the tests each bug runs");
    fs::path ctest_json, costs, traces;
    double budget = 4.0;
    plan_command->add_option("--ctest-json", ctest_json, "ctest --show-only=json-v1 of the schemata build")->required();
    plan_command->add_option("--costs", costs, "its Testing/Temporary/CTestCostData.txt")->required();
    plan_command->add_option("--traces", traces, "the folder of RASTER_MUTANT_TRACE files")->required();
    plan_command->add_option("--budget", budget, "expected seconds of tests per bug, negative for every test that "
                                                 "reaches its site (default 4)");
    CLI11_PARSE(app, argc, argv);
    try {
        const Catalogue catalogue = read_catalogue(catalogue_path.empty() ? root / "mutants/bugs.txt" : catalogue_path);
        if (*list) {
            for (const Entry& entry : catalogue.entries) std::cout << entry.name << ": " << entry.bug << '\n';
        } else if (*entries) {
            for (const Entry& entry : catalogue.entries)
                std::cout << entry.name << '|' << entry.family << '|' << entry.file << '|' << entry.scene << '|'
                          << entry.flags << '|' << comparison_test_name(case_of(entry)) << '\n';
        } else if (*check_command) {
            return check(catalogue, root);
        } else if (*generate) {
            for (const auto& [file, text] : schemata_sources(catalogue, root)) write_if_changed(out / file, text);
            write_if_changed(out / "raster_mutant_sites.h", sites_header(catalogue));
        } else if (*plan_command) {
            return plan(catalogue, ctest_json, costs, traces, budget);
        }
    } catch (const CatalogueError& error) {
        std::cerr << "raster_mutants: " << error.what() << '\n';
        return 2;
    } catch (const fs::filesystem_error& error) {
        std::cerr << "raster_mutants: " << error.what() << '\n';
        return 2;
    }
    return 0;
}
