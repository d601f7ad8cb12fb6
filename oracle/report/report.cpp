// The comparison report's index page (a summary table, a row a scene, linking to each scene's page) and summary.
#include "oracle/report/report.h"

#include <algorithm>

#include "oracle/report/html_text.h"
#include "oracle/report/tradeoff_section.h"

namespace raster::oracle {
namespace {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
table.summary { border-collapse: collapse; }
table.summary th, table.summary td { padding: 0.3em 0.7em; border-bottom: 1px solid #ddd; text-align: right;
                                     vertical-align: middle; }
table.summary th:first-child, table.summary td:first-child, table.summary td.why, table.summary td.text { text-align: left; }
table.summary thead th { cursor: pointer; user-select: none; background: #eee; }
table.summary thead th[aria-sort="ascending"]::after { content: " \25B2"; }
table.summary thead th[aria-sort="descending"]::after { content: " \25BC"; }
tr.fail td.verdict { color: #c00; font-weight: bold; }
tr.pass td.verdict { color: #176317; }
table.summary img { width: 96px; height: auto; image-rendering: pixelated; background: #000; display: block; }
img.pareto { max-width: 100%; height: auto; border: 1px solid #ccc; background: #fff; }
table.tradeoff { border-collapse: collapse; margin-bottom: 1em; }
table.tradeoff th, table.tradeoff td { padding: 0.15em 0.6em; text-align: right; border-bottom: 1px solid #e4e4e4; }
table.tradeoff th:first-child, table.tradeoff td:first-child { text-align: left; }
table.tradeoff tr.on-front td { color: #a01010; font-weight: bold; }
)";

// Marks each row data-rendered once its thumbnail has loaded (and counts them on <body>), and sorts the table by
// the column whose header is clicked: by each cell's data-value, numerically when every value is a number, the
// second click on the same header reversing the order. <body data-sorted> names the column and the direction.
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
function sortBy(header) {
  const table = header.closest('table'), body = table.tBodies[0];
  const column = Array.from(header.parentNode.children).indexOf(header);
  const descending = header.getAttribute('aria-sort') === 'ascending';
  for (const other of header.parentNode.children) other.removeAttribute('aria-sort');
  header.setAttribute('aria-sort', descending ? 'descending' : 'ascending');
  const rows = Array.from(body.rows);
  const value = row => row.cells[column].dataset.value;
  const numeric = rows.every(row => value(row) !== '' && !isNaN(Number(value(row))));
  rows.sort((a, b) => {
    const order = numeric ? Number(value(a)) - Number(value(b)) : value(a).localeCompare(value(b));
    return descending ? -order : order;
  });
  for (const row of rows) body.appendChild(row);
  document.body.dataset.sorted = header.dataset.column + ' ' + (descending ? 'descending' : 'ascending');
}
for (const header of document.querySelectorAll('table.summary thead th')) header.addEventListener('click', () => sortBy(header));
)";

// A cell with the value the table sorts it by.
std::string cell(const std::string& shown, const std::string& value, const std::string& classes = "") {
    return "<td" + (classes.empty() ? "" : " class=\"" + classes + "\"") + " data-value=\"" + escape_html(value) +
           "\">" + shown + "</td>";
}

std::string value_of(const nlohmann::json& value) { return value.is_number() ? value.dump() : ""; }

// The summary table's columns: its data-column name and header.
constexpr std::pair<const char*, const char*> kColumns[] = {
    {"scene", "scene"},          {"verdict", "verdict"},
    {"why", "why"},              {"genuine", "genuine"},
    {"ambiguous", "ambiguous"},  {"excused", "excused share"},
    {"widest", "widest colour interval"}, {"samples", "samples"},
    {"renderer", "renderer"},    {"raster_ms", "raster ms"},
    {"oracle_ms", "oracle ms"},  {"diff", "diff map"},
};

std::string summary_row(const ReportRow& row) {
    const nlohmann::json& c = row.comparison;
    const bool genuine = c.value("genuine_total", 0) > 0;
    const std::string link = "<a href=\"" + escape_html(row.page) + "\">" + escape_html(row.name) + "</a>";
    std::string html = "<tr class=\"scene " + std::string(genuine ? "fail" : "pass") + "\" data-scene=\"" +
                       escape_html(row.name) + "\" data-rendered=\"no\">";
    html += cell(link, row.name);
    html += cell(genuine ? "FAIL" : "pass", genuine ? "0 fail" : "1 pass", "verdict");
    // The reasons as the comparison counts them: only the classes its precision modes let the oracle judge.
    const std::string why = genuine ? text(c, "genuine_reasons") : "";
    html += cell(escape_html(why), why, "why");
    html += cell(number(field(c, "genuine_total")), value_of(field(c, "genuine_total")));
    html += cell(number(field(c, "ambiguous_total")), value_of(field(c, "ambiguous_total")));
    const nlohmann::json excused = field(field(c, "ambiguous_fraction"), "total");
    html += cell(percent(excused), value_of(excused));
    const nlohmann::json widest = field(field(c, "interval_widths"), "widest");
    html += cell(widest.is_number() ? number(widest) + "/255" : "-", value_of(widest));
    html += cell(number(field(c, "samples")), value_of(field(c, "samples")));
    html += cell(escape_html(text(c, "renderer")), text(c, "renderer"), "text");
    html += cell(fixed(field(c, "raster_ms"), 1), value_of(field(c, "raster_ms")));
    html += cell(fixed(field(c, "oracle_ms"), 1), value_of(field(c, "oracle_ms")));
    html += cell("<a href=\"" + escape_html(row.page) + "\"><img src=\"" + escape_html(row.diff_image) + "\" alt=\"" +
                     escape_html(row.name + ": disagreement map") + "\"></a>",
                 row.name);
    return html + "</tr>\n";
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


std::string report_html(const std::vector<ReportRow>& rows, const std::optional<TradeoffLink>& tradeoff) {
    size_t with_genuine = 0;
    for (const ReportRow& row : rows) with_genuine += row.comparison.value("genuine_total", 0) > 0;
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<title>raster against the Embree oracle</title>\n<style>" +
                       std::string(kStyle) + "</style>\n</head>\n<body data-rows-rendered=\"0\" data-sorted=\"\">\n";
    html += "<h1>raster against the Embree oracle</h1>\n";
    html += "<p>" + std::to_string(rows.size()) + " scenes, " + std::to_string(with_genuine) +
            " with genuine disagreements (listed first). A genuine disagreement is a sample or pixel the oracle's "
            "precision model cannot explain; ambiguous ones it can. Click a header to sort, a scene for its images, "
            "zoom and counts.</p>\n";
    html += "<table class=\"summary\">\n<thead><tr>";
    for (const auto& [column, title] : kColumns) html += "<th data-column=\"" + std::string(column) + "\">" + title + "</th>";
    html += "</tr></thead>\n<tbody>\n";
    // Failing scenes first, each group in the order given.
    std::vector<const ReportRow*> order;
    for (const ReportRow& row : rows) order.push_back(&row);
    std::stable_sort(order.begin(), order.end(), [](const ReportRow* a, const ReportRow* b) {
        return a->comparison.value("genuine_total", 0) > 0 && !(b->comparison.value("genuine_total", 0) > 0);
    });
    for (const ReportRow* row : order) html += summary_row(*row);
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
        entry["page"] = row.page;
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
