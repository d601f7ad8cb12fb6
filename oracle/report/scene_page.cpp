// A scene's page in the report (scene_page.h).
#include "oracle/report/scene_page.h"

#include <initializer_list>

#include "oracle/compare/diff_map.h"
#include "oracle/report/html_text.h"
#include "oracle/report/scene_page_assets.h"

namespace raster::oracle {
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

// Every count of the comparison, a row each: agree, ambiguous and excused by class, genuine by reason, the open
// classes of the shadow and transparency models, the pixels judged, the excuses against their caps, the colour
// intervals, the largest colour difference and the times.
std::string counts_table(const nlohmann::json& c) {
    std::string html = "<table class=\"counts\">";
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
    return html + "</table>\n";
}

// A pane: a frame holding the image (or images), and its caption.
std::string pane(const std::string& layer, const std::string& images, const std::string& caption,
                 const std::string& extra = "") {
    return "<figure class=\"pane" + std::string(layer == "swipe" ? " swipe\" hidden" : "\"") + " data-layer=\"" + layer +
           "\"><div class=\"frame\">" + images + "</div>" + extra + "<figcaption>" + caption + "</figcaption></figure>\n";
}

// An image of the viewer: class "view" and `classes`, its natural size as attributes, and `attributes`.
std::string view_image(const std::string& file, const std::string& alt, const nlohmann::json& c,
                       const std::string& classes = "", const std::string& attributes = "") {
    return "<img class=\"view" + (classes.empty() ? "" : " " + classes) + "\" src=\"" + escape_html(file) +
           "\" alt=\"" + escape_html(alt) + "\" width=\"" + number(c["width"]) + "\" height=\"" +
           number(c["height"]) + "\"" + attributes + ">";
}

// The disagreement map's colours and what each means (oracle/compare/diff_map.h).
std::string legend() {
    std::string html = "<p class=\"legend\">Disagreement map:";
    for (const oracle::DiffMapKey& key : oracle::diff_map_legend()) {
        const std::string colour = oracle::css_colour(key);
        html += "<span class=\"swatch\" data-colour=\"" + colour + "\" style=\"background:" + colour + "\"></span>" +
                key.meaning;
    }
    return html + "</p>\n";
}

}  // namespace

std::string scene_page_html(const ReportRow& row) {
    const nlohmann::json& c = row.comparison;
    const bool genuine = c.value("genuine_total", 0) > 0;
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                       escape_html(row.name) + ": raster against the Embree oracle</title>\n<style>" +
                       scene_page_style() + "</style>\n</head>\n<body data-rendered=\"no\" data-pixel=\"\">\n";
    html += "<p><a class=\"back\" href=\"index.html\">&larr; all scenes</a></p>\n<h1>" + escape_html(row.name) + "</h1>\n";
    html += std::string("<p class=\"verdict ") + (genuine ? "fail\">FAIL: " + number(c["genuine_total"]) +
                                                            " genuine (" + escape_html(text(c, "genuine_reasons")) + ")"
                                                      : "pass\">PASS: no genuine disagreement") + "</p>\n";
    html += "<p>" + number(c["width"]) + " &times; " + number(c["height"]) + ", " + number(c["samples"]) +
            (c.value("samples", 0) == 1 ? " sample" : " samples") + " per pixel, " + escape_html(text(c, "renderer")) + " against the oracle (" +
            escape_html(text(c, "oracle_mode")) + ")</p>\n";
    html += "<div class=\"toolbar\"><button type=\"button\" data-zoom=\"fit\">fit</button>"
            "<button type=\"button\" data-zoom=\"in\">zoom in</button>"
            "<button type=\"button\" data-zoom=\"out\">zoom out</button>"
            "<button type=\"button\" data-zoom=\"1\">1:1</button>"
            "<label><input type=\"checkbox\" class=\"swipe-toggle\"> swipe raster | oracle</label>"
            "<span class=\"zoom-level\"></span><span class=\"readout\">click a pixel to read it</span></div>\n";
    html += "<div class=\"panes\" data-width=\"" + number(c["width"]) + "\" data-height=\"" + number(c["height"]) + "\">\n";
    html += pane("raster", view_image(row.raster_image, row.name + ": raster", c), "raster");
    html += pane("oracle", view_image(row.oracle_image, row.name + ": oracle", c), "the oracle");
    const nlohmann::json disagreements = c.value("color_disagreements", nlohmann::json::array());
    html += pane("diff",
                 view_image(row.diff_image, row.name + ": disagreement map", c, "diff",
                            " data-disagreements=\"" + escape_html(disagreements.dump()) + "\""),
                 "disagreement map");
    html += pane("swipe",
                 view_image(row.raster_image, row.name + ": raster", c) +
                     view_image(row.oracle_image, row.name + ": oracle", c, "over"),
                 "raster left of the line, the oracle right of it",
                 "<input type=\"range\" class=\"swipe-slider\" min=\"0\" max=\"100\" value=\"50\" "
                 "aria-label=\"swipe between raster and the oracle\">");
    html += "</div>\n";
    html += "<div class=\"inspector\"><h2>Pixel inspector</h2><p class=\"inspector-status\">Click a pixel of any "
            "image: each of its samples' class, and what raster and the oracle each saw there.</p>"
            "<table class=\"samples\"></table></div>\n";
    html += legend();
    html += counts_table(c);
    if (!row.evidence.empty()) html += "<script src=\"" + escape_html(row.evidence) + "\"></script>\n";
    html += "<script>" + std::string(scene_page_script()) + "</script>\n</body>\n</html>\n";
    return html;
}

}  // namespace raster::oracle
