// `raster report` end to end: the report is written, and headless Chromium (Debian `chromium`, installed by
// .ci/install) opens the index and a scene page, with a script that plays a person's clicks, wheel and drags, as the
// DOM Chromium dumps once the page is idle shows: the index sorts, the scene page zooms, pans, swipes and reads the
// pixel clicked. Without Chromium the test fails: it does not skip.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/cli.h"
#include "tests/support/headless_chromium.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

using test_support::find_chromium;
using test_support::read_text;

// The DOM of the report page `page` once Chromium has loaded it and run its scripts (test_support::dom_after_scripts).
std::string report_dom(const std::string& chromium, const fs::path& work, const fs::path& page) {
    test_support::DumpOptions options;
    options.window_width = 1400;
    options.window_height = 1800;
    return test_support::dom_after_scripts(chromium, work, "file://" + fs::absolute(page).string(), options);
}

size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

// A person's use of the index, played by a script the test adds to a copy of it after the page's own: once the page
// has loaded, a click on the "scene" header, then another. The order of the rows after each is kept on <body>.
constexpr const char* kIndexScript = R"(<script>
window.addEventListener('load', () => {
  const order = () => Array.from(document.querySelectorAll('tr.scene')).map(row => row.dataset.scene).join(' ');
  const header = document.querySelector('th[data-column="scene"]');
  header.click();
  document.body.dataset.firstOrder = order() + ' / ' + document.body.dataset.sorted;
  header.click();
  document.body.dataset.secondOrder = order() + ' / ' + document.body.dataset.sorted;
});
</script>
)";

// A person's use of a scene page: a colour disagreement put at pixel (8, 5) of the diff map and a click there; the
// wheel turned once (zoom in) over raster's pane at (100, 50); a drag on the oracle's pane from (200, 100) to
// (150, 80); a click on the diff map at (300, 200); the swipe shown and its slider set to 30; then "1:1", "zoom
// in", "zoom out" twice and "fit". What the
// page shows after each step is kept on <body>, with the frame's width (the fit's scale follows from it).
constexpr const char* kScenePageScript = R"(<script>
window.addEventListener('load', () => {
  const body = document.body;
  const frame = layer => document.querySelector('.pane[data-layer="' + layer + '"] .frame');
  const at = (element, type, x, y, extra) => {
    const box = element.getBoundingClientRect();
    const init = Object.assign({clientX: box.left + x, clientY: box.top + y, bubbles: true}, extra || {});
    const event = type === 'wheel' ? new WheelEvent(type, init) : new PointerEvent(type, init);
    element.dispatchEvent(event);
    return (event.clientX - box.left) + ',' + (event.clientY - box.top);  // where it landed: whole CSS pixels
  };
  const click = (element, x, y) => { at(element, 'pointerdown', x, y); at(element, 'pointerup', x, y); };
  const readout = () => document.querySelector('.readout').textContent;
  body.dataset.frameWidth = String(frame('diff').clientWidth);
  body.dataset.fitZoom = body.dataset.zoom;
  document.querySelector('img.diff').dataset.disagreements = JSON.stringify([{x: 8, y: 5, file: 'first.png',
      raster: [250, 10, 10], allowed: [[0, 5], [0, 6], [1, 7]], oracle: [2, 3, 4]}]);
  const scale = Number(body.dataset.zoom);
  click(frame('diff'), 8.5 * scale, 5.5 * scale);
  body.dataset.firstReadout = readout();
  body.dataset.wheelAt = at(frame('raster'), 'wheel', 100, 50, {deltaY: -100});
  body.dataset.wheelZoom = body.dataset.zoom;
  body.dataset.dragFrom = at(frame('oracle'), 'pointerdown', 200, 100);
  body.dataset.dragTo = at(frame('oracle'), 'pointermove', 150, 80);
  at(frame('oracle'), 'pointerup', 150, 80);
  body.dataset.dragPan = body.dataset.pan;
  const transforms = new Set(Array.from(document.querySelectorAll('img.view')).map(image => image.style.transform));
  body.dataset.transforms = String(transforms.size);
  body.dataset.clickAt = at(frame('diff'), 'pointerdown', 300, 200);
  at(frame('diff'), 'pointerup', 300, 200);
  body.dataset.secondPixel = body.dataset.pixel;
  const toggle = document.querySelector('.swipe-toggle');
  toggle.checked = true;
  toggle.dispatchEvent(new Event('change'));
  const slider = document.querySelector('.swipe-slider');
  slider.value = '30';
  slider.dispatchEvent(new Event('input'));
  body.dataset.swipeShown = String(!document.querySelector('.pane.swipe').hidden);
  body.dataset.clip = document.querySelector('.pane.swipe img.over').style.clipPath;
  document.querySelector('button[data-zoom="1"]').click();
  body.dataset.actualZoom = body.dataset.zoom;
  document.querySelector('button[data-zoom="in"]').click();
  body.dataset.inZoom = body.dataset.zoom;
  document.querySelector('button[data-zoom="out"]').click();
  document.querySelector('button[data-zoom="out"]').click();
  body.dataset.outZoom = body.dataset.zoom;
  document.querySelector('button[data-zoom="fit"]').click();
  body.dataset.refitZoom = body.dataset.zoom;
});
</script>
)";

