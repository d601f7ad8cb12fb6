// The report's page and summary: one row per scene, escaped names, unique image names, no network references.
#include "oracle/report/report.h"

#include <gtest/gtest.h>

namespace raster::oracle {
namespace {

nlohmann::json counts(uint64_t genuine) {
    return {{"width", 8},   {"height", 6},          {"samples", 4},
            {"agree", 100}, {"ambiguous_total", 2}, {"ambiguous", {{"edge_band", 2}, {"depth_tie", 0}, {"clip_boundary", 0}}},
            {"genuine_total", genuine},
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

TEST(ReportPage, oneEscapedRowPerSceneWithItsImagesAndCounts) {
    const std::vector<ReportRow> rows = {{"cube<1>", counts(0), "c.raster.png", "c.oracle.png", "c.diff.png"},
                                         {"teapot", counts(7), "t.raster.png", "t.oracle.png", "t.diff.png"}};
    const std::string html = report_html(rows);
    size_t count = 0;
    for (size_t at = html.find("<tr class=\"scene"); at != std::string::npos; at = html.find("<tr class=\"scene", at + 1))
        ++count;
    EXPECT_EQ(count, 2u);
    EXPECT_NE(html.find("cube&lt;1&gt;"), std::string::npos);
    EXPECT_EQ(html.find("cube<1>"), std::string::npos);
    for (const char* image : {"c.raster.png", "c.oracle.png", "c.diff.png", "t.diff.png"})
        EXPECT_NE(html.find(std::string("src=\"") + image + "\""), std::string::npos) << image;
    EXPECT_NE(html.find("2 scenes, 1 with genuine disagreements"), std::string::npos);
    EXPECT_NE(html.find("scene genuine"), std::string::npos);  // the failing row is marked
    EXPECT_EQ(html.find("http:"), std::string::npos);  // self-contained: nothing from the network
    EXPECT_EQ(html.find("https:"), std::string::npos);
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
