// The known-divergences file: a line parser with line-numbered errors.
#include "oracle/compare/expectations.h"

#include <sstream>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"

namespace raster::oracle {
namespace {

std::string trim(const std::string& text) {
    const size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    const size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

constexpr uint64_t kMaxExpectationsBytes = uint64_t{1} << 20;

}  // namespace

std::vector<KnownDivergence> parse_expectations(const std::string& text, const std::string& file_name) {
    std::vector<KnownDivergence> list;
    std::istringstream lines(text);
    std::string raw;
    for (int number = 1; std::getline(lines, raw); ++number) {
        const std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        auto fail = [&](const std::string& message) { throw InputError(file_name, number, 1, message); };
        const size_t hash = line.find('#');
        if (hash == std::string::npos || trim(line.substr(hash + 1)).empty())
            fail("every known divergence needs a reason: SCENE SAMPLES MAX_GENUINE  # reason");
        KnownDivergence entry;
        entry.reason = trim(line.substr(hash + 1));
        entry.line = number;
        std::istringstream fields(line.substr(0, hash));
        std::string extra;
        if (!(fields >> entry.scene >> entry.samples >> entry.max_genuine) || (fields >> extra))
            fail("expected SCENE SAMPLES MAX_GENUINE  # reason, got \"" + line + "\"");
        if (entry.samples < 1) fail("SAMPLES must be >= 1");
        if (find_expectation(list, entry.scene, entry.samples))
            fail("a second entry for " + entry.scene + " at " + std::to_string(entry.samples) + " samples");
        list.push_back(std::move(entry));
    }
    return list;
}

std::vector<KnownDivergence> load_expectations(const std::filesystem::path& path) {
    return parse_expectations(read_file_bytes(path, kMaxExpectationsBytes), path.string());
}

const KnownDivergence* find_expectation(const std::vector<KnownDivergence>& list, const std::string& scene, int samples) {
    for (const KnownDivergence& entry : list)
        if (entry.scene == scene && entry.samples == samples) return &entry;
    return nullptr;
}

}  // namespace raster::oracle
