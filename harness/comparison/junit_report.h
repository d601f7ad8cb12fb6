// Comparisons as JUnit XML, the report format CI systems read natively: a test suite per command run, a test case
// per scene and sample count, failed when the scene has genuine disagreements (the message names their counts by
// reason, the body lists the first of them), with the run's summary as the case's output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/comparison/scene_comparison.h"

namespace raster::harness {

struct JunitCase {
    std::string classname;  // the scene's folder, e.g. "corpus.scenes"
    std::string name;       // the scene file's name and what it was rendered with, e.g. "teapot.yaml, 16 samples"
    double seconds = 0.0;   // raster's frame, its writing, the oracle and the comparison
    uint64_t genuine = 0;   // 0: the case passed
    std::string message;    // for a failure: "12 genuine: visibility 10, color 2"
    std::string details;    // for a failure: the first genuine samples and pixels, one a line
    std::string output;     // the run's summary for a person
};

// The case for one scene's comparison; `scene_file` as the user named it.
JunitCase junit_case(const Comparison& comparison, const std::string& scene_file);

// A whole document: <testsuites> holding one <testsuite name="suite"> of the cases, stamped with `timestamp`
// (ISO 8601, UTC) and `hostname`. Text is escaped for XML 1.0; characters XML cannot hold become '?'.
std::string junit_xml(const std::string& suite, const std::vector<JunitCase>& cases, const std::string& timestamp,
                      const std::string& hostname);

// The current time as ISO 8601 in UTC (2026-12-07T15:04:05) and this machine's host name, for junit_xml.
std::string junit_timestamp_now();
std::string junit_hostname();

}  // namespace raster::harness
