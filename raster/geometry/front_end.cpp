// The front end: culling, clipping and setup in parallel chunks kept in draw order, vertices projected once, and the
// transparent triangles' setups set aside.
#include "raster/geometry/front_end.h"

#include <algorithm>
#include <array>

#include "raster/core/parallel.h"
#include "raster/geometry/clip.h"
#include "raster/geometry/setup_table.h"

namespace raster {
namespace {

// Each vertex projected to the screen once, for the triangles no clip plane touches, and whether it is inside the
// clip volume, into `out`.
void project_vertices(const TransformedScene& geometry, const FrameParams& frame, ProjectedVertices& out) {
    const size_t count = geometry.clip.size();
    out.screen.resize(count);
    out.inside.resize(count);
    const SnapGrid grid = snap_grid(frame);
    constexpr size_t kBatch = 16384;
    parallel_for((count + kBatch - 1) / kBatch, frame.threads, [&](size_t batch) {
        for (size_t i = batch * kBatch; i < std::min(count, (batch + 1) * kBatch); ++i) {
            out.inside[i] = inside_clip_volume(geometry.clip[i], frame.clip);
            if (out.inside[i]) out.screen[i] = project_to_screen(geometry.clip[i], frame, grid);
        }
    });
}

// Appends the transparent setups of `setups` to `out` and keeps the rest in place, both in draw order.
void move_transparent_setups(const std::vector<uint8_t>& transparent, std::vector<TriangleSetup>& setups,
                             std::vector<TriangleSetup>& out) {
    size_t kept = 0;
    for (const TriangleSetup& t : setups) {
        if (transparent[t.triangle_id]) out.push_back(t);
        else setups[kept++] = t;
    }
    setups.resize(kept);
}

}  // namespace

std::vector<uint8_t> transparent_triangles(const Scene& scene) {
    if (!has_transparency(scene)) return {};
    std::vector<uint8_t> out;
    for (const SceneMesh& mesh : scene.meshes)
        for (uint32_t t = 0; t < mesh.data->triangles.size(); ++t) out.push_back(is_blended(material_of(mesh, t)));
    return out;
}

void split_transparent_setups(const std::vector<uint8_t>& transparent,
                              std::vector<std::vector<TriangleSetup>>& chunks, std::vector<TriangleSetup>& out) {
    out.clear();
    if (transparent.empty()) return;
    for (std::vector<TriangleSetup>& chunk : chunks) move_transparent_setups(transparent, chunk, out);
}

SetupCounts set_up_triangles_into(const TransformedScene& geometry, const FrameParams& frame, bool cull,
                                  const std::vector<uint8_t>& transparent, FrontEndSetups& out) {
    ProjectedVertices& projected = out.projected;
    project_vertices(geometry, frame, projected);
    // Clip and set up in chunks of triangles, each into its own list: the chunks in order keep the draw order.
    const size_t chunks = (geometry.triangles.size() + kSetupChunkTriangles - 1) / kSetupChunkTriangles;
    auto& chunk_setups = out.setup_chunks;
    chunk_setups.resize(chunks);  // each list keeps its storage from frame to frame
    std::vector<size_t> chunk_clipped(chunks, 0);
    parallel_for(chunks, frame.threads, [&](size_t chunk) {
        const size_t begin = chunk * kSetupChunkTriangles;
        const size_t end = std::min(geometry.triangles.size(), begin + kSetupChunkTriangles);
        auto& setups = chunk_setups[chunk];
        setups.clear();
        setups.reserve(end - begin);
        for (size_t tri = begin; tri < end; ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec4 &a = geometry.clip[v.v[0]], &b = geometry.clip[v.v[1]], &c = geometry.clip[v.v[2]];
            if (cull && !faces_front(a, b, c)) continue;
            const auto id = static_cast<uint32_t>(tri);
            if (projected.inside[v.v[0]] && projected.inside[v.v[1]] &&
                projected.inside[v.v[2]]) {  // what clip_triangle passes through untouched
                const std::array<const ScreenPoint*, 3> screen = {&projected.screen[v.v[0]], &projected.screen[v.v[1]],
                                                                  &projected.screen[v.v[2]]};
                setup_screen_triangle(screen, {&kCornerBarycentrics[0], &kCornerBarycentrics[1], &kCornerBarycentrics[2]},
                                      id, frame, setups);
                continue;
            }
            const ClippedPolygon polygon = clip_triangle(a, b, c, frame.clip);
            chunk_clipped[chunk] += polygon.clipped;
            setup_polygon(polygon, id, frame, setups);
        }
    });
    SetupCounts counts;
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
        counts.rasterized += chunk_setups[chunk].size();
        counts.clipped += chunk_clipped[chunk];
    }
    split_transparent_setups(transparent, chunk_setups, out.transparent_setups);
    return counts;
}

void concatenate_setups(const std::vector<std::vector<TriangleSetup>>& chunks, int threads,
                        std::vector<TriangleSetup>& out) {
    std::vector<size_t> start(chunks.size() + 1, 0);
    for (size_t chunk = 0; chunk < chunks.size(); ++chunk) start[chunk + 1] = start[chunk] + chunks[chunk].size();
    out.resize(start.back());  // keeps its storage from frame to frame
    parallel_for(chunks.size(), threads, [&](size_t chunk) {
        std::copy(chunks[chunk].begin(), chunks[chunk].end(), out.begin() + static_cast<ptrdiff_t>(start[chunk]));
    });
}

std::vector<TriangleSetup> set_up_triangles(const TransformedScene& geometry, const FrameParams& frame,
                                            bool cull_backfaces, SetupCounts* counts) {
    FrontEndSetups front_end;
    const SetupCounts made = set_up_triangles_into(geometry, frame, cull_backfaces, {}, front_end);
    if (counts) *counts = made;
    std::vector<TriangleSetup> setups;
    concatenate_setups(front_end.setup_chunks, frame.threads, setups);
    return setups;
}

}  // namespace raster
