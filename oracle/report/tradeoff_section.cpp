// The report's "Speed against accuracy" section (tradeoff_section.h).
#include "oracle/report/tradeoff_section.h"

#include "oracle/report/html_text.h"

namespace raster::oracle {

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

}  // namespace raster::oracle
