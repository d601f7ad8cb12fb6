// Standalone main for builds without libFuzzer: feeds every file named (or found in a named folder) to the target.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/replay_cpu_time.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::vector<std::filesystem::path> inputs_under(const std::filesystem::path& path) {
    std::vector<std::filesystem::path> inputs;
    if (std::filesystem::is_directory(path)) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
            if (entry.is_regular_file()) inputs.push_back(entry.path());
        std::sort(inputs.begin(), inputs.end());  // the same order on every machine
    } else {
        inputs.push_back(path);
    }
    return inputs;
}

}  // namespace

int main(int argc, char** argv) {
    size_t replayed = 0, slow = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.starts_with("-")) continue;  // libFuzzer flags such as -runs=0 mean nothing here
        if (!std::filesystem::exists(argument)) {
            std::fprintf(stderr, "replay: %s does not exist\n", argument.c_str());
            return 2;
        }
        for (const std::filesystem::path& input : inputs_under(argument)) {
            std::ifstream in(input, std::ios::binary);
            const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            if (!in.good() && !in.eof()) {
                std::fprintf(stderr, "replay: cannot read %s\n", input.c_str());
                return 2;
            }
            std::fprintf(stderr, "replay: %s\n", input.c_str());
            // CPU time, not wall time: see replay_cpu_time.h.
            const double seconds = raster::fuzz::cpu_seconds_of(
                [&] { LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()); });
            if (seconds > raster::fuzz::kHangCpuSeconds) {
                std::fprintf(stderr, "replay: SLOW %s took %.2f s of CPU time (over %.1f s)\n", input.c_str(), seconds,
                             raster::fuzz::kHangCpuSeconds);
                ++slow;
            }
            ++replayed;
        }
    }
    std::fprintf(stderr, "replay: %zu inputs, %zu slow\n", replayed, slow);
    return slow == 0 ? 0 : 1;
}
