// The trade-off plot as hand-written SVG: axes with ticks, labelled points, the Pareto front as a staircase.
#include "harness/tradeoff/pareto_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raster::harness {
namespace {

constexpr double kPanelWidth = 800, kPanelHeight = 500;
constexpr double kLeft = 70, kRight = 130, kTop = 50, kBottom = 110;  // margins around the plot area
constexpr double kPlotWidth = kPanelWidth - kLeft - kRight, kPlotHeight = kPanelHeight - kTop - kBottom;
constexpr double kCharWidth = 6.2, kLineHeight = 12;  // 11 px sans-serif, roughly

std::string escape_xml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string num(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

std::string tick_label(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// A time with about three significant digits and no exponent: 0.523, 31.3, 1208.
std::string milliseconds(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, ms < 10 ? "%.3g" : ms < 100 ? "%.1f" : "%.0f", ms);
    return text;
}

// A "nice" step (1, 2 or 5 times a power of ten) near range / 5.
double nice_step(double range) {
    const double raw = range / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power) return m * power;
    return 10.0 * power;
}

struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// One panel at vertical offset `top`.
std::string panel(const SceneTradeoff& scene, int reference_grid, double top) {
    std::string svg = "<g transform=\"translate(0," + num(top) + ")\">\n";
    char title[512];
    std::snprintf(title, sizeof title, "%s (%dx%d, %zu triangles): frame time against colour error", scene.name.c_str(),
                  scene.width, scene.height, scene.triangles);
    svg += "<text x=\"" + num(kLeft) + "\" y=\"24\" font-size=\"15\" font-weight=\"bold\">" + escape_xml(title) +
           "</text>\n";
    if (scene.modes.empty()) return svg + "<text x=\"" + num(kLeft) + "\" y=\"60\">no modes measured</text>\n</g>\n";

    // x: log10 of the median time, padded; y: RMSE from 0.
    double lo = INFINITY, hi = -INFINITY, max_error = 0;
    for (const ModeResult& m : scene.modes) {
        const double l = std::log10(std::max(m.median_ms, 1e-6));
        lo = std::min(lo, l);
        hi = std::max(hi, l);
        max_error = std::max(max_error, m.color_rmse);
    }
    const double pad = std::max(0.05 * (hi - lo), 0.1);
    lo -= pad;
    hi += pad;
    const double y_step = nice_step(max_error > 0 ? max_error * 1.1 : 1.0);
    const double y_max = std::ceil((max_error > 0 ? max_error * 1.1 : 1.0) / y_step) * y_step;
    auto px = [&](double ms) { return kLeft + (std::log10(std::max(ms, 1e-6)) - lo) / (hi - lo) * kPlotWidth; };
    auto py = [&](double error) { return kTop + kPlotHeight - error / y_max * kPlotHeight; };

    // Frame, grid and ticks.
    svg += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(kTop) + "\" width=\"" + num(kPlotWidth) + "\" height=\"" +
           num(kPlotHeight) + "\" fill=\"white\" stroke=\"#444\"/>\n";
    std::vector<double> x_ticks;
    for (const std::vector<double>& mantissas :
         {std::vector<double>{1, 2, 5}, std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
        x_ticks.clear();
        for (int decade = int(std::floor(lo)); decade <= int(std::ceil(hi)); ++decade)
            for (double m : mantissas) {
                const double value = m * std::pow(10.0, decade), l = std::log10(value);
                if (l >= lo && l <= hi) x_ticks.push_back(value);
            }
        if (x_ticks.size() >= 3) break;
    }
    for (double value : x_ticks) {
        const double x = px(value);
        svg += "<line x1=\"" + num(x) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(x) + "\" y2=\"" +
               num(kTop + kPlotHeight) + "\" stroke=\"#e4e4e4\"/>\n";
        svg += "<text x=\"" + num(x) + "\" y=\"" + num(kTop + kPlotHeight + 16) +
               "\" font-size=\"11\" text-anchor=\"middle\">" + tick_label(value) + "</text>\n";
    }
    for (double value = 0; value <= y_max * (1 + 1e-9); value += y_step) {
        const double y = py(value);
        svg += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(y) + "\" x2=\"" + num(kLeft + kPlotWidth) + "\" y2=\"" +
               num(y) + "\" stroke=\"#e4e4e4\"/>\n";
        svg += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(y + 4) + "\" font-size=\"11\" text-anchor=\"end\">" +
               tick_label(value) + "</text>\n";
    }
    svg += "<text x=\"" + num(kLeft + kPlotWidth / 2) + "\" y=\"" + num(kTop + kPlotHeight + 36) +
           "\" font-size=\"12\" text-anchor=\"middle\">median frame time, ms (log scale)</text>\n";
    const std::string grid = std::to_string(reference_grid);
    svg += "<text transform=\"translate(18," + num(kTop + kPlotHeight / 2) +
           ") rotate(-90)\" font-size=\"12\" text-anchor=\"middle\">colour RMSE against the " + grid + "x" + grid +
           " oracle (0-255)</text>\n";

    // The front as a staircase, fastest first: the best error reachable within each time budget.
    std::vector<const ModeResult*> front;
    for (const ModeResult& m : scene.modes)
        if (m.on_front) front.push_back(&m);
    std::stable_sort(front.begin(), front.end(), [](const ModeResult* a, const ModeResult* b) {
        return a->median_ms < b->median_ms || (a->median_ms == b->median_ms && a->color_rmse > b->color_rmse);
    });
    if (!front.empty()) {
        std::string path = "M" + num(px(front[0]->median_ms)) + " " + num(py(front[0]->color_rmse));
        for (size_t i = 1; i < front.size(); ++i)
            path += " H" + num(px(front[i]->median_ms)) + " V" + num(py(front[i]->color_rmse));
        path += " H" + num(kLeft + kPlotWidth);
        svg += "<path class=\"front\" d=\"" + path + "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n";
    }

    // Points, then labels placed greedily where they overlap no earlier label and no point.
    std::vector<Box> taken;
    for (const ModeResult& m : scene.modes)
        taken.push_back({px(m.median_ms) - 4, py(m.color_rmse) - 4, px(m.median_ms) + 4, py(m.color_rmse) + 4});
    for (const ModeResult& m : scene.modes) {
        const double x = px(m.median_ms), y = py(m.color_rmse);
        char tip[256];
        const std::string counts = m.compared ? "genuine " + std::to_string(m.genuine) + ", ambiguous " +
                                                    std::to_string(m.ambiguous)
                                              : std::string("not compared sample by sample");
        std::snprintf(tip, sizeof tip, "%s: %s ms, RMSE %.3g, coverage error %.3g, %s", m.mode.c_str(),
                      milliseconds(m.median_ms).c_str(), m.color_rmse, m.coverage_error, counts.c_str());
        svg += "<circle class=\"" + std::string(m.on_front ? "mode on-front" : "mode") + "\" data-mode=\"" +
               escape_xml(m.mode) + "\" cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"4\" fill=\"" +
               (m.on_front ? "#d62728" : "#888") + "\"><title>" + escape_xml(tip) + "</title></circle>\n";
    }
    for (const ModeResult& m : scene.modes) {
        const double x = px(m.median_ms), y = py(m.color_rmse);
        const double width = kCharWidth * double(m.mode.size());
        Box chosen{x + 6, y - 8, x + 6 + width, y + 4};
        bool right = true;
        double shift = 0;
        bool placed = false;
        for (int step = 0; step <= 40 && !placed; ++step) {  // up and down, ever further, up to 20 lines
            const double dy = (step % 2 ? 1 : -1) * kLineHeight * double((step + 1) / 2);
            for (bool on_right : {true, false}) {
                const Box box = on_right ? Box{x + 6, y - 8 + dy, x + 6 + width, y + 4 + dy}
                                         : Box{x - 6 - width, y - 8 + dy, x - 6, y + 4 + dy};
                if (box.x0 < kLeft + 2 || box.x1 > kPanelWidth || box.y0 < kTop - 10 || box.y1 > kTop + kPlotHeight + 4)
                    continue;
                bool free = true;
                for (const Box& other : taken) free = free && !box.overlaps(other);
                if (free) {
                    chosen = box;
                    right = on_right;
                    shift = dy;
                    placed = true;
                    break;
                }
            }
        }
        taken.push_back(chosen);
        if (shift != 0)  // a leader from the point to its displaced label
            svg += "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" +
                   num(right ? chosen.x0 - 1 : chosen.x1 + 1) + "\" y2=\"" + num(chosen.y1 - 4) +
                   "\" stroke=\"#bbb\" stroke-width=\"0.7\"/>\n";
        svg += "<text class=\"label\" x=\"" + num(right ? chosen.x0 : chosen.x1) + "\" y=\"" + num(chosen.y1 - 1) +
               "\" font-size=\"11\"" + (right ? "" : " text-anchor=\"end\"") + (m.on_front ? " fill=\"#a01010\"" : "") +
               ">" + escape_xml(m.mode) + "</text>\n";
    }

    // The legend and the front, listed.
    const double list_top = kTop + kPlotHeight + 58;
    svg += "<text x=\"" + num(kLeft) + "\" y=\"" + num(list_top) +
           "\" font-size=\"11\"><tspan fill=\"#d62728\">&#9679; on the Pareto front</tspan> (no other mode is both "
           "at least as fast and at least as accurate)   <tspan fill=\"#888\">&#9679; dominated</tspan></text>\n";
    std::string line = "Pareto front, fastest first: ";
    std::vector<std::string> lines;
    for (size_t i = 0; i < front.size(); ++i) {
        char item[128];
        std::snprintf(item, sizeof item, "%s (%s ms, %.3g)%s", front[i]->mode.c_str(),
                      milliseconds(front[i]->median_ms).c_str(), front[i]->color_rmse,
                      i + 1 < front.size() ? ", " : "");
        if (line.size() + std::char_traits<char>::length(item) > 115) {
            lines.push_back(line);
            line = "  ";
        }
        line += item;
    }
    lines.push_back(line);
    for (size_t i = 0; i < lines.size(); ++i)
        svg += "<text class=\"front-list\" x=\"" + num(kLeft) + "\" y=\"" +
               num(list_top + 16 + kLineHeight * double(i)) + "\" font-size=\"11\" xml:space=\"preserve\">" +
               escape_xml(lines[i]) + "</text>\n";
    return svg + "</g>\n";
}

}  // namespace

std::string pareto_svg(const std::vector<SceneTradeoff>& scenes, int reference_grid) {
    const double height = kPanelHeight * double(std::max<size_t>(scenes.size(), 1));
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      num(kPanelWidth) + "\" height=\"" + num(height) + "\" viewBox=\"0 0 " + num(kPanelWidth) + " " +
                      num(height) + "\" font-family=\"sans-serif\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
    for (size_t i = 0; i < scenes.size(); ++i) svg += panel(scenes[i], reference_grid, kPanelHeight * double(i));
    return svg + "</svg>\n";
}

}  // namespace raster::harness
