// Google Benchmark's initialisation with the bench programs' own defaults: the defaults first, so that the user's
// flags, parsed later, win; the program's own flags are taken out by the caller before.
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace raster_bench {

// Initialises Google Benchmark with `defaults` followed by `user_flags` (argv[0] first). False (after printing
// the offending flag) when a flag is unknown.
inline bool initialize_benchmark(const char* program, std::vector<std::string> defaults,
                                 const std::vector<char*>& user_flags) {
    std::vector<char*> args{const_cast<char*>(program)};
    for (std::string& flag : defaults) args.push_back(flag.data());
    args.insert(args.end(), user_flags.begin(), user_flags.end());
    int count = static_cast<int>(args.size());
    args.push_back(nullptr);
    benchmark::Initialize(&count, args.data());
    return !benchmark::ReportUnrecognizedArguments(count, args.data());
}

}  // namespace raster_bench
