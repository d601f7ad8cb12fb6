// Comparisons as JUnit XML (junit_report.h).
#include "harness/comparison/junit_report.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <filesystem>

#include "harness/comparison/comparison_output.h"

namespace raster::harness {
namespace {

// Text as XML 1.0 character data or an attribute value: the five special characters as entities, the control
// characters XML 1.0 forbids (all below 0x20 but tab, newline and return) as '?'.
std::string escaped(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += '?';
                else out += c;
        }
    }
    return out;
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds);
    return text;
}

}  // namespace

JunitCase junit_case(const Comparison& comparison, const std::string& scene_file) {
    JunitCase out;
    const std::filesystem::path path(scene_file);
    std::string folder = path.parent_path().relative_path().generic_string();  // no leading slash
    for (char& c : folder)
        if (c == '/') c = '.';
    out.classname = folder.empty() ? "raster" : folder;
    out.name = path.filename().string() + ", " + std::to_string(comparison.samples) +
               (comparison.samples == 1 ? " sample" : " samples") + (comparison.renderer.empty() ? "" : ", " + comparison.renderer);
    out.seconds = (comparison.raster_ms + comparison.write_ms + comparison.oracle_ms + comparison.compare_ms) / 1000.0;
    out.genuine = comparison.genuine_total();
    if (out.genuine > 0) {
        out.message = std::to_string(out.genuine) + " genuine: " + genuine_reasons(comparison);
        out.details = genuine_details(comparison);
    }
    out.output = comparison_summary(comparison);
    return out;
}

std::string junit_xml(const std::string& suite, const std::vector<JunitCase>& cases, const std::string& timestamp,
                      const std::string& hostname) {
    size_t failures = 0;
    double seconds = 0.0;
    for (const JunitCase& c : cases) {
        failures += c.genuine > 0;
        seconds += c.seconds;
    }
    const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                               "\" errors=\"0\"";
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"" + escaped(suite) + "\"" + counts + " time=\"" + seconds_text(seconds) + "\">\n";
    xml += "  <testsuite name=\"" + escaped(suite) + "\"" + counts + " skipped=\"0\" time=\"" + seconds_text(seconds) +
           "\" timestamp=\"" + escaped(timestamp) + "\" hostname=\"" + escaped(hostname) + "\">\n";
    xml += "    <properties/>\n";
    for (const JunitCase& c : cases) {
        xml += "    <testcase classname=\"" + escaped(c.classname) + "\" name=\"" + escaped(c.name) + "\" time=\"" +
               seconds_text(c.seconds) + "\">\n";
        if (c.genuine > 0)
            xml += "      <failure message=\"" + escaped(c.message) + "\" type=\"genuine disagreement\">" +
                   escaped(c.details) + "</failure>\n";
        xml += "      <system-out>" + escaped(c.output) + "</system-out>\n";
        xml += "    </testcase>\n";
    }
    xml += "    <system-out/>\n    <system-err/>\n  </testsuite>\n</testsuites>\n";
    return xml;
}

std::string junit_timestamp_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
    return text;
}

std::string junit_hostname() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "localhost";
    return name;
}

}  // namespace raster::harness
