// The closing tables: each benchmark's median frame time kept as it runs, then raster against its peers per scene.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"

namespace raster_bench {

// The console reporter, also keeping each benchmark's median wall and process CPU time per frame (or, without
// repetitions, the median over its runs) for the closing table.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
    using ConsoleReporter::ConsoleReporter;

    enum Clock { wall = 0, cpu = 1 };

    void ReportRuns(const std::vector<Run>& runs) override;

    // Median milliseconds per frame; NaN when the benchmark did not run.
    double median_ms(const std::string& name, Clock clock) const;

private:
    std::map<std::string, std::array<double, 2>> medians_;
    std::map<std::string, std::vector<std::array<double, 2>>> runs_;
};

// The medians table (raster against llvmpipe, wall and CPU time), the targets, and raster against the oracle.
void print_summary(const SummaryReporter& reporter, const std::vector<std::unique_ptr<BenchScene>>& scenes,
                   const std::string& llvmpipe_absent);

}  // namespace raster_bench