// `page` with `script` added at the end of its body, written beside it (so its images resolve the same).
fs::path with_script(const fs::path& page, const char* script) {
    std::string html = read_text(page);
    const size_t end = html.rfind("</body>");
    EXPECT_NE(end, std::string::npos);
    html.insert(end == std::string::npos ? html.size() : end, script);
    const fs::path driven = page.parent_path() / ("driven-" + page.filename().string());
    std::ofstream(driven, std::ios::binary) << html;
    return driven;
}

// The value of <body>'s attribute `name` in a dumped DOM ("" when it is missing).
std::string body_data(const std::string& dom, const std::string& name) {
    const size_t body = dom.find("<body");
    const std::string key = " " + name + "=\"";
    const size_t start = dom.find(key, body);
    if (body == std::string::npos || start == std::string::npos || start > dom.find('>', body)) return "";
    const size_t end = dom.find('"', start + key.size());
    return dom.substr(start + key.size(), end - start - key.size());
}

class ReportInChromium : public ::testing::Test {
protected:
    void SetUp() override {
        work = fs::temp_directory_path() / ("raster_report_test_" + std::to_string(::getpid()));
        fs::remove_all(work);
        fs::create_directories(work);
    }
    void TearDown() override { fs::remove_all(work); }
    fs::path work;
};

