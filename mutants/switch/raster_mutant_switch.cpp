// The schemata build's switch: RASTER_MUTANT picks the entry, RASTER_MUTANT_TRACE records the sites each process ran.
#include "raster_mutant_switch.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "raster_mutant_sites.h"  // generated: kSiteNames, kSiteCount

namespace raster_mutant {
namespace {

std::atomic<unsigned char> g_reached[kSiteCount > 0 ? kSiteCount : 1];

// A process's command line, its arguments separated by the unit separator (0x1f).
std::string command_line(long pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
    std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!raw.empty() && raw.back() == '\0') raw.pop_back();
    for (char& c : raw)
        if (c == '\0') c = '\x1f';
    return raw;
}

long parent_of(long pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t close = stat.rfind(')');  // the command name may hold spaces and parentheses
    if (close == std::string::npos) return 0;
    std::istringstream rest(stat.substr(close + 1));
    std::string state;
    long parent = 0;
    rest >> state >> parent;
    return parent;
}

const char* g_trace_dir = nullptr;

void write_trace() {
    std::string text;
    // The process and up to eight ancestors (ctest's own process ends the chain): the runner matches these against
    // each test's command to tell which test reached which site.
    for (long pid = getpid(), level = 0; pid > 1 && level < 9; pid = parent_of(pid), ++level) {
        const std::string command = command_line(pid);
        text += "command " + command + "\n";
        const std::string program = command.substr(0, command.find('\x1f'));
        if (program.size() >= 5 && program.compare(program.size() - 5, 5, "ctest") == 0) break;
    }
    for (int site = 0; site < kSiteCount; ++site)
        if (g_reached[site].load(std::memory_order_relaxed)) text += std::string("site ") + kSiteNames[site] + "\n";
    const std::string path = std::string(g_trace_dir) + "/" + std::to_string(getpid()) + ".trace";
    if (FILE* file = std::fopen((path + ".tmp").c_str(), "wb")) {
        std::fwrite(text.data(), 1, text.size(), file);
        if (std::fclose(file) == 0) std::rename((path + ".tmp").c_str(), path.c_str());
    }
}

}  // namespace

State load_state() {
    State state{-1, g_reached};
    if (const char* name = std::getenv("RASTER_MUTANT"); name && *name) {
        for (int site = 0; site < kSiteCount; ++site)
            if (std::strcmp(kSiteNames[site], name) == 0) state.active = site;
        if (state.active < 0) {
            std::fprintf(stderr, "raster: RASTER_MUTANT=%s names no entry of mutants/bugs.txt\n", name);
            std::exit(2);
        }
    }
    if (const char* dir = std::getenv("RASTER_MUTANT_TRACE"); dir && *dir) {
        g_trace_dir = dir;
        std::atexit(write_trace);
    }
    return state;
}

}  // namespace raster_mutant
