// The comparison report's page and summary: plain HTML with inline style and script, and JSON.
#include "oracle/report/report.h"

#include <cstdio>
#include <initializer_list>

namespace raster::oracle {
namespace {

std::string escape_html(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string number(const nlohmann::json& value) {
    if (value.is_number_float()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", value.get<double>());
        return text;
    }
    return value.dump();
}

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
table.report { border-collapse: collapse; }
table.report > tbody > tr > * { border-top: 1px solid #ccc; padding: 0.5em; vertical-align: top; text-align: left; }
table.report img { width: 240px; height: auto; image-rendering: pixelated; background: #000; display: block; }
table.counts td { padding: 0 0.6em 0 0; font-size: 0.9em; }
tr.genuine > th { color: #c00; }
.legend span { padding: 0 0.4em; }
.hover { font-size: 0.8em; min-height: 1.2em; max-width: 240px; color: #444; }
img.pareto { max-width: 100%; height: auto; border: 1px solid #ccc; background: #fff; }
table.tradeoff { border-collapse: collapse; margin-bottom: 1em; }
table.tradeoff th, table.tradeoff td { padding: 0.15em 0.6em; text-align: right; border-bottom: 1px solid #e4e4e4; }
table.tradeoff th:first-child, table.tradeoff td:first-child { text-align: left; }
table.tradeoff tr.on-front td { color: #a01010; font-weight: bold; }
)";

constexpr const char* kScript = R"(
function markRenderedRows() {
  let rendered = 0;
  for (const row of document.querySelectorAll('tr.scene')) {
    const images = Array.from(row.querySelectorAll('img'));
    const ok = images.length > 0 && images.every(image => image.complete && image.naturalWidth > 0);
    row.dataset.rendered = ok ? 'yes' : 'no';
    if (ok) rendered++;
  }
  document.body.dataset.rowsRendered = String(rendered);
}
window.addEventListener('load', markRenderedRows);
// Over a diff map, the colour disagreement under the pointer: raster's bytes, the range the oracle allows and the
// oracle's own bytes, per channel.
function showColourDisagreement(event) {
  const image = event.target;
  const x = Math.floor(event.offsetX * image.naturalWidth / image.clientWidth);
  const y = Math.floor(event.offsetY * image.naturalHeight / image.clientHeight);
  const list = JSON.parse(image.dataset.disagreements || '[]');
  const found = list.filter(d => d.x === x && d.y === y);
  const out = image.closest('tr').querySelector('.hover');
  out.textContent = found.length === 0 ? '(' + x + ', ' + y + ')' : found.map(d =>
    '(' + x + ', ' + y + ') ' + d.file + ': raster ' + d.raster.join(' ') + ', allowed ' +
    d.allowed.map(r => r[0] + '-' + r[1]).join(' ') + ', oracle ' + d.oracle.join(' ')).join('; ');
}
for (const image of document.querySelectorAll('img.diff')) image.addEventListener('mousemove', showColourDisagreement);
)";

std::string image_cell(const std::string& file, const std::string& alt, const std::string& extra = "") {
    return "<td><a href=\"" + escape_html(file) + "\"><img src=\"" + escape_html(file) + "\" alt=\"" +
           escape_html(alt) + "\"" + extra + "></a></td>";
}

// A fraction of the samples, as a percentage with four decimals.
std::string percent(const nlohmann::json& value) {
    if (!value.is_number()) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.4f%%", 100.0 * value.get<double>());
    return text;
}

// object[key], or null when it is missing (a hand-edited or older tradeoff.json must not crash the page).
nlohmann::json field(const nlohmann::json& object, const char* key) {
    return object.is_object() && object.contains(key) ? object[key] : nlohmann::json();
}

// A number of a tradeoff.json, with `digits` decimals; "-" when missing or null.
std::string fixed(const nlohmann::json& value, int digits) {
    if (!value.is_number()) return "-";
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", digits, value.get<double>());
    return text;
}

// object[key] as text, or "" when it is missing or not a string.
std::string text(const nlohmann::json& object, const char* key) {
    const nlohmann::json value = field(object, key);
    return value.is_string() ? value.get<std::string>() : "";
}

// The elements of object[key] that are objects (none when it is missing or not an array).
std::vector<nlohmann::json> objects(const nlohmann::json& object, const char* key) {
    std::vector<nlohmann::json> out;
    const nlohmann::json list = field(object, key);
    if (list.is_array())
        for (const nlohmann::json& item : list)
            if (item.is_object()) out.push_back(item);
    return out;
}

// The "Speed against accuracy" section: the plot, a table per scene and the links. Reads tradeoff.json's fields
// defensively: a missing or mistyped field shows as "-" or blank, never as an exception.
std::string tradeoff_section(const TradeoffLink& link) {
    const std::string dir = link.dir.empty() ? "" : link.dir + "/";
    const nlohmann::json& results = link.results;
    std::string html = "<h2 id=\"tradeoff\">Speed against accuracy</h2>\n";
    html += "<p>Each mode's median frame time (of " + fixed(field(results, "runs"), 0) +
            " runs) against its colour RMSE (0-255) to the oracle's image at " +
            fixed(field(field(results, "reference"), "samples_per_pixel"), 0) +
            " samples per pixel; genuine and ambiguous samples as above; coverage error = the sum over triangles of "
            "|sampled area - exact area| / the total exact area. In red: the Pareto front. <a href=\"" +
            escape_html(dir + "tradeoff.csv") + "\">CSV</a>, <a href=\"" + escape_html(dir + "tradeoff.json") +
            "\">JSON</a>.</p>\n";
    html += "<p><a href=\"" + escape_html(dir + "pareto.svg") + "\"><img class=\"pareto\" src=\"" +
            escape_html(dir + "pareto.svg") + "\" alt=\"time against colour RMSE per mode, Pareto front\"></a></p>\n";
    for (const nlohmann::json& scene : objects(results, "scenes")) {
        const std::string name = text(scene, "name");
        html += "<h3>" + escape_html(name) + "</h3>\n<table class=\"tradeoff\" data-scene=\"" + escape_html(name) +
                "\">\n<thead><tr><th>mode</th><th>median ms</th><th>genuine</th><th>ambiguous</th><th>colour RMSE</th>"
                "<th>coverage error</th><th>front</th></tr></thead>\n<tbody>\n";
        for (const nlohmann::json& mode : objects(scene, "modes")) {
            const bool on_front = field(mode, "on_front") == true;
            html += std::string("<tr") + (on_front ? " class=\"on-front\"" : "") + "><td title=\"" +
                    escape_html(text(mode, "description")) + "\">" + escape_html(text(mode, "mode")) + "</td><td>" +
                    fixed(field(mode, "median_ms"), 2) + "</td><td>" + fixed(field(mode, "genuine"), 0) + "</td><td>" +
                    fixed(field(mode, "ambiguous"), 0) + "</td><td>" + fixed(field(mode, "color_rmse"), 3) +
                    "</td><td>" + fixed(field(mode, "coverage_error"), 5) + "</td><td>" + (on_front ? "&#10003;" : "") +
                    "</td></tr>\n";
        }
        html += "</tbody>\n</table>\n";
    }
    return html;
}

}  // namespace

std::string unique_file_stem(const std::string& name, std::set<std::string>& taken) {
    std::string base;
    for (char c : name) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                           c == '_' || c == '-';
        base += plain ? c : '_';
    }
    if (base.empty() || base[0] == '.') base = "scene" + base;
    std::string stem = base;
    for (int k = 2; taken.count(stem); ++k) stem = base + "-" + std::to_string(k);
    taken.insert(stem);
    return stem;
}

namespace {

// Each excuse class against its cap (the classes over it first, in bold), the colour intervals' widths, and what the
// precision modes left unjudged.
std::string excuse_rows(const nlohmann::json& c) {
    std::string html, over, within;
    for (const nlohmann::json& line : c.value("excuses", nlohmann::json::array())) {
        const std::string text = escape_html(line.value("class", "")) + " " + number(line["count"]) + " " +
                                 escape_html(line.value("unit", "")) + " (" + percent(line["share"]) + " of cap " +
                                 percent(line["cap"]) + ")";
        if (line.value("within", true)) {
            if (line.value("count", 0) > 0) within += (within.empty() ? "" : ", ") + text;
        } else {
            over += "<b>" + text + " over its cap</b><br>";
        }
    }
    if (c.contains("excuses"))
        html += "<tr class=\"excuses\"><td>excuses</td><td>" + std::string(over.empty() ? "within caps" : "OVER CAP") +
                "</td><td>" + over + (within.empty() ? "none used" : within) + "</td></tr>";
    const nlohmann::json widths = c.value("interval_widths", nlohmann::json::object());
    if (!widths.empty()) {
        std::string bins;
        for (const nlohmann::json& bin : widths.value("bins", nlohmann::json::array()))
            bins += (bins.empty() ? "" : ", ") + escape_html(bin.value("levels", "")) + ": " + number(bin["pixels"]);
        html += "<tr class=\"interval-widths\"><td>colour intervals</td><td>widest " + number(widths["widest"]) +
                "</td><td>pixels by width in levels: " + bins + "; wider than " + number(widths["wide_above"]) +
                " counted ambiguous</td></tr>";
    }
    for (const nlohmann::json& reason : c.value("unjudged", nlohmann::json::array()))
        html += "<tr class=\"unjudged\"><td>unjudged</td><td></td><td>" + escape_html(reason.get<std::string>()) +
                "</td></tr>";
    return html;
}

}  // namespace

std::string report_html(const std::vector<ReportRow>& rows, const std::optional<TradeoffLink>& tradeoff) {
    size_t with_genuine = 0;
    for (const ReportRow& row : rows) with_genuine += row.comparison.value("genuine_total", 0) > 0;
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<title>raster against the Embree oracle</title>\n<style>" +
                       std::string(kStyle) + "</style>\n</head>\n<body data-rows-rendered=\"0\">\n";
    html += "<h1>raster against the Embree oracle</h1>\n";
    html += "<p>" + std::to_string(rows.size()) + " scenes, " + std::to_string(with_genuine) +
            " with genuine disagreements. Diff maps: <span style=\"color:#e61414\">red</span> a genuine sample, "
            "<span style=\"color:#dc28dc\">magenta</span> a colour outside the oracle's range (hover for the "
            "bytes), <span style=\"color:#b89a00\">yellow</span> ambiguous (allowed by the precision model), grey "
            "agreeing.</p>\n";
    html += "<table class=\"report\">\n<thead><tr><th>scene</th><th>raster</th><th>oracle</th><th>diff</th>"
            "<th>samples</th></tr></thead>\n<tbody>\n";
    for (const ReportRow& row : rows) {
        const nlohmann::json& c = row.comparison;
        const bool genuine = c.value("genuine_total", 0) > 0;
        html += "<tr class=\"scene" + std::string(genuine ? " genuine" : "") + "\" data-scene=\"" +
                escape_html(row.name) + "\" data-rendered=\"no\">";
        html += "<th>" + escape_html(row.name) + "<br><small>" + number(c["width"]) + "&times;" + number(c["height"]) +
                ", " + number(c["samples"]) + " spp</small></th>";
        html += image_cell(row.raster_image, row.name + ": raster");
        html += image_cell(row.oracle_image, row.name + ": oracle");
        const nlohmann::json disagreements = c.value("color_disagreements", nlohmann::json::array());
        html += image_cell(row.diff_image, row.name + ": disagreement map",
                           " class=\"diff\" data-disagreements=\"" + escape_html(disagreements.dump()) + "\"");
        html += "<td><table class=\"counts\">";
        html += "<tr><td>agree</td><td>" + number(c["agree"]) + "</td></tr>";
        html += "<tr><td>ambiguous</td><td>" + number(c["ambiguous_total"]) + "</td><td>edge band " +
                number(c["ambiguous"]["edge_band"]) + ", depth tie " + number(c["ambiguous"]["depth_tie"]) +
                ", clip boundary " + number(c["ambiguous"]["clip_boundary"]) + ", facing " +
                number(c["ambiguous"].value("facing", 0)) + "</td></tr>";
        const nlohmann::json fractions = c.value("ambiguous_fraction", nlohmann::json::object());
        html += "<tr><td>excused</td><td>" + percent(fractions.value("total", nlohmann::json())) +
                "</td><td>edge band " + percent(fractions.value("edge_band", nlohmann::json())) + ", depth tie " +
                percent(fractions.value("depth_tie", nlohmann::json())) + ", clip boundary " +
                percent(fractions.value("clip_boundary", nlohmann::json())) + ", facing " +
                percent(fractions.value("facing", nlohmann::json())) + "</td></tr>";
        html += "<tr><td><b>genuine</b></td><td><b>" + number(c["genuine_total"]) + "</b></td><td>visibility " +
                number(c["genuine"]["visibility"]) + ", barycentrics " + number(c["genuine"]["barycentrics"]) +
                ", depth " + number(c["genuine"]["depth"]) + ", colour " + number(c["genuine"]["color"]) +
                ", shadow " + number(c["genuine"].value("shadow", nlohmann::json(0))) + ", transparency " +
                number(c["genuine"].value("transparency", nlohmann::json(0))) + "</td></tr>";
        // The open classes of the shadow and transparency models, where the scene has them.
        auto open_row = [&](const char* label, const char* key, std::initializer_list<const char*> classes) {
            const nlohmann::json open = c.value(key, nlohmann::json::object());
            if (open.empty()) return;
            std::string text;
            for (const char* name : classes)
                text += std::string(text.empty() ? "" : ", ") + name + " " + number(open.value(name, nlohmann::json(0)));
            html += std::string("<tr><td>") + label + "</td><td></td><td>" + text + " pixels</td></tr>";
        };
        open_row("shadows open", "shadows", {"edge", "depth", "inconsistent"});
        open_row("layers open", "transparency", {"edge", "depth", "order"});
        const nlohmann::json pixels = c.value("pixels", nlohmann::json::object());
        html += "<tr><td>pixels</td><td>" + number(pixels.value("judged", nlohmann::json(0))) +
                "</td><td>judged by colour; " + number(pixels.value("ambiguous", nlohmann::json(0))) +
                " left to their samples' classes</td></tr>";
        html += excuse_rows(c);
        html += "<tr><td>max colour difference</td><td>" + number(c["max_color_error"]) + "/255</td></tr>";
        html += "<tr><td>time</td><td colspan=\"2\">raster " + number(c["raster_ms"]) + " ms, oracle " +
                number(c["oracle_ms"]) + " ms (" + escape_html(c.value("oracle_mode", "")) + ")</td></tr>";
        html += "</table><div class=\"hover\"></div></td></tr>\n";
    }
    html += "</tbody>\n</table>\n";
    if (tradeoff) html += tradeoff_section(*tradeoff);
    html += "<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
    return html;
}

nlohmann::json report_summary(const std::vector<ReportRow>& rows) {
    nlohmann::json scenes = nlohmann::json::array();
    uint64_t genuine_total = 0;
    size_t with_genuine = 0;
    for (const ReportRow& row : rows) {
        nlohmann::json entry = row.comparison;
        entry["name"] = row.name;
        entry["images"] = {{"raster", row.raster_image}, {"oracle", row.oracle_image}, {"diff", row.diff_image}};
        const uint64_t genuine = row.comparison.value("genuine_total", uint64_t{0});
        genuine_total += genuine;
        with_genuine += genuine > 0;
        scenes.push_back(std::move(entry));
    }
    return {{"scenes", scenes},
            {"scene_count", rows.size()},
            {"genuine_total", genuine_total},
            {"scenes_with_genuine", with_genuine}};
}

}  // namespace raster::oracle
