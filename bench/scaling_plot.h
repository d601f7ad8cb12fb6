// The scaling benchmark's analysis: a least-squares fit of frame time to triangles and covered samples, and the
// SVG of both sweeps (measured points and the fit's prediction) on log-log axes.
#pragma once

#include <string>
#include <vector>

namespace raster_bench {

// One measured frame: what was drawn and its median time.
struct ScalingPoint {
    std::string sweep;  // "triangles" or "resolution"
    double triangles = 0;
    double pixels = 0;
    double covered_samples = 0;
    double ms = 0;
};

// time = fixed + per_triangle * triangles + per_sample * covered samples, fitted to every point (least squares on
// relative error, so small frames count as much as large ones).
struct ScalingFit {
    double fixed_ms = 0, ms_per_triangle = 0, ms_per_sample = 0;
    double predict(const ScalingPoint& p) const {
        return fixed_ms + ms_per_triangle * p.triangles + ms_per_sample * p.covered_samples;
    }
};
ScalingFit fit_scaling(const std::vector<ScalingPoint>& points);

// Two panels, time against triangles and time against pixels, each point with the fit's prediction beside it.
std::string scaling_svg(const std::vector<ScalingPoint>& points, const ScalingFit& fit, const std::string& title);

}  // namespace raster_bench
