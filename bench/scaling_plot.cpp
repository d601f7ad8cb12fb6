// The scaling fit (3x3 normal equations, weighted by 1/time^2) and a small hand-written SVG writer for its plot.
#include "bench/scaling_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster_bench {

ScalingFit fit_scaling(const std::vector<ScalingPoint>& points) {
    glm::dmat3 normal(0.0);
    glm::dvec3 right(0.0);
    for (const ScalingPoint& p : points) {
        const double weight = 1.0 / (p.ms * p.ms);  // relative residuals
        const glm::dvec3 row(1.0, p.triangles, p.covered_samples);
        normal += weight * glm::outerProduct(row, row);
        right += weight * p.ms * row;
    }
    const glm::dvec3 solution = glm::inverse(normal) * right;
    return {solution.x, solution.y, solution.z};
}

namespace {

struct Axis {
    double lo, hi;      // data range (log10)
    double from, to;    // pixel range
    double at(double value) const { return from + (std::log10(value) - lo) / (hi - lo) * (to - from); }
};

Axis log_axis(double lo, double hi, double from, double to) {
    return {std::floor(std::log10(lo)), std::ceil(std::log10(hi)), from, to};
}

std::string text(double x, double y, const std::string& s, const char* anchor = "middle", int size = 12) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "<text x='%.1f' y='%.1f' font-size='%d' text-anchor='%s'>%s</text>\n", x, y,
                  size, anchor, s.c_str());
    return buffer;
}

std::string panel(const std::vector<ScalingPoint>& points, const ScalingFit& fit, const std::string& sweep,
                  double (*x_of)(const ScalingPoint&), const std::string& x_label, double left) {
    std::vector<ScalingPoint> mine;
    for (const ScalingPoint& p : points)
        if (p.sweep == sweep) mine.push_back(p);
    if (mine.empty()) return "";
    std::sort(mine.begin(), mine.end(), [&](const ScalingPoint& a, const ScalingPoint& b) { return x_of(a) < x_of(b); });
    double x_lo = 1e300, x_hi = 0, y_lo = 1e300, y_hi = 0;
    for (const ScalingPoint& p : mine) {
        x_lo = std::min(x_lo, x_of(p)), x_hi = std::max(x_hi, x_of(p));
        y_lo = std::min({y_lo, p.ms, fit.predict(p)}), y_hi = std::max({y_hi, p.ms, fit.predict(p)});
    }
    const Axis x = log_axis(x_lo, x_hi, left + 60, left + 380), y = log_axis(y_lo, y_hi, 400, 60);
    std::string svg;
    for (double e = x.lo; e <= x.hi; ++e) {
        const double px = x.at(std::pow(10.0, e));
        svg += "<line x1='" + std::to_string(px) + "' y1='60' x2='" + std::to_string(px) +
               "' y2='400' stroke='#ddd'/>\n";
        svg += text(px, 418, "1e" + std::to_string(static_cast<int>(e)));
    }
    for (double e = y.lo; e <= y.hi; ++e) {
        const double py = y.at(std::pow(10.0, e));
        svg += "<line x1='" + std::to_string(x.from) + "' y1='" + std::to_string(py) + "' x2='" +
               std::to_string(x.to) + "' y2='" + std::to_string(py) + "' stroke='#ddd'/>\n";
        char label[32];
        std::snprintf(label, sizeof label, "%g ms", std::pow(10.0, e));
        svg += text(x.from - 6, py + 4, label, "end");
    }
    svg += text((x.from + x.to) / 2, 440, x_label);
    std::string measured, predicted;
    for (const ScalingPoint& p : mine) {
        char point[200];
        std::snprintf(point, sizeof point, "%.1f,%.1f ", x.at(x_of(p)), y.at(p.ms));
        measured += point;
        std::snprintf(point, sizeof point, "%.1f,%.1f ", x.at(x_of(p)), y.at(fit.predict(p)));
        predicted += point;
        std::snprintf(point, sizeof point, "<circle cx='%.1f' cy='%.1f' r='4' fill='#c33'/>\n", x.at(x_of(p)),
                      y.at(p.ms));
        svg += point;
    }
    svg += "<polyline points='" + measured + "' fill='none' stroke='#c33' stroke-width='2'/>\n";
    svg += "<polyline points='" + predicted + "' fill='none' stroke='#36c' stroke-width='2' stroke-dasharray='6 4'/>\n";
    return svg;
}

}  // namespace

std::string scaling_svg(const std::vector<ScalingPoint>& points, const ScalingFit& fit, const std::string& title) {
    std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='900' height='500' font-family='sans-serif'>\n"
                      "<rect width='900' height='500' fill='white'/>\n";
    svg += text(450, 24, title, "middle", 15);
    char legend[300];
    std::snprintf(legend, sizeof legend,
                  "red: measured median; blue dashed: fit %.3g ms + %.3g us/triangle + %.3g ns/covered sample",
                  fit.fixed_ms, fit.ms_per_triangle * 1e3, fit.ms_per_sample * 1e6);
    svg += text(450, 44, legend, "middle", 12);
    svg += panel(points, fit, "triangles", [](const ScalingPoint& p) { return p.triangles; },
                 "triangles (sphere, same screen area, 800x800)", 0);
    svg += panel(points, fit, "resolution", [](const ScalingPoint& p) { return p.pixels; },
                 "pixels (81,920-triangle sphere, 256^2 to 4096^2)", 450);
    return svg + "</svg>\n";
}

}  // namespace raster_bench
