// The report's pages and summary: the index's row per scene, failing first, linking to the scene's page; the scene
// page's three images, its legend in the diff map's own colours; escaped names, unique file names, nothing from the
// network.
#include "oracle/report/report.h"

#include <cstdio>

#include <gtest/gtest.h>

#include "oracle/compare/diff_map.h"
#include "oracle/report/scene_page.h"

namespace raster::oracle {
namespace {

nlohmann::json counts(uint64_t genuine) {
    return {{"width", 8},   {"height", 6},          {"samples", 4},
            {"agree", 100}, {"ambiguous_total", 2}, {"ambiguous", {{"edge_band", 2}, {"depth_tie", 0}, {"clip_boundary", 0}}},
            {"genuine_total", genuine},
            {"genuine_reasons", genuine ? "visibility " + std::to_string(genuine) : "-"},
            {"genuine", {{"visibility", genuine}, {"barycentrics", 0}, {"depth", 0}, {"color", 0}}},
            {"max_color_error", 1}, {"raster_ms", 1.25}, {"oracle_ms", 3.5}, {"oracle_mode", "robust"}};
}

TEST(ReportPage, fileStemsArePlainAndUnique) {
    std::set<std::string> taken;
    EXPECT_EQ(unique_file_stem("teapot", taken), "teapot");
    EXPECT_EQ(unique_file_stem("teapot", taken), "teapot-2");
    EXPECT_EQ(unique_file_stem("a b<c>&d", taken), "a_b_c__d");
    EXPECT_EQ(unique_file_stem(".hidden", taken), "scene.hidden");
    EXPECT_EQ(unique_file_stem("", taken), "scene");
}

size_t count_of(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

TEST(ReportPage, theIndexHasAnEscapedRowPerSceneFailingFirstEachLinkingToItsPage) {
    const std::vector<ReportRow> rows = {{"cube<1>", counts(0), "c.raster.png", "c.oracle.png", "c.diff.png", "c.html"},
                                         {"teapot", counts(7), "t.raster.png", "t.oracle.png", "t.diff.png", "t.html"}};
    const std::string html = report_html(rows);
    EXPECT_EQ(count_of(html, "<tr class=\"scene"), 2u);
    EXPECT_NE(html.find("cube&lt;1&gt;"), std::string::npos);
    EXPECT_EQ(html.find("cube<1>"), std::string::npos);
    // The failing scene comes first although it was given second, with its reasons.
    EXPECT_LT(html.find("data-scene=\"teapot\""), html.find("data-scene=\"cube&lt;1&gt;\""));
    EXPECT_NE(html.find("<tr class=\"scene fail\" data-scene=\"teapot\""), std::string::npos);
    EXPECT_NE(html.find("data-value=\"visibility 7\">visibility 7</td>"), std::string::npos) << html;
    for (const char* link : {"href=\"c.html\"", "href=\"t.html\"", "src=\"c.diff.png\"", "src=\"t.diff.png\""})
        EXPECT_EQ(count_of(html, link), std::string(link).find("html") != std::string::npos ? 2u : 1u) << link;
    EXPECT_NE(html.find("2 scenes, 1 with genuine disagreements"), std::string::npos);
    // The reasons are the comparison's own line: a passing scene's raw counts (a class its precision modes leave
    // unjudged) give it none.
    nlohmann::json unjudged = counts(0);
    unjudged["genuine"]["visibility"] = 5;
    const std::string passing = report_html({{"float_edges", unjudged, "f.r.png", "f.o.png", "f.d.png", "f.html"}});
    EXPECT_NE(passing.find("<td class=\"why\" data-value=\"\"></td>"), std::string::npos) << passing;
    EXPECT_EQ(html.find("http:"), std::string::npos);  // self-contained: nothing from the network
    EXPECT_EQ(html.find("https:"), std::string::npos);
}

TEST(ReportPage, aScenePageShowsItsThreeImagesTheVerdictAndALegendInTheMapsOwnColours) {
    nlohmann::json c = counts(7);
    c["color_disagreements"] = nlohmann::json::array({{{"x", 1}, {"y", 2}, {"file", "a\"b.png"}}});
    const std::string html = scene_page_html({"teapot", c, "t.raster.png", "t.oracle.png", "t.diff.png", "t.html"});
    EXPECT_NE(html.find("FAIL: 7 genuine (visibility 7)"), std::string::npos);
    EXPECT_EQ(count_of(html, "src=\"t.raster.png\""), 2u);  // its pane and the swipe's
    EXPECT_EQ(count_of(html, "src=\"t.oracle.png\""), 2u);
    EXPECT_EQ(count_of(html, "src=\"t.diff.png\""), 1u);
    EXPECT_NE(html.find("width=\"8\" height=\"6\""), std::string::npos);
    EXPECT_NE(html.find("href=\"index.html\""), std::string::npos);
    EXPECT_NE(html.find("a\\&quot;b.png"), std::string::npos) << "the disagreements' JSON, escaped";
    // Every colour the map paints is named in the legend.
    for (const uint8_t* colour : {kGenuineColor, kColourDisagreementColor, kAmbiguousColor, kShadowDisagreementColor,
                                  kShadowOpenColor}) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "#%02x%02x%02x", colour[0], colour[1], colour[2]);
        EXPECT_NE(html.find(std::string("data-colour=\"") + hex + "\""), std::string::npos) << hex;
    }
    EXPECT_EQ(html.find("http:"), std::string::npos);
}

TEST(ReportPage, theSummaryAddsUpTheScenes) {
    const std::vector<ReportRow> rows = {{"a", counts(0), "a.r.png", "a.o.png", "a.d.png"},
                                         {"b", counts(7), "b.r.png", "b.o.png", "b.d.png"}};
    const nlohmann::json summary = report_summary(rows);
    EXPECT_EQ(summary["scene_count"], 2);
    EXPECT_EQ(summary["genuine_total"], 7);
    EXPECT_EQ(summary["scenes_with_genuine"], 1);
    EXPECT_EQ(summary["scenes"][1]["name"], "b");
    EXPECT_EQ(summary["scenes"][1]["images"]["diff"], "b.d.png");
}

}  // namespace
}  // namespace raster::oracle
