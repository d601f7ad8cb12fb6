// The differential corpus's excuse accounting: every input of the given folders through the differential target's
// cases and comparison, summed; prints how many cases each precision mode had (and how many had extreme
// coordinates) and, per class, how many samples the precision model excused and what fraction of all compared
// samples that is. Exit 0 when no input has a genuine disagreement of a class its mode lets the oracle judge, 1
// otherwise, 2 on bad usage.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/differential_scene.h"
#include "harness/comparison/scene_comparison.h"

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    using raster::oracle::SampleClass;
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s DIR|FILE...\n", argv[0]);
        return 2;
    }
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        if (fs::is_directory(argv[i])) {
            for (const auto& entry : fs::directory_iterator(argv[i]))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
        } else {
            inputs.push_back(argv[i]);
        }
    }
    raster::oracle::ComparisonCounts total;
    uint64_t compared = 0, scenes = 0, extreme = 0, genuine_inputs = 0;
    std::map<std::string, uint64_t> by_modes;
    for (const fs::path& path : inputs) {
        std::ifstream file(path, std::ios::binary);
        const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
        const std::optional<raster::fuzz::DifferentialCase> input =
            raster::fuzz::differential_case(bytes.data(), bytes.size());
        if (!input) continue;
        raster::harness::ComparisonOptions options;
        options.threads = 1;
        const raster::harness::Comparison comparison = raster::harness::compare_scene(input->scene, options);
        ++scenes;
        ++by_modes[input->modes];
        extreme += input->extreme;
        compared += comparison.visibility.classes.size();
        for (int c = 0; c < raster::oracle::kSampleClassCount; ++c)
            total.by_class[c] += comparison.visibility.counts.by_class[c];
        if (raster::fuzz::judged_genuine(comparison, input->judged) > 0) {
            ++genuine_inputs;
            std::printf("GENUINE in %s (modes %s): %s\n", path.c_str(), input->modes,
                        raster::harness::genuine_reasons(comparison).c_str());
        }
    }
    std::printf("%zu inputs, %llu scenes compared (%llu with extreme coordinates), %llu samples\n", inputs.size(),
                static_cast<unsigned long long>(scenes), static_cast<unsigned long long>(extreme),
                static_cast<unsigned long long>(compared));
    for (const auto& [modes, count] : by_modes)
        std::printf("  modes %-20s %6llu scenes\n", modes.c_str(), static_cast<unsigned long long>(count));
    const double all = compared ? static_cast<double>(compared) : 1.0;
    for (SampleClass k : {SampleClass::edge_band, SampleClass::depth_tie, SampleClass::clip_boundary, SampleClass::facing})
        std::printf("  %-14s %10llu  %.4f%%\n", raster::oracle::to_string(k),
                    static_cast<unsigned long long>(total.count(k)), 100.0 * total.count(k) / all);
    std::printf("  %-14s %10llu  %.4f%%\n", "ambiguous", static_cast<unsigned long long>(total.ambiguous_total()),
                100.0 * total.ambiguous_total() / all);
    std::printf("  %-14s %10llu inputs\n", "genuine", static_cast<unsigned long long>(genuine_inputs));
    return genuine_inputs == 0 ? 0 : 1;
}
