// Speed against accuracy: renders a scene in each trade-off mode and measures its frame time (median of several
// runs) and its error against the oracle (genuine and ambiguous sample counts, colour RMSE against a high-sample
// oracle image, coverage error against the exact area), marks the Pareto front of time against colour RMSE, and
// writes the results as JSON and CSV.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/tradeoff/tradeoff_modes.h"
#include "oracle/reference/ray_caster.h"
#include "raster/image/image.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster::harness {

struct TradeoffOptions {
    int runs = 5;            // timed frames per mode (after an untimed warm-up frame); the median is reported
    int reference_grid = 8;  // the reference oracle image has reference_grid^2 samples per pixel on a regular grid
    oracle::OracleMode oracle_mode = oracle::OracleMode::robust;
    int threads = 0;  // 0 = all cores, for raster, the oracle and the comparator
};

// One mode on one scene.
struct ModeResult {
    std::string mode;
    std::string description;
    RenderSettings settings;       // the scene's settings with the mode applied
    std::vector<double> times_ms;  // each timed frame
    double median_ms = 0;
    uint64_t samples = 0;  // width * height * samples per pixel (the internal frame's at a divisor above 1)
    uint64_t genuine = 0, ambiguous = 0;  // compare_scene's totals for the scene in this mode (genuine: judged or not)
    // False for a mode at a resolution divisor above 1, which compare_scene refuses: genuine and ambiguous are not
    // measured (JSON null, CSV empty); its RMSE and coverage error are.
    bool compared = true;
    double color_rmse = 0;                // 0-255, RGB, every pixel, against the reference oracle image
    double coverage_error = 0;            // see coverage_error()
    bool timed_image_matches = true;      // the timed frame's image is the compared one, byte for byte
    bool on_front = false;                // no other mode of the scene is both at least as fast and as accurate
};

struct SceneTradeoff {
    std::string name;   // the scene file's stem
    std::string scene;  // the scene file
    int width = 0, height = 0;
    size_t triangles = 0;
    double exact_area = 0;    // px^2, the sum of every triangle's exact visible area (the coverage error's divisor)
    double reference_ms = 0;  // the reference oracle image
    std::vector<ModeResult> modes;
};

// The median (the mean of the two middle values for an even count); 0 for none.
double median(std::vector<double> values);

// Per scene triangle, the exact screen area in px^2 of its part inside the view volume (the oracle's exact
// clipping against near, far and the four side planes, so inside the viewport); 0 for a culled triangle or one
// outside the volume.
std::vector<double> exact_triangle_areas(const Scene& scene);

// Per scene triangle, how many samples its snapped setups cover under the exact integer `covers` test, over their
// bounding boxes, before any depth test: what the mode's setup, snapping and sample positions make of its area.
// Deterministic for any thread count.
std::vector<uint64_t> covered_sample_counts(const Scene& scene, const TransformedScene& geometry, int threads);

// The coverage error: sum_t |n_t / spp - A_t| / sum_t A_t over scene triangles t, with n_t from
// covered_sample_counts and A_t from exact_triangle_areas. 0 when nothing is visible and nothing is covered.
double coverage_error(const std::vector<uint64_t>& covered, int samples_per_pixel, const std::vector<double>& areas);

// Root mean square of the RGB byte differences over every pixel (0-255). Both images must have the same size and
// at least 3 channels (only RGB is compared), else std::invalid_argument.
double color_rmse(const Image& a, const Image& b);

// Empty when the reference image of a scene with `settings` fits the frame-memory cap (kMaxFrameBytes: the oracle's
// visibility buffer, 20 bytes per sample, and the image), else what is wrong.
std::string reference_problem(const RenderSettings& settings, int grid);

// The oracle's own image of `scene` at grid^2 samples per pixel on a regular grid (SSAA, sample positions at 16
// sub-pixel bits): the "ground truth" picture. Throws OracleError if Embree fails.
Image reference_image(const Scene& scene, int grid, const TradeoffOptions& options);

// Whether each (time, error) point is on the Pareto front: no other point is <= in both and < in one. Equal points
// are all on it (none dominates another). A NaN coordinate is never on it and dominates nothing.
std::vector<bool> pareto_front(const std::vector<std::pair<double, double>>& points);

// Measures every mode on `scene` (which must be valid): the reference image, then each mode's accuracy, then the
// timing in interleaved rounds (a warm-up round, then `runs` rounds of one frame per mode). `progress` is called
// before each of measure_steps() steps with a label. Throws OracleError if Embree fails.
size_t measure_steps(size_t modes, const TradeoffOptions& options);
SceneTradeoff measure_scene(const Scene& scene, const std::vector<const TradeoffMode*>& modes,
                            const TradeoffOptions& options,
                            const std::function<void(const std::string&)>& progress = {});

// {runs, reference: {grid, samples_per_pixel, oracle_mode}, scenes: [{name, scene, width, height, triangles,
//  exact_area, reference_ms, front: [mode names by time], modes: [{mode, description, settings, median_ms, times_ms,
//  samples, genuine, ambiguous, color_rmse, coverage_error, timed_image_matches, on_front}]}]}
nlohmann::json tradeoff_json(const std::vector<SceneTradeoff>& scenes, const TradeoffOptions& options);

// One row per scene and mode: scene, mode, the settings, median_ms, samples, genuine, ambiguous, color_rmse,
// coverage_error, on_front (0 or 1). Fields with a comma, quote or newline are quoted.
std::string tradeoff_csv(const std::vector<SceneTradeoff>& scenes);

}  // namespace raster::harness
