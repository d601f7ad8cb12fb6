// The differential corpus's excuse accounting: every input of the given folders through the differential target's
// cases and comparison, summed; prints how many cases each precision mode had and, per class, how many samples the
// precision model excused and what fraction of the compared samples that is: over all cases, and over those with
// ordinary and with extreme coordinates apart; and every excuse class summed over the cases against the fuzz corpus's
// cap. Exit 0 when no input has a genuine disagreement of a class its mode lets the oracle judge and every class is
// within its cap, 1 otherwise, 2 on bad usage.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/differential_scene.h"
#include "harness/comparison/comparison_output.h"
#include "harness/comparison/excuse_account.h"

namespace {

using raster::oracle::SampleClass;

// The classes' counts over some of the cases.
struct Tally {
    raster::oracle::ComparisonCounts counts;
    uint64_t samples = 0, scenes = 0;

    void add(const raster::harness::Comparison& comparison) {
        ++scenes;
        samples += comparison.visibility.classes.size();
        for (int c = 0; c < raster::oracle::kSampleClassCount; ++c)
            counts.by_class[c] += comparison.visibility.counts.by_class[c];
    }
};

// Per ambiguous class, the samples it excused and their fraction of the tally's samples.
void print_excuses(const char* title, const Tally& tally) {
    std::printf("%s: %llu scenes, %llu samples\n", title, static_cast<unsigned long long>(tally.scenes),
                static_cast<unsigned long long>(tally.samples));
    const double all = tally.samples ? static_cast<double>(tally.samples) : 1.0;
    const auto line = [&](const char* name, uint64_t count) {
        std::printf("  %-14s %10llu  %.4f%%\n", name, static_cast<unsigned long long>(count), 100.0 * count / all);
    };
    for (SampleClass k :
         {SampleClass::edge_band, SampleClass::depth_tie, SampleClass::clip_boundary, SampleClass::facing})
        line(raster::oracle::to_string(k), tally.counts.count(k));
    line("ambiguous", tally.counts.ambiguous_total());
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
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
    // All cases, and apart those with ordinary and with extreme coordinates: extremes excuse more, and the split
    // shows how much.
    Tally all, ordinary, extreme;
    raster::harness::ExcuseAccount account;  // every case summed, against the fuzz corpus's caps
    uint64_t genuine_inputs = 0;
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
        ++by_modes[input->modes];
        account.add(raster::harness::account_excuses(comparison, raster::harness::kFuzzCorpusCaps));
        all.add(comparison);
        (input->extreme ? extreme : ordinary).add(comparison);
        if (comparison.genuine_total() > 0) {
            ++genuine_inputs;
            std::printf("GENUINE in %s (modes %s): %s\n", path.c_str(), input->modes,
                        raster::harness::genuine_reasons(comparison).c_str());
        }
    }
    std::printf("%zu inputs\n", inputs.size());
    for (const auto& [modes, count] : by_modes)
        std::printf("  modes %-20s %6llu scenes\n", modes.c_str(), static_cast<unsigned long long>(count));
    print_excuses("all compared", all);
    print_excuses("ordinary coordinates", ordinary);
    print_excuses("extreme coordinates", extreme);
    std::printf("excuses against the fuzz corpus's caps (excuse_account.h):\n");
    for (const raster::harness::ExcuseLine& line : account.lines)
        std::printf("  %-20s %-7s %10llu of %12llu  %.4f%%  cap %.4f%%%s\n", line.name.c_str(), line.unit.c_str(),
                    static_cast<unsigned long long>(line.count), static_cast<unsigned long long>(line.of),
                    100.0 * line.share(), 100.0 * line.cap, line.within() ? "" : "  OVER");
    std::printf("genuine: %llu inputs\n", static_cast<unsigned long long>(genuine_inputs));
    return genuine_inputs == 0 && account.within() ? 0 : 1;
}
