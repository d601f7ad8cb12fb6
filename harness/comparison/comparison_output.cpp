// A comparison's JSON, summary, reasons, details and disagreement map.
#include "harness/comparison/comparison_output.h"

#include <algorithm>
#include <cstdio>

#include "harness/comparison/decoded_image.h"
#include "harness/comparison/excuse_account.h"
#include "oracle/compare/diff_map.h"

namespace raster::harness {
namespace {

oracle::RasterPixels pixels_of(const Image& image) {
    return {image.width, image.height, image.channels, image.pixels.data()};
}

// Genuine colour pixels that neither a shadow nor a transparent layer explains.
uint64_t plain_colour_pixels(const Comparison& c) {
    return c.colour.genuine_pixels - c.shadows.genuine_pixels - c.transparency.genuine_pixels;
}

nlohmann::json colour_disagreements_json(const oracle::ColourCheck& check, const char* format) {
    nlohmann::json list = nlohmann::json::array();
    for (const oracle::ColourDisagreement& d : check.first) {
        nlohmann::json raster = nlohmann::json::array(), oracle = nlohmann::json::array(),
                       allowed = nlohmann::json::array();
        for (int c = 0; c < d.channels; ++c) {
            raster.push_back(d.raster[c]);
            oracle.push_back(d.oracle[c]);
            allowed.push_back({d.allowed[c].lo, d.allowed[c].hi});
        }
        list.push_back({{"x", d.x}, {"y", d.y}, {"file", format}, {"raster", raster}, {"oracle", oracle},
                        {"allowed", allowed}});
    }
    return list;
}

nlohmann::json depth_disagreements_json(const oracle::DepthImageCheck& check, const char* format) {
    nlohmann::json list = nlohmann::json::array();
    for (const oracle::DepthImageCheck::Disagreement& d : check.first)
        list.push_back({{"x", d.x}, {"y", d.y}, {"file", format}, {"raster", d.file}, {"allowed", {d.lo, d.hi}}});
    return list;
}

nlohmann::json excuses_json(const ExcuseAccount& account) {
    nlohmann::json list = nlohmann::json::array();
    for (const ExcuseLine& line : account.lines)
        list.push_back({{"class", line.name},
                        {"unit", line.unit},
                        {"count", line.count},
                        {"of", line.of},
                        {"share", line.share()},
                        {"cap", line.cap},
                        {"within", line.within()}});
    return list;
}

nlohmann::json interval_widths_json(const oracle::IntervalWidths& widths) {
    nlohmann::json bins = nlohmann::json::array();
    for (int b = 0; b < oracle::kIntervalWidthBins; ++b)
        bins.push_back({{"levels", oracle::IntervalWidths::label(b)}, {"pixels", widths.pixels[b]}});
    return {{"bins", bins}, {"widest", widths.widest}, {"wide_above", oracle::kWideIntervalLevels}};
}

}  // namespace

nlohmann::json comparison_json(const Comparison& c) {
    using oracle::SampleClass;
    const oracle::ComparisonCounts& counts = c.visibility.counts;
    auto count = [&](SampleClass k) { return counts.count(k); };
    const double total = std::max<double>(1.0, static_cast<double>(c.visibility.classes.size()));
    auto fraction = [&](SampleClass k) { return static_cast<double>(count(k)) / total; };
    nlohmann::json colour_disagreements = colour_disagreements_json(c.colour.png, "png");
    for (const nlohmann::json& d : colour_disagreements_json(c.colour.ppm, "ppm")) colour_disagreements.push_back(d);
    nlohmann::json depth_disagreements = depth_disagreements_json(c.depth.png, "png");
    for (const nlohmann::json& d : depth_disagreements_json(c.depth.ppm, "ppm")) depth_disagreements.push_back(d);
    return {{"scene", c.scene},
            {"renderer", c.renderer},
            {"width", c.width},
            {"height", c.height},
            {"samples", c.samples},
            {"oracle_mode", oracle::to_string(c.mode)},
            {"agree", count(SampleClass::agree)},
            {"ambiguous",
             {{"edge_band", count(SampleClass::edge_band)},
              {"depth_tie", count(SampleClass::depth_tie)},
              {"clip_boundary", count(SampleClass::clip_boundary)},
              {"facing", count(SampleClass::facing)}}},
            {"ambiguous_total", counts.ambiguous_total()},
            {"ambiguous_fraction",
             {{"edge_band", fraction(SampleClass::edge_band)},
              {"depth_tie", fraction(SampleClass::depth_tie)},
              {"clip_boundary", fraction(SampleClass::clip_boundary)},
              {"facing", fraction(SampleClass::facing)},
              {"total", static_cast<double>(counts.ambiguous_total()) / total}}},
            {"genuine",
             {{"visibility", count(SampleClass::visibility)},
              {"barycentrics", count(SampleClass::barycentrics)},
              {"depth", count(SampleClass::depth)},
              {"color", plain_colour_pixels(c)},
              {"shadow", c.shadows.genuine_pixels},
              {"transparency", c.transparency.genuine_pixels},
              {"depth_image", c.depth.genuine_pixels}}},
            {"genuine_total", c.genuine_total()},
            {"genuine_reasons", genuine_reasons(c)},
            {"unjudged", c.judged.unjudged},
            {"shadows",
             {{"edge", c.shadows.edge_pixels},
              {"depth", c.shadows.depth_pixels},
              {"inconsistent", c.shadows.inconsistent_pixels}}},
            {"transparency",
             {{"edge", c.transparency.edge_pixels},
              {"depth", c.transparency.depth_pixels},
              {"order", c.transparency.order_pixels}}},
            {"excuses", excuses_json(account_excuses(c))},
            {"interval_widths", interval_widths_json(c.colour.png.widths)},
            {"pixels",
             {{"judged", c.colour.png.judged},
              {"ambiguous", c.colour.png.ambiguous},
              {"wide_interval", c.colour.png.wide},
              {"color_png", c.colour.png.genuine},
              {"color_ppm", c.colour.ppm.genuine},
              {"depth_png", c.depth.png.genuine},
              {"depth_ppm", c.depth.ppm.genuine}}},
            {"outputs", {{"color", c.colour.written}, {"depth", c.depth.written}}},
            {"max_color_error", std::max(c.colour.png.max_difference, c.colour.ppm.max_difference)},
            {"max_depth_error", std::max(c.depth.png.max_difference, c.depth.ppm.max_difference)},
            {"color_disagreements", colour_disagreements},
            {"depth_disagreements", depth_disagreements},
            {"raster_ms", c.raster_ms},
            {"write_ms", c.write_ms},
            {"oracle_ms", c.oracle_ms},
            {"compare_ms", c.compare_ms}};
}

std::string comparison_summary(const Comparison& c) {
    using oracle::SampleClass;
    using ull = unsigned long long;
    const oracle::ComparisonCounts& counts = c.visibility.counts;
    auto count = [&](SampleClass k) { return static_cast<ull>(counts.count(k)); };
    const double total = std::max<double>(1.0, static_cast<double>(c.visibility.classes.size()));
    char text[2048];
    int used = std::snprintf(
        text, sizeof text,
        "%s (%s): %dx%d, %d samples per pixel, oracle %s\n"
        "  samples agree      %llu\n"
        "  samples ambiguous  %llu = %.4f%% (edge band %llu, depth tie %llu, clip boundary %llu, facing %llu)\n"
        "  samples genuine    %llu (visibility %llu, barycentrics %llu, depth %llu)\n",
        c.scene.c_str(), c.renderer.c_str(), c.width, c.height, c.samples, oracle::to_string(c.mode),
        count(SampleClass::agree), static_cast<ull>(counts.ambiguous_total()), 100.0 * counts.ambiguous_total() / total,
        count(SampleClass::edge_band), count(SampleClass::depth_tie), count(SampleClass::clip_boundary),
        count(SampleClass::facing), static_cast<ull>(counts.genuine_total()), count(SampleClass::visibility),
        count(SampleClass::barycentrics), count(SampleClass::depth));
    std::string out(text, static_cast<size_t>(std::max(used, 0)));
    if (c.colour.written) {
        std::snprintf(text, sizeof text,
                      "  colour image       pixels judged %llu, ambiguous %llu, genuine %llu (png %llu, ppm %llu), of "
                      "them shadow %llu, transparency %llu\n"
                      "  shadow model open  %llu pixels by an edge, %llu by depth, %llu inconsistent\n"
                      "  layers open        %llu pixels by an edge, %llu by depth, %llu by order\n"
                      "  max colour difference from the oracle's image %d/255 on judged pixels\n",
                      static_cast<ull>(c.colour.png.judged), static_cast<ull>(c.colour.png.ambiguous),
                      static_cast<ull>(c.colour.genuine_pixels), static_cast<ull>(c.colour.png.genuine),
                      static_cast<ull>(c.colour.ppm.genuine), static_cast<ull>(c.shadows.genuine_pixels),
                      static_cast<ull>(c.transparency.genuine_pixels), static_cast<ull>(c.shadows.edge_pixels),
                      static_cast<ull>(c.shadows.depth_pixels), static_cast<ull>(c.shadows.inconsistent_pixels),
                      static_cast<ull>(c.transparency.edge_pixels), static_cast<ull>(c.transparency.depth_pixels),
                      static_cast<ull>(c.transparency.order_pixels),
                      std::max(c.colour.png.max_difference, c.colour.ppm.max_difference));
        out += text;
    }
    if (c.depth.written) {
        std::snprintf(text, sizeof text, "  depth image        pixels judged %llu, genuine %llu (png %llu, ppm %llu)\n",
                      static_cast<ull>(c.depth.png.pixels), static_cast<ull>(c.depth.genuine_pixels),
                      static_cast<ull>(c.depth.png.genuine), static_cast<ull>(c.depth.ppm.genuine));
        out += text;
    }
    if (c.colour.written) {
        std::string bins;
        for (int b = 0; b < oracle::kIntervalWidthBins; ++b)
            bins += std::string(b ? ", " : "") + oracle::IntervalWidths::label(b) + ": " +
                    std::to_string(c.colour.png.widths.pixels[b]);
        out += "  interval widths    " + bins + " (pixels by levels; widest " +
               std::to_string(c.colour.png.widths.widest) + ", " + std::to_string(c.colour.png.wide) + " wider than " +
               std::to_string(oracle::kWideIntervalLevels) + " counted ambiguous)\n";
    }
    const std::string over = account_excuses(c).violations();
    if (over.empty()) out += "  excuses            every class within its cap\n";
    for (size_t at = 0, end; at < over.size(); at = end + 1) {
        end = over.find('\n', at);
        out += "  over its cap       " + over.substr(at, end - at) + "\n";
    }
    for (const std::string& reason : c.judged.unjudged) out += "  unjudged           " + reason + "\n";
    std::snprintf(text, sizeof text,
                  "  genuine total      %llu\n"
                  "  raster %.1f ms (writing %.1f ms), oracle %.1f ms, compare %.1f ms\n",
                  static_cast<ull>(c.genuine_total()), c.raster_ms, c.write_ms, c.oracle_ms, c.compare_ms);
    return out + text;
}

std::string genuine_reasons(const Comparison& c) {
    std::string text;
    auto add = [&](const char* reason, uint64_t count) {
        if (count) text += std::string(text.empty() ? "" : ", ") + reason + " " + std::to_string(count);
    };
    if (c.judged.visibility) add("visibility", c.visibility.counts.count(oracle::SampleClass::visibility));
    if (c.judged.interpolation) {
        for (oracle::SampleClass k : {oracle::SampleClass::barycentrics, oracle::SampleClass::depth})
            add(oracle::to_string(k), c.visibility.counts.count(k));
        add("color", plain_colour_pixels(c));
        add("shadow", c.shadows.genuine_pixels);
        add("transparency", c.transparency.genuine_pixels);
    }
    add("depth image", c.depth.genuine_pixels);
    return text.empty() ? "-" : text;
}

std::string genuine_details(const Comparison& c, int shown) {
    std::string text;
    int listed = 0;
    const auto& classes = c.visibility.classes;
    const VisibilityBuffer& raster = c.raster.visibility;
    const oracle::SampleBuffer& oracle = c.oracle_visibility;
    for (size_t i = 0; i < classes.size() && listed < shown; ++i) {
        if (!oracle::is_genuine(classes[i])) continue;
        const size_t samples = static_cast<size_t>(c.samples), width = static_cast<size_t>(c.width);
        const glm::vec3 &a = raster.bary[i], &b = oracle.bary[i];
        char line[512];
        std::snprintf(line, sizeof line,
                      "  %s at pixel (%zu, %zu) sample %zu:\n    raster triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n"
                      "    oracle triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n",
                      oracle::to_string(classes[i]), (i / samples) % width, i / samples / width, i % samples,
                      int(raster.triangle[i]), double(raster.view_depth[i]), double(a.x), double(a.y), double(a.z),
                      int(oracle.triangle[i]), double(oracle.view_depth[i]), double(b.x), double(b.y), double(b.z));
        text += line;
        ++listed;
    }
    for (const auto* check : {&c.colour.png, &c.colour.ppm})
        for (const oracle::ColourDisagreement& d : check->first) {
            if (listed >= 2 * shown) break;
            // snprintf rather than string concatenation: g++ 12's -O3 -Wrestrict misreads the latter here.
            char line[128];
            std::snprintf(line, sizeof line, "  colour (%s) at pixel (%d, %d):", check == &c.colour.png ? "png" : "ppm",
                          d.x, d.y);
            text += line;
            for (int ch = 0; ch < d.channels; ++ch) {
                std::snprintf(line, sizeof line, " %d not in [%d, %d] (oracle %d)", d.raster[ch], d.allowed[ch].lo,
                              d.allowed[ch].hi, d.oracle[ch]);
                text += line;
            }
            text += "\n";
            ++listed;
        }
    for (const auto* check : {&c.depth.png, &c.depth.ppm})
        for (const oracle::DepthImageCheck::Disagreement& d : check->first) {
            if (listed >= 3 * shown) break;
            char line[128];
            std::snprintf(line, sizeof line, "  depth image (%s) at pixel (%d, %d): %d not in [%d, %d]\n",
                          check == &c.depth.png ? "png" : "ppm", d.x, d.y, d.file, d.lo, d.hi);
            text += line;
            ++listed;
        }
    return text;
}

Image diff_map(const Comparison& c) {
    // A pixel whose bytes are wrong in any written file, colour or depth, is a wrong pixel of the map.
    std::vector<uint8_t> wrong_bytes(static_cast<size_t>(c.width) * c.height, 0);
    for (size_t i = 0; i < wrong_bytes.size(); ++i)
        wrong_bytes[i] = (c.colour.written && c.colour.genuine[i]) ||
                         (c.depth.written && (c.depth.png.genuine_pixels[i] | c.depth.ppm.genuine_pixels[i]));
    return image_of(oracle::diff_map(c.visibility.classes, c.samples, wrong_bytes, pixels_of(c.raster.image),
                                     {&c.shadows.genuine, &c.shadows.seen, &c.transparency.open}));
}

}  // namespace raster::harness