TEST_F(ReportInChromium, theIndexSortsAndEachScenePageZoomsPansSwipesAndReadsPixels) {
    const std::string chromium = find_chromium();
    ASSERT_FALSE(chromium.empty()) << "chromium is not installed (bash .ci/install installs it)";

    const fs::path dir = work / "report";
    std::ostringstream out, err;
    const int code = run({"raster", "report", kCorpus + "single_triangle.yaml", kCorpus + "interpenetrating.yaml",
                          kCorpus + "perspective_quad.yaml", "-o", dir.string()},
                         out, err);
    ASSERT_EQ(code, 0) << err.str();
    EXPECT_NE(out.str().find("3 scenes, 0 with genuine disagreements"), std::string::npos) << out.str();
    const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "summary.json"));
    ASSERT_EQ(summary["scene_count"], 3);
    EXPECT_EQ(summary["scenes"][0]["name"], "single_triangle");
    EXPECT_EQ(summary["scenes"][0]["page"], "single_triangle.html");
    for (const auto& scene : summary["scenes"]) {
        for (const char* image : {"raster", "oracle", "diff"})
            EXPECT_TRUE(fs::exists(dir / scene["images"][image].get<std::string>())) << scene["name"] << " " << image;
        EXPECT_TRUE(fs::exists(dir / scene["page"].get<std::string>())) << scene["name"];
    }

    // The index: every row's thumbnail decoded, and a click on a header sorts by it, a second click reverses.
    const std::string index = report_dom(chromium, work, with_script(dir / "index.html", kIndexScript));
    EXPECT_EQ(body_data(index, "data-rows-rendered"), "3") << index.substr(0, 2000);
    EXPECT_EQ(occurrences(index, "data-rendered=\"yes\""), 3u);
    EXPECT_EQ(body_data(index, "data-first-order"),
              "interpenetrating perspective_quad single_triangle / scene ascending");
    EXPECT_EQ(body_data(index, "data-second-order"),
              "single_triangle perspective_quad interpenetrating / scene descending");

    // A scene page (single_triangle, 320 x 240): fitted to its frame on load, a click reads the pixel under it, the
    // wheel zooms by 5/4 about the pointer, a drag pans, and every pane moves as one.
    const std::string page = report_dom(chromium, work, with_script(dir / "single_triangle.html", kScenePageScript));
    EXPECT_EQ(body_data(page, "data-rendered"), "yes") << page.substr(0, 2000);
    const double frame_width = std::stod(body_data(page, "data-frame-width"));
    const double fit = frame_width / 320.0;
    EXPECT_NEAR(std::stod(body_data(page, "data-fit-zoom")), fit, 1e-9);
    EXPECT_EQ(body_data(page, "data-first-readout"), "(8, 5) first.png: raster 250 10 10, allowed 0-5 0-6 1-7, oracle 2 3 4");
    // Events land on whole CSS pixels of the page: each step's point is where its event landed in its frame.
    const auto point = [&](const std::string& name) {
        const std::string text = body_data(page, name);
        const size_t comma = text.find(',');
        EXPECT_NE(comma, std::string::npos) << name << ": " << text;
        return comma == std::string::npos ? std::pair{0.0, 0.0}
                                          : std::pair{std::stod(text.substr(0, comma)), std::stod(text.substr(comma + 1))};
    };
    const double zoomed = fit * 1.25;
    EXPECT_NEAR(std::stod(body_data(page, "data-wheel-zoom")), zoomed, 1e-9);
    // The image point under the wheel stays there: the pan moves by that point times (1 - 5/4); the drag adds its move.
    const auto [wheel_x, wheel_y] = point("data-wheel-at");
    const auto [from_x, from_y] = point("data-drag-from");
    const auto [to_x, to_y] = point("data-drag-to");
    const double pan_x = -0.25 * wheel_x + (to_x - from_x), pan_y = -0.25 * wheel_y + (to_y - from_y);
    const auto [dragged_x, dragged_y] = point("data-drag-pan");
    EXPECT_NEAR(dragged_x, pan_x, 1e-9);
    EXPECT_NEAR(dragged_y, pan_y, 1e-9);
    EXPECT_EQ(body_data(page, "data-transforms"), "1") << "every pane shares one zoom and pan";
    const auto [click_x, click_y] = point("data-click-at");
    const int x = static_cast<int>(std::floor((click_x - pan_x) / zoomed)), y = static_cast<int>(std::floor((click_y - pan_y) / zoomed));
    EXPECT_EQ(body_data(page, "data-second-pixel"), std::to_string(x) + "," + std::to_string(y));
    EXPECT_EQ(body_data(page, "data-swipe-shown"), "true");
    EXPECT_EQ(body_data(page, "data-swipe"), "30");
    EXPECT_EQ(body_data(page, "data-clip"), "inset(0px 0px 0px 30%)");
    EXPECT_EQ(body_data(page, "data-actual-zoom"), "1");
    // The toolbar's zoom in doubles the scale, zoom out halves it, and fit returns to the fit's scale.
    EXPECT_EQ(body_data(page, "data-in-zoom"), "2");
    EXPECT_EQ(body_data(page, "data-out-zoom"), "0.5");
    EXPECT_EQ(body_data(page, "data-refit-zoom"), body_data(page, "data-fit-zoom"));

    // The check can fail: with one image gone, the page is no longer marked rendered, nor its index row.
    fs::remove(dir / "single_triangle.oracle.png");
    EXPECT_EQ(body_data(report_dom(chromium, work, dir / "single_triangle.html"), "data-rendered"), "no");
    fs::remove(dir / "interpenetrating.diff.png");
    EXPECT_EQ(body_data(report_dom(chromium, work, dir / "index.html"), "data-rows-rendered"), "2");
}

// A script that, once the scene page has loaded, zooms about pixel (x, y) and clicks its centre on the diff map,
// then marks the body with what the inspector shows (data-pixel, data-inspected: a row per sample, its class,
// triangles, excuse, figure and bound; data-pixel-status), then fits and clicks pixel (0, 0) (data-corner-status).
// At the fit's scale a pixel is under one CSS pixel, and events land on whole CSS pixels: the script first zooms
// about the pixel (ten turns of the wheel, 9.3 times), then clicks its centre where the page now draws it.
std::string click_pixel_script(const std::string& x, const std::string& y) {
    return "<script>\nwindow.addEventListener('load', () => {\n"
           "  const body = document.body, frame = document.querySelector('.pane[data-layer=\"diff\"] .frame');\n"
           "  const box = frame.getBoundingClientRect();\n"
           "  const centre = (px, py) => { const [panX, panY] = body.dataset.pan.split(',').map(Number), z = Number(body.dataset.zoom);\n"
           "    return {clientX: box.left + panX + px * z, clientY: box.top + panY + py * z, bubbles: true}; };\n"
           "  for (let turn = 0; turn < 10; ++turn)\n"
           "    frame.dispatchEvent(new WheelEvent('wheel', Object.assign(centre(" + x + " + 0.5, " + y + " + 0.5), {deltaY: -1})));\n"
           "  for (const type of ['pointerdown', 'pointerup']) frame.dispatchEvent(new PointerEvent(type, centre(" + x +
           " + 0.5, " + y + " + 0.5)));\n"
           "  const rows = Array.from(document.querySelectorAll('table.samples tr')).slice(1);\n"
           "  body.dataset.inspected = body.dataset.pixel + ': ' + rows.map(row => row.cells[1].textContent + ' ' +\n"
           "    row.cells[2].textContent + ' ' + row.cells[5].textContent + ' ' + row.cells[8].textContent + ' ' +\n"
           "    row.cells[9].textContent + ' ' + row.cells[10].textContent).join('; ');\n"
           "  body.dataset.pixelStatus = document.querySelector('.inspector-status').textContent;\n"
           "  document.querySelector('button[data-zoom=\"fit\"]').click();\n"
           "  for (const type of ['pointerdown', 'pointerup']) frame.dispatchEvent(new PointerEvent(type, centre(0.5, 0.5)));\n"
           "  body.dataset.cornerStatus = document.querySelector('.inspector-status').textContent;\n"
           "});\n</script>\n";
}

