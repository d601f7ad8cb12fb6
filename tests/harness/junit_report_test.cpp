// The JUnit XML of comparisons: valid against the common schema (tests/support/junit.xsd, checked by xmllint), a
// case per scene, failed exactly when the scene has genuine disagreements and naming their counts, and text escaped
// so that any scene name or summary stays well-formed XML.
#include "harness/comparison/junit_report.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "harness/comparison/comparison_output.h"
#include "raster/compat/scene_loader.h"

namespace raster {
namespace {

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

// raster's frame with its image's red channel halved: a renderer behind the seam whose colours are off.
class RedHalved final : public Renderer {
public:
    std::string name() const override { return "raster, red halved"; }
    bool gives_visibility() const override { return true; }
    void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const override {
        RasterRenderer{}.render_into(scene, options, result);
        for (int y = 0; y < result.image.height; ++y)
            for (int x = 0; x < result.image.width; ++x) result.image.at(x, y)[0] *= 0.5f;
    }
};

// xmllint's verdict on `xml` against the schema: 0 when it validates.
int validate(const std::string& xml) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("raster_junit_" + std::to_string(getpid()) + ".xml");
    std::ofstream(file) << xml;
    const std::string command = "xmllint --noout --schema '" + (kSource / "tests/support/junit.xsd").string() + "' '" +
                                file.string() + "' > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    std::filesystem::remove(file);
    return status;
}

size_t count_of(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

TEST(JunitReport, aCasePerSceneFailedExactlyWhereTheOracleFoundGenuineDisagreements) {
    const std::string path = (kSource / "corpus/scenes/single_triangle.yaml").string();
    const Scene scene = load_scene(path);
    const harness::Comparison clean = harness::compare_scene(scene, harness::ComparisonOptions{});
    const RedHalved red_halved;
    harness::ComparisonOptions options;
    options.renderer = &red_halved;
    const harness::Comparison off = harness::compare_scene(scene, options);
    ASSERT_EQ(clean.genuine_total(), 0u);
    ASSERT_GT(off.genuine_total(), 0u);

    // Named as a user names it on the command line, relative to the project.
    const std::string named = "corpus/scenes/single_triangle.yaml";
    const harness::JunitCase passed = harness::junit_case(clean, named), failed = harness::junit_case(off, named);
    EXPECT_EQ(passed.classname, "corpus.scenes");
    EXPECT_EQ(passed.name, "single_triangle.yaml, " + std::to_string(clean.samples) +
                               (clean.samples == 1 ? " sample, raster" : " samples, raster"));
    EXPECT_EQ(failed.message, std::to_string(off.genuine_total()) + " genuine: " + harness::genuine_reasons(off));
    const std::string xml = harness::junit_xml("raster report", {passed, failed}, "2026-12-07T15:04:05", "ci-host");
    EXPECT_EQ(validate(xml), 0) << xml;
    EXPECT_NE(xml.find("<testsuite name=\"raster report\" tests=\"2\" failures=\"1\" errors=\"0\""), std::string::npos)
        << xml;
    EXPECT_EQ(count_of(xml, "<testcase "), 2u);
    EXPECT_EQ(count_of(xml, "<failure "), 1u);
    EXPECT_NE(xml.find("<failure message=\"" + failed.message + "\""), std::string::npos) << xml;
    EXPECT_EQ(harness::junit_case(clean, "/abs/olute/x.yaml").classname, "abs.olute");
    EXPECT_EQ(harness::junit_case(clean, "x.yaml").classname, "raster");
}

TEST(JunitReport, anyTextStaysWellFormedXml) {
    harness::JunitCase odd;
    odd.classname = "a.b";
    odd.name = "<scene> & \"its\" 'flags'\x01\x1f";
    odd.seconds = 1.25;
    odd.genuine = 3;
    odd.message = "3 genuine: color 3 <&>";
    odd.details = "pixel (1, 2): raster [255 0 0], allowed [0, 10]\n]]> and \x02";
    odd.output = "summary & more";
    const std::string xml = harness::junit_xml("raster compare", {odd}, "2026-12-07T15:04:05", "host<1>");
    EXPECT_EQ(validate(xml), 0) << xml;
    EXPECT_NE(xml.find("name=\"&lt;scene&gt; &amp; &quot;its&quot; &apos;flags&apos;??\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("time=\"1.250\""), std::string::npos);
    // The schema is not vacuous: a suite without its host, or a case without its time, does not validate.
    std::string no_host = xml;
    no_host.replace(no_host.find(" hostname="), std::string(" hostname=\"host&lt;1&gt;\"").size(), "");
    EXPECT_NE(validate(no_host), 0) << no_host;
    std::string no_time = xml;
    const size_t at = no_time.find(" time=\"1.250\">", no_time.find("<testcase "));
    no_time.replace(at, std::string(" time=\"1.250\"").size(), "");
    EXPECT_NE(validate(no_time), 0);
}

}  // namespace
}  // namespace raster
