// The rasterizer pipeline: runs each stage in order on plain structs and records what it did.
#include "raster/render.h"

#include "raster/tiled_render.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "raster/clip.h"
#include "raster/errors.h"
#include "raster/parallel.h"
#include "raster/rasterize.h"
#include "raster/resolve.h"
#include "raster/sample_pattern.h"
#include "raster/setup.h"
#include "raster/shade.h"
#include "raster/vertex_stage.h"

namespace raster {
namespace {

using Clock = std::chrono::steady_clock;


constexpr size_t kSetupChunk = 4096;

}  // namespace

uint64_t frame_bytes(const RenderSettings& settings) {
    // Per sample: visibility buffer (4 id + 12 barycentrics + 4 depth) + z-buffer 4 + winner 4.
    // Per pixel: up to 4 bytes of output image.
    const uint64_t pixels = uint64_t(std::max(settings.width, 0)) * uint64_t(std::max(settings.height, 0));
    return pixels * uint64_t(std::max(settings.samples, 0)) * 28u + pixels * 4u;
}

void set_up_triangles_into(const Scene& scene, const TransformedScene& geometry, int threads,
                           const PipelineStages& stages, RenderStats& stats, RenderWorkspace& workspace) {
    // Clip and set up in chunks of triangles; concatenating the chunks in order keeps the draw order.
    const RenderSettings& settings = scene.settings;
    const ClipVolume volume = clip_volume_for(scene.camera, settings);
    const SetupParams setup_params = setup_params_for(settings);
    const size_t chunks = (geometry.triangles.size() + kSetupChunk - 1) / kSetupChunk;
    auto& chunk_setups = workspace.chunk_setups;
    chunk_setups.resize(chunks);
    std::vector<size_t> chunk_clipped(chunks, 0);
    parallel_for(chunks, threads, [&](size_t chunk) {
        const size_t begin = chunk * kSetupChunk;
        const size_t end = std::min(geometry.triangles.size(), begin + kSetupChunk);
        auto& out = chunk_setups[chunk];
        out.clear();
        out.reserve(end - begin);
        for (size_t tri = begin; tri < end; ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            if (settings.cull_backfaces &&
                !stages.faces_front(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]]))
                continue;
            const ClippedPolygon polygon =
                stages.clip(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]], volume);
            chunk_clipped[chunk] += polygon.clipped;
            stages.setup(polygon, static_cast<uint32_t>(tri), setup_params, out);
        }
    });
    std::vector<TriangleSetup>& setups = workspace.setups;
    setups.clear();
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
        setups.insert(setups.end(), chunk_setups[chunk].begin(), chunk_setups[chunk].end());
        stats.clipped += chunk_clipped[chunk];
    }
    stats.rasterized = setups.size();
}

std::vector<TriangleSetup> set_up_triangles(const Scene& scene, const TransformedScene& geometry, int threads,
                                            const PipelineStages& stages, RenderStats& stats) {
    RenderWorkspace workspace;
    set_up_triangles_into(scene, geometry, threads, stages, stats, workspace);
    return std::move(workspace.setups);
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

TransformedScene run_vertex_stage_timed(const Scene& scene, const PipelineStages& stages, RenderStats& stats) {
    const auto start = Clock::now();
    TransformedScene geometry = stages.vertex(scene, vertex_stage_needs(scene.settings.shading));
    stats.triangles = geometry.triangles.size();
    stats.ms_vertex = milliseconds_since(start);
    return geometry;
}

ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options) {
    ResolveParams params;
    params.msaa = scene.settings.msaa;
    params.background = scene.settings.background;
    params.alpha = options.alpha;
    params.threads = options.threads;
    return params;
}

RenderResult render(const Scene& scene, const RenderOptions& options, const PipelineStages& stages) {
    RenderResult result;
    render_into(scene, options, result, stages);
    return result;
}

void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result, const PipelineStages& stages) {
    if (options.path == RasterPath::tiled && stages.rasterize == PipelineStages{}.rasterize) {
        render_tiled_into(scene, options, result, stages);
        return;
    }
    const auto start = Clock::now();
    const RenderSettings& settings = scene.settings;
    result.stats = RenderStats{};
    RenderStats& stats = result.stats;

    const TransformedScene geometry = run_vertex_stage_timed(scene, stages, stats);

    auto stage_start = Clock::now();
    set_up_triangles_into(scene, geometry, options.threads, stages, stats, result.workspace);
    const std::vector<TriangleSetup>& setups = result.workspace.setups;
    stats.ms_setup = milliseconds_since(stage_start);

    stage_start = Clock::now();
    RasterParams raster_params;
    raster_params.width = settings.width;
    raster_params.height = settings.height;
    raster_params.snap_bits = settings.snap_bits;
    raster_params.sample_offsets = stages.sample_offsets(settings.samples, settings.pattern);
    raster_params.threads = options.threads;
    stages.rasterize(setups, raster_params, result.visibility);
    stats.samples = result.visibility.size();
    stats.ms_raster = milliseconds_since(stage_start);

    stage_start = Clock::now();
    const Shader shader(scene, geometry, stages.lighting);
    resolve_image(result.visibility, shader, resolve_params_for(scene, options), result.image);
    stats.ms_shade = milliseconds_since(stage_start);

    for (uint32_t id : result.visibility.triangle) stats.covered_samples += id != kNoTriangle;
    stats.ms_total = milliseconds_since(start);
}

namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

std::string settings_problem(const RenderSettings& s) {
    if (s.width < 1 || s.height < 1 || s.width > kMaxImageDimension || s.height > kMaxImageDimension)
        return "image size " + std::to_string(s.width) + "x" + std::to_string(s.height) + " is outside 1.." +
               std::to_string(kMaxImageDimension) + " per side";
    if (std::string error = sample_count_error(s.samples, s.pattern); !error.empty()) return error;
    if (frame_bytes(s) > kMaxFrameBytes)
        return "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " image with " +
               std::to_string(s.samples) + " samples needs " + std::to_string(frame_bytes(s) >> 20) +
               " MiB of frame buffers, over the " + std::to_string(kMaxFrameBytes >> 20) + " MiB cap";
    if (s.snap_bits < kMinSnapBits || s.snap_bits > kMaxSnapBits)
        return "snap bits must be " + std::to_string(kMinSnapBits) + ".." + std::to_string(kMaxSnapBits);
    if (!finite3(s.background) || !finite3(s.ambient_light)) return "background and ambient light must be finite";
    return "";
}

std::string camera_problem(const Camera& c) {
    if (!finite3(c.eye) || !finite3(c.target) || !finite3(c.up)) return "camera eye, target and up must be finite";
    if (!(c.near > 0.0f) || !std::isfinite(c.near)) return "camera near must be > 0, got " + std::to_string(c.near);
    // Setup stores 1 / w in float, and w goes down to near: a subnormal near would make it infinite.
    if (c.near < std::numeric_limits<float>::min()) {
        char near[32];
        std::snprintf(near, sizeof near, "%g", double(c.near));
        return std::string("camera near must be > 0 and a normal float (at least 1.17549e-38), got ") + near;
    }
    if (!(c.far > c.near) || !std::isfinite(c.far))
        return "camera far (" + std::to_string(c.far) + ") must be finite and greater than near (" +
               std::to_string(c.near) + ")";
    if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
        return "camera field of view must be in (0, 180) degrees, got " + std::to_string(c.fov_y_degrees);
    const glm::vec3 view = c.target - c.eye;
    if (!(glm::length(view) > 0.0f)) return "camera eye and target are the same point";
    const glm::vec3 side = glm::cross(glm::normalize(view), c.up);
    if (!(glm::length(side) > 1e-6f * glm::length(c.up)) || !(glm::length(c.up) > 0.0f))
        return "camera up is parallel to the view direction (or zero)";
    return "";
}

void validate_scene(const Scene& scene) {
    auto fail = [&](const std::string& message) { throw InputError(scene.path, 0, 0, message); };
    if (std::string problem = settings_problem(scene.settings); !problem.empty()) fail(problem);
    if (std::string problem = camera_problem(scene.camera); !problem.empty()) fail(problem);
    // A field of view so narrow that 1 / tan(fov / 2) overflows float gives an infinite projection: nothing could
    // be drawn, and camera rays (the oracle's) would be NaN.
    const glm::mat4 projection = projection_matrix(scene.camera, scene.settings.width, scene.settings.height);
    for (int column = 0; column < 4; ++column)
        if (!finite3(glm::vec3(projection[column])) || !std::isfinite(projection[column].w)) {
            char fov[32];
            std::snprintf(fov, sizeof fov, "%g", double(scene.camera.fov_y_degrees));
            fail(std::string("camera field of view ") + fov + " degrees is too narrow: its projection overflows float");
        }
    if (triangle_count(scene) >= kNoTriangle) fail("too many triangles");

    for (const Light& light : scene.lights)
        if (!finite3(light.position) || !finite3(light.color) || !std::isfinite(light.intensity))
            fail("light position, colour and intensity must be finite");
    for (const SceneMesh& mesh : scene.meshes) {
        const MeshData& m = mesh.data;
        for (const glm::vec3& p : m.positions)
            if (!finite3(p)) fail(mesh.source + ": vertex coordinates must be finite");
        for (size_t t = 0; t < m.triangles.size(); ++t)
            for (uint32_t v : m.triangles[t].v)
                if (v >= m.positions.size())
                    fail(mesh.source + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                         " but there are only " + std::to_string(m.positions.size()));
        if (!m.normals.empty() && m.normals.size() != m.positions.size()) fail(mesh.source + ": normals count mismatch");
        if (!m.colors.empty() && m.colors.size() != m.positions.size()) fail(mesh.source + ": colour count mismatch");
        if (!m.face_colors.empty() && m.face_colors.size() != m.triangles.size())
            fail(mesh.source + ": face colour count mismatch");
        for (int r = 0; r < 4; ++r)
            for (int col = 0; col < 4; ++col)
                if (!std::isfinite(mesh.model[col][r])) fail(mesh.source + ": the model transform is not finite");
        if (!std::isfinite(mesh.material.exponent) || !finite3(mesh.material.ambient) ||
            !finite3(mesh.material.diffuse) || !finite3(mesh.material.specular) || !finite3(mesh.material.color))
            fail(mesh.source + ": material values must be finite");
    }
}

}  // namespace raster