// The inspector: the test reads the evidence file the report wrote beside the teapot's page, picks its first pixel,
// and a script clicks that pixel's centre on the diff map; the inspector must show the pixel's state and bytes on
// both sides, and a row per sample with the class, triangles and excuse (its figure and bound) the file gives. A
// pixel the file does not list shows as every sample agreeing.
TEST_F(ReportInChromium, theInspectorShowsEachSampleOfTheClickedPixel) {
    const std::string chromium = find_chromium();
    ASSERT_FALSE(chromium.empty()) << "chromium is not installed (bash .ci/install installs it)";
    const fs::path dir = work / "report";
    std::ostringstream out, err;
    ASSERT_EQ(run({"raster", "report", kCorpus + "teapot.yaml", "--samples", "4", "-o", dir.string()}, out, err), 0)
        << err.str();
    const std::string script = read_text(dir / "teapot.evidence.js");
    const std::string prefix = "window.rasterEvidence = ";
    ASSERT_EQ(script.rfind(prefix, 0), 0u);
    const nlohmann::json evidence = nlohmann::json::parse(script.substr(prefix.size(), script.rfind(';') - prefix.size()));
    ASSERT_EQ(evidence["samples"], 4);
    ASSERT_FALSE(evidence["pixels"].empty()) << "the teapot at 4 samples has edge-band samples";
    const std::string key = evidence["pixels"].begin().key();
    const nlohmann::json& pixel = evidence["pixels"][key];
    const nlohmann::json& samples = pixel["samples"];
    const std::string x = key.substr(0, key.find(',')), y = key.substr(key.find(',') + 1);
    const std::string click = click_pixel_script(x, y);
    const std::string dom = report_dom(chromium, work, with_script(dir / "teapot.html", click.c_str()));
    std::string want = key + ": ";
    for (size_t k = 0; k < samples.size(); ++k) {
        const auto triangle = [](const nlohmann::json& t) { return t.get<int64_t>() < 0 ? std::string("none") : t.dump(); };
        const auto figure = [](const nlohmann::json& f) { return f.is_null() ? std::string("-") : f.dump(); };
        want += (k ? "; " : "") + samples[k][0].get<std::string>() + " " + triangle(samples[k][1]) + " " +
                triangle(samples[k][4]) + " " + samples[k][7].get<std::string>() + " " + figure(samples[k][8]) + " " +
                figure(samples[k][9]);
    }
    const auto bytes = [](const nlohmann::json& b) {
        return std::to_string(b[0].get<int>()) + " " + std::to_string(b[1].get<int>()) + " " + std::to_string(b[2].get<int>());
    };
    ASSERT_EQ(pixel["state"], "ambiguous") << "an edge-band pixel of the teapot";
    EXPECT_EQ(body_data(dom, "data-pixel-status"),
              "Pixel (" + x + ", " + y + "): ambiguous, 4 samples. raster " + bytes(pixel["raster"]) + ", oracle " +
                  bytes(pixel["oracle"]) + ", allowed none: not judged (ambiguous). colour: " +
                  pixel["colour"].get<std::string>() + ".");
    EXPECT_EQ(body_data(dom, "data-inspected"), want) << dom.substr(0, 3000);
    // The corner pixel (0, 0) is background on both sides: not listed, every sample agreeing.
    EXPECT_EQ(evidence["pixels"].count("0,0"), 0u);
    EXPECT_EQ(body_data(dom, "data-corner-status"), "Pixel (0, 0): every one of its 4 samples agrees with the oracle and its colour is inside its "
              "interval.");
}

// With shadows and glass: a pixel the shadow model or the layers left open shows those verdicts in the inspector.
TEST_F(ReportInChromium, theInspectorShowsAPixelsShadowAndLayerVerdicts) {
    const std::string chromium = find_chromium();
    ASSERT_FALSE(chromium.empty()) << "chromium is not installed (bash .ci/install installs it)";
    const fs::path dir = work / "report";
    std::ostringstream out, err;
    ASSERT_EQ(run({"raster", "report", kCorpus + "shadows_and_glass.yaml", "-o", dir.string()}, out, err), 0) << err.str();
    const std::string script = read_text(dir / "shadows_and_glass.evidence.js");
    const std::string prefix = "window.rasterEvidence = ";
    const nlohmann::json evidence = nlohmann::json::parse(script.substr(prefix.size(), script.rfind(';') - prefix.size()));
    // The first pixel the shadow model left open, and the first the layers left open.
    std::string shadow_key, layer_key;
    for (const auto& [at, pixel] : evidence["pixels"].items()) {
        if (shadow_key.empty() && pixel["shadows"].dump().find("open_") != std::string::npos) shadow_key = at;
        if (layer_key.empty() && !pixel["layers"].is_null()) layer_key = at;
    }
    ASSERT_FALSE(shadow_key.empty()) << "the scene's shadow edges leave some pixel open";
    ASSERT_FALSE(layer_key.empty()) << "the glass's edges leave some pixel open";
    for (const std::string& key : {shadow_key, layer_key}) {
        const nlohmann::json& pixel = evidence["pixels"][key];
        const std::string x = key.substr(0, key.find(',')), y = key.substr(key.find(',') + 1);
        const std::string dom =
            report_dom(chromium, work, with_script(dir / "shadows_and_glass.html", click_pixel_script(x, y).c_str()));
        const std::string status = body_data(dom, "data-pixel-status");
        std::string verdicts, allowed;
        for (const auto& verdict : pixel["shadows"]) verdicts += (verdicts.empty() ? "" : ", ") + verdict.get<std::string>();
        for (const auto& range : pixel["allowed"])
            allowed += (allowed.empty() ? "" : " ") + range[0].dump() + "-" + range[1].dump();
        EXPECT_NE(status.find("Pixel (" + x + ", " + y + "): " + pixel["state"].get<std::string>()), std::string::npos)
            << status;
        EXPECT_NE(status.find("shadow verdicts met: " + (verdicts.empty() ? "none" : verdicts) + "."), std::string::npos)
            << status;
        EXPECT_NE(status.find("transparent layers: " + (pixel["layers"].is_null()
                                                            ? std::string("decided")
                                                            : "left open by " + pixel["layers"].get<std::string>()) + "."),
                  std::string::npos) << status;
        if (!allowed.empty()) EXPECT_NE(status.find("allowed " + allowed + "."), std::string::npos) << status;
    }
}

TEST_F(ReportInChromium, badInputExitsTwoBeforeWritingAnything) {
    std::ostringstream out, err;
    const fs::path dir = work / "report";
    EXPECT_EQ(run({"raster", "report", kCorpus + "single_triangle.yaml", (work / "missing.yaml").string(), "-o",
                   dir.string()},
                  out, err),
              2);
    EXPECT_NE(err.str().find("missing.yaml"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir));
    EXPECT_EQ(run({"raster", "report", kCorpus + "single_triangle.yaml"}, out, err), 2);  // -o is required
}

TEST_F(ReportInChromium, aDirectoryInputContributesEverySceneInIt) {
    std::ostringstream out, err;
    const fs::path scenes = work / "scenes";
    fs::create_directories(scenes);
    fs::copy_file(kCorpus + "single_triangle.yaml", scenes / "b.yaml");
    fs::copy_file(kCorpus + "interpenetrating.yaml", scenes / "a.yaml");
    fs::copy_file(kCorpus + "single_triangle.yaml", scenes / "notes.txt");  // not a scene file
    ASSERT_EQ(run({"raster", "report", scenes.string(), "-o", (work / "report").string(), "--samples", "4"}, out, err), 0)
        << err.str();
    const nlohmann::json summary = nlohmann::json::parse(read_text(work / "report" / "summary.json"));
    ASSERT_EQ(summary["scene_count"], 2);
    EXPECT_EQ(summary["scenes"][0]["name"], "a");
    EXPECT_EQ(summary["scenes"][1]["name"], "b");
    EXPECT_EQ(summary["scenes"][0]["samples"], 4);
}

}  // namespace
}  // namespace raster::cli
